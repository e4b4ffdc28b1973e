#ifndef pg_mesh_mesh_file_h
#define pg_mesh_mesh_file_h

#include <pg/base/global.h>
#include <pg/mesh/geometry_parameters.h>

#include <deal.II/grid/tria.h>

#include <map>
#include <string>
#include <vector>

namespace pg
{
  namespace Mesh
  {
    /**
     * Fill the empty @p triangulation from the mesh file 'File name' of
     * subsection 'Geometry' (Gmsh .msh, Abaqus .inp or UCD .ucd, read with
     * GridIn; Exodus II .g, .e or .exo, read with netCDF, see
     * exodus_file.h), then treat distinct vertices at the same position as
     * 'Coincident vertices' says (merge, reject or keep). Throws with a
     * message naming the file on an unknown extension, an unreadable file or
     * a file without cells of dimension @p dim. What was done (vertices
     * merged or kept) is appended to @p notes, one line each. The node
     * sets of an Exodus II file, as vertex indices of @p triangulation
     * (after the merge), go to @p node_sets if given (empty for the other
     * formats).
     */
    template <int dim>
    void
    read_mesh_file(
      const Parameters::Geometry                       &parameters,
      Triangulation<dim>                               &triangulation,
      std::string                                      *notes,
      std::map<std::string, std::vector<unsigned int>> *node_sets = nullptr);

    /**
     * Extend the node sets of a mesh file (vertex indices of the coarse
     * mesh) to the vertices that the refinement of @p triangulation added:
     * the midpoint of a line, the centre of a quadrilateral face and of a
     * hexahedron belong to a node set if all the vertices of the line,
     * face or cell do (level by level, so that the sets follow several
     * refinements). A node set on a face of the coarse mesh then holds
     * every vertex of that face of the refined mesh.
     */
    template <int dim>
    void
    refine_node_sets(
      const Triangulation<dim>                         &triangulation,
      std::map<std::string, std::vector<unsigned int>> &node_sets);
  } // namespace Mesh
} // namespace pg

#endif
