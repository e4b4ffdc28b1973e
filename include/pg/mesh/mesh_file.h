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
  } // namespace Mesh
} // namespace pg

#endif
