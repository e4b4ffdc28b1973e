#ifndef pg_mesh_mesh_generator_h
#define pg_mesh_mesh_generator_h

#include <pg/base/global.h>
#include <pg/mesh/geometry_parameters.h>

#include <deal.II/grid/tria.h>

#include <string>
#include <vector>

namespace pg
{
  namespace Mesh
  {
    /**
     * Fill the empty @p triangulation from subsection 'Geometry': the base
     * mesh with its boundary ids (and manifolds for curved boundaries), then
     * 'Global refinement', then 'Distortion' (reproducible by 'Random seed').
     * Throws with a message that names the entry on bad input (unreadable
     * file, unsupported dimension, ...). What was done to a mesh file
     * (coincident vertices merged) is appended to @p notes, one line each,
     * for the banner.
     */
    template <int dim>
    void
    create_mesh(const Parameters::Geometry &parameters,
                Triangulation<dim>         &triangulation,
                std::string                *notes = nullptr);

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
