#ifndef pg_mesh_geometry_parameters_h
#define pg_mesh_geometry_parameters_h

#include <pg/base/global.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

// The parameters of the mesh (subsection "Geometry"), used by
// create_mesh() and mark_meshfree_cells() (pg/mesh/mesh_generator.h).

namespace pg
{
  namespace Parameters
  {
    /** Subsection "Geometry". */
    struct Geometry
    {
      /** hyper rectangle | cook membrane | plate with hole | file */
      std::string mesh;
      /**
       * 'Cells': hypercubes (the quadrilaterals or hexahedra as generated or
       * read) | simplices (each split into 8 triangles or 24 tetrahedra
       * after refinement and distortion, deal.II's
       * GridGenerator::convert_hypercube_to_simplex_mesh()).
       */
      std::string               cells = "hypercubes";
      std::vector<double>       lower_corner;
      std::vector<double>       upper_corner;
      std::vector<unsigned int> subdivisions;
      /** Plate with hole: edge length L and hole radius R (length units). */
      double plate_size;
      double hole_radius;
      /** 'Thickness': z extent of the 3-D Cook membrane (length). */
      double      thickness;
      std::string file_name;
      /** Mesh = file: merge | reject | keep coincident vertices. */
      std::string  coincident_vertices;
      unsigned int global_refinement;
      /**
       * 'Memory check': refuse a mesh whose estimated memory exceeds the
       * machine's (pg/dofs/memory_estimate.h).
       */
      bool memory_check = true;
      /** Interior vertices move by up to this fraction of the local spacing. */
      double       distortion;
      unsigned int random_seed;
      /** all | none | material ids a,b | box x0,y0 : x1,y1 | ball cx,cy : r */
      std::string meshfree_region;
      /** Hyper rectangle: 'box x0,y0 : x1,y1' of removed cells, or empty. */
      std::string hole;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace pg

#endif
