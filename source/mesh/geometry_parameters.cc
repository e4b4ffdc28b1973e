#include <pg/base/exceptions.h>
#include <pg/base/parameter_utilities.h>
#include <pg/mesh/geometry_parameters.h>

#include <string>

namespace pg
{
  namespace Parameters
  {
    void
    Geometry::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      {
        prm.declare_entry(
          "Mesh",
          "hyper rectangle",
          Patterns::Selection("hyper rectangle|cook membrane|plate with hole|"
                              "file"),
          "The mesh. 'hyper rectangle': the box between 'Lower corner' and "
          "'Upper corner' with colorized boundary ids 0..2*dim-1 (0: x=min, "
          "1: x=max, 2: y=min, 3: y=max, 4: z=min, 5: z=max). 'cook "
          "membrane': the 48 x 44/16 tapered panel (2-D), ids 0 clamped left "
          "edge, 1 loaded right edge, 2 bottom, 3 top. 'plate with hole': the "
          "quarter [0,L]^2 of a square plate minus the disk of radius R at "
          "the origin (2-D), ids 0 hole, 1 x=0, 2 y=0, 3 x=L, 4 y=L. 'file': "
          "read 'File name'.");
        prm.declare_entry(
          "Cells",
          "hypercubes",
          Patterns::Selection("hypercubes|simplices"),
          "The kind of cell of a generated mesh (and of a mesh file of "
          "quadrilaterals or hexahedra). 'hypercubes': the quadrilaterals "
          "(hexahedra) as generated or read. 'simplices': after 'Global "
          "refinement', 'Distortion' and 'Hole', each quadrilateral is split "
          "into 8 triangles (a vertex at each edge midpoint and at the "
          "centre) and each hexahedron into 24 tetrahedra (a vertex at each "
          "face centre), with deal.II's "
          "GridGenerator::convert_hypercube_to_simplex_mesh(); the boundary "
          "and material ids are kept, the new vertices on the hole of 'plate "
          "with hole' lie on its circle, and the cells are then straight P1 "
          "triangles (tetrahedra): FE cells are P1, the particles are the "
          "vertices with the volumes lumped from the simplices (as for a "
          "Gmsh mesh of simplices, which this entry leaves unchanged). The "
          "split of a regular mesh is the mirror image of itself across the "
          "mid-planes of every cell, so a half or quarter model of a "
          "symmetric box is the exact mirror image of the full body.");
        prm.declare_entry("Lower corner",
                          "0, 0",
                          Patterns::List(Patterns::Double()),
                          "Hyper rectangle: lower corner, dim coordinates. "
                          "Units: length.");
        prm.declare_entry("Upper corner",
                          "1, 1",
                          Patterns::List(Patterns::Double()),
                          "Hyper rectangle: upper corner, dim coordinates, "
                          "each greater than that of 'Lower corner'. Units: "
                          "length.");
        prm.declare_entry("Subdivisions",
                          "1, 1",
                          Patterns::List(Patterns::Integer(1)),
                          "Cells per direction before global refinement "
                          "(hyper rectangle and cook membrane); one value is "
                          "used for every direction.");
        prm.declare_entry(
          "Hole",
          "",
          Patterns::Anything(),
          "Hyper rectangle only: 'box x0,y0 : x1,y1' (dim coordinates per "
          "corner) removes the cells of the coarse mesh ('Subdivisions') "
          "whose centres lie in the box, before refinement; the faces of the "
          "hole get boundary id 2*dim (4 in 2-D, 6 in 3-D). Empty: no hole. "
          "E.g. the unit square or cube with a centred square hole of side "
          "0.4: 'box 0.3,0.3 : 0.7,0.7' with 10 subdivisions.");
        prm.declare_entry("Plate size",
                          "4",
                          Patterns::Double(0.),
                          "Plate with hole: edge length L of the quarter "
                          "plate. Units: length.");
        prm.declare_entry("Thickness",
                          "10",
                          Patterns::Double(0.),
                          "Cook membrane in 3-D: the extent in z. Units: "
                          "length.");
        prm.declare_entry("Hole radius",
                          "1",
                          Patterns::Double(0.),
                          "Plate with hole: hole radius R < L. Units: "
                          "length.");
        prm.declare_entry("File name",
                          "",
                          Patterns::Anything(),
                          "Mesh file for 'Mesh = file': Gmsh (.msh), Abaqus "
                          "(.inp) or UCD (.ucd), read with deal.II's GridIn, "
                          "or Exodus II (.g, .e, .exo: Cubit, Peridigm), read "
                          "with netCDF: element blocks become material ids, "
                          "side sets boundary ids, node sets are named "
                          "vertex sets for 'Dirichlet node sets'. "
                          "Relative paths start in the working directory. "
                          "Quadrilaterals (hexahedra; FE cells are Q1), or "
                          "linear triangles (tetrahedra; FE cells are P1, "
                          "the mixed codes' FE cells are refused: P1-P0 "
                          "locks); one kind of cell per mesh.");
        prm.declare_entry(
          "Coincident vertices",
          "merge",
          Patterns::Selection("merge|reject|keep"),
          "Mesh = file: what to do with distinct vertices at the same "
          "position (closer than 1e-10 x the bounding-box diagonal in every "
          "coordinate), which some mesh generators leave where blocks meet "
          "(e.g. Cubit/Exodus meshes converted to Gmsh): they disconnect "
          "the finite elements there and make coincident particles. "
          "'merge': merge them into one vertex on reading and say how many "
          "were merged. 'reject': stop with a message naming the first "
          "positions. 'keep': read the mesh as it is and only say so (the "
          "blocks stay disconnected: FEM then has a singular system and "
          "PG coincident particles, whose families give NaN; for tests "
          "of those messages).");
        prm.declare_entry("Global refinement",
                          "0",
                          Patterns::Integer(0, 12),
                          "Number of uniform refinements of the mesh.");
        prm.declare_entry(
          "Memory check",
          "true",
          Patterns::Bool(),
          "Before the mesh is built, estimate the memory of the run from the "
          "mesh size ('Subdivisions' and 'Global refinement', or the cells "
          "of the mesh file), the DoFs and the formulation (the measured "
          "bytes per DoF of doc/memory.md, scaled with the matrix nonzeros "
          "per row that the horizon gives), and stop with a message if the "
          "estimate exceeds the machine's memory (MemTotal of /proc/meminfo). "
          "'false' skips the check, for those who know that the run fits.");
        prm.declare_entry("Distortion",
                          "0",
                          Patterns::Double(0., 0.45),
                          "Every interior vertex is moved randomly by up to "
                          "this fraction of its shortest adjacent edge "
                          "(after refinement); vertices of cells that the "
                          "shifts make non-convex are drawn again. 0 keeps "
                          "the mesh regular.");
        prm.declare_entry("Random seed",
                          "0",
                          Patterns::Integer(0),
                          "Seed of the random distortion; the same seed "
                          "gives the same mesh.");
        prm.declare_entry(
          "Meshfree region",
          "all",
          Patterns::Anything(),
          "Which cells are meshfree (their vertices become particles); the "
          "others are Q1 finite elements. 'all', 'none', 'material ids 1,2', "
          "'box x0,y0 : x1,y1' or 'ball cx,cy : r'. A cell is meshfree if its "
          "centre lies inside the box or ball. Ignored for 'Formulation = "
          "FEM'.");
      }
      prm.leave_subsection();
    }



    void
    Geometry::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      {
        mesh  = prm.get("Mesh");
        cells = prm.get("Cells");
        lower_corner =
          parse_doubles(prm.get("Lower corner"), "Geometry/Lower corner");
        upper_corner =
          parse_doubles(prm.get("Upper corner"), "Geometry/Upper corner");
        subdivisions.clear();
        for (const double s :
             parse_doubles(prm.get("Subdivisions"), "Geometry/Subdivisions"))
          subdivisions.push_back(static_cast<unsigned int>(s));
        plate_size          = prm.get_double("Plate size");
        hole_radius         = prm.get_double("Hole radius");
        thickness           = prm.get_double("Thickness");
        file_name           = prm.get("File name");
        coincident_vertices = prm.get("Coincident vertices");
        global_refinement   = prm.get_integer("Global refinement");
        memory_check        = prm.get_bool("Memory check");
        distortion          = prm.get_double("Distortion");
        random_seed         = prm.get_integer("Random seed");
        meshfree_region     = prm.get("Meshfree region");
        hole                = prm.get("Hole");
      }
      prm.leave_subsection();

      AssertThrow(mesh != "plate with hole" || hole_radius < plate_size,
                  ExcBadParameter("Geometry/Hole radius",
                                  std::to_string(hole_radius),
                                  "it must be smaller than 'Plate size' "
                                  "in subsection 'Geometry'."));
      AssertThrow(mesh != "cook membrane" || thickness > 0.,
                  ExcBadParameter("Geometry/Thickness",
                                  std::to_string(thickness),
                                  "the 3-D Cook membrane needs a positive "
                                  "thickness."));
      AssertThrow(mesh != "file" || !file_name.empty(),
                  ExcBadParameter("Geometry/File name",
                                  file_name,
                                  "'Mesh = file' needs the name of a mesh "
                                  "file."));
    }
  } // namespace Parameters
} // namespace pg
