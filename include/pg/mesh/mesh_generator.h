#ifndef pg_mesh_mesh_generator_h
#define pg_mesh_mesh_generator_h

#include <pg/base/global.h>
#include <pg/mesh/geometry_parameters.h>

#include <deal.II/grid/tria.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace pg
{
  namespace Mesh
  {
    /**
     * The size of the mesh that create_mesh() will build, known before it
     * is built (counts as doubles: a typo can ask for 10^10 cells).
     */
    struct MeshSize
    {
      /** Active cells after 'Global refinement'. */
      double n_cells = 0;
      /** Vertices after 'Global refinement' (= particles of PG-everywhere). */
      double n_vertices = 0;
      /** Mean cell size after refinement, (measure / cells)^(1/dim). */
      double spacing = 0;
      /** Cells before refinement: of 'Subdivisions', or of the file. */
      double n_coarse_cells = 0;
      /**
       * True for a mesh file of triangles or tetrahedra. Their counts
       * differ from those of hypercubes: a tetrahedral mesh has about 5 to
       * 6 cells per vertex (a hexahedral one 1), and a P1 node couples to
       * its edge neighbours only (about 14 in 3-D, 26 for Q1).
       */
      bool simplex = false;
      /**
       * Simplex meshes: the mean number of vertices joined to a vertex by a
       * cell edge (2 x edges / vertices); a P1 row has this plus one node.
       * 0 for hypercube meshes (a Q1 row has 3^dim nodes).
       */
      double edge_neighbours = 0;
    };

    /**
     * The size of a generated mesh ('hyper rectangle', 'cook membrane',
     * 'plate with hole') from 'Subdivisions' and 'Global refinement',
     * without building it: exact cell and vertex counts ('Hole' is not
     * subtracted). Not for 'Mesh = file'.
     */
    template <int dim>
    MeshSize
    predict_mesh_size(const Parameters::Geometry &parameters);

    /**
     * The size after 'Global refinement' of the coarse mesh
     * @p coarse read from a file: cells x 2^(dim r), and about as many
     * vertices plus those of the refined surface (quadrilaterals,
     * hexahedra), or for triangles and tetrahedra the vertices plus the
     * edges x (2^(dim r) - 1) / (2^dim - 1) (a refinement adds one vertex
     * per edge, about 3 (2-D) and 6 to 7 (3-D) per vertex, where a
     * hypercube mesh gains one per new cell; exact for r = 1). For simplex
     * meshes also the edge neighbours of MeshSize (of the coarse mesh:
     * refinement keeps the edges per vertex about the same) and the
     * spacing from the vertices, (measure / n_vertices)^(1/dim), the
     * spacing of a cubic lattice of the same density.
     */
    template <int dim>
    MeshSize
    predict_mesh_size(const Parameters::Geometry &parameters,
                      const Triangulation<dim>   &coarse);

    /**
     * Fill the empty @p triangulation from subsection 'Geometry': the base
     * mesh with its boundary ids (and manifolds for curved boundaries), then
     * 'Global refinement', then 'Distortion' (reproducible by 'Random seed').
     * Throws with a message that names the entry on bad input (unreadable
     * file, unsupported dimension, ...). What was done to a mesh file
     * (coincident vertices merged) is appended to @p notes, one line each,
     * for the banner.
     *
     * If given, @p check_size is called with the predicted size of the
     * final mesh before anything is allocated for a generated mesh, and
     * after reading, before refining, a mesh file; it may throw (the memory
     * check of pg/dofs/memory_estimate.h).
     *
     * The node sets of an Exodus II mesh file go to @p node_sets if given:
     * name -> vertex indices of @p triangulation (refinement keeps the
     * indices of the coarse vertices).
     */
    template <int dim>
    void
    create_mesh(
      const Parameters::Geometry                       &parameters,
      Triangulation<dim>                               &triangulation,
      std::string                                      *notes      = nullptr,
      const std::function<void(const MeshSize &)>      &check_size = {},
      std::map<std::string, std::vector<unsigned int>> *node_sets  = nullptr);

    /**
     * Which active cells are meshfree, indexed by active_cell_index(), from
     * 'Meshfree region' in subsection 'Geometry'. Throws on a malformed
     * region description, naming the entry.
     */
    template <int dim>
    std::vector<bool>
    mark_meshfree_cells(const Parameters::Geometry &parameters,
                        const Triangulation<dim>   &triangulation);

    /**
     * The largest distance between two boundary vertices of the mesh, the
     * same number as GridTools::diameter(). That one loops over all vertex
     * pairs (O(vertices^2): 16 s of a 28 s run at 263k vertices in 2-D);
     * this one visits the boundary vertices in the order of their distance
     * to the farthest corner of the bounding box (an upper bound of every
     * distance from them) and stops when that bound falls below the largest
     * distance found: on a box, only the corners are compared with all
     * others.
     */
    template <int dim>
    double
    diameter(const Triangulation<dim> &triangulation);
  } // namespace Mesh
} // namespace pg

#endif
