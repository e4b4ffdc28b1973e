#ifndef pg_mesh_exodus_file_h
#define pg_mesh_exodus_file_h

#include <pg/base/global.h>

#include <deal.II/base/point.h>
#include <deal.II/grid/tria_description.h>

#include <map>
#include <string>
#include <vector>

namespace pg
{
  namespace Mesh
  {
    /**
     * What pg takes from an Exodus II mesh (Sandia's netCDF-based format
     * of Cubit, Peridigm and MOOSE): the nodes, the elements of every
     * element block, the side sets and the node sets.
     */
    template <int dim>
    struct ExodusMesh
    {
      /** The nodes, in the file's order. */
      std::vector<Point<dim>> vertices;
      /**
       * The elements in deal.II's vertex order; the material id of each is
       * the id of its element block (eb_prop1).
       */
      std::vector<CellData<dim>> cells;
      /**
       * The faces of the side sets, boundary id = side set id (ss_prop1),
       * in subcelldata.boundary_lines (2-D) or boundary_quads (3-D).
       */
      SubCellData subcelldata;
      /**
       * The node sets: name -> indices into vertices. The name is the one
       * in ns_names or, where that is empty, "nodelist_<id>", the name
       * Peridigm gives node set <id>.
       */
      std::map<std::string, std::vector<unsigned int>> node_sets;
    };

    /**
     * Whether this build of pg reads Exodus II files (it needs the netCDF
     * library at configure time, Debian package libnetcdf-dev).
     */
    bool
    exodus_support();

    /**
     * Read the Exodus II file @p file_name ('File name' of subsection
     * 'Geometry', a .g, .e or .exo file). Elements: QUAD4 and TRI3 in 2-D
     * (num_dim = 2), HEX8 and TETRA4 in 3-D, with their usual alias names;
     * every other element type (SPHERE particles, second-order elements,
     * wedges, shells in 3-D) stops with a message that names the block and
     * the type. Throws with a message naming the file if it cannot be
     * opened or is not Exodus II, or if num_dim differs from @p dim.
     */
    template <int dim>
    ExodusMesh<dim>
    read_exodus_file(const std::string &file_name);
  } // namespace Mesh
} // namespace pg

#endif
