// pg::Mesh::create_mesh on Exodus II files (tests/exodus/bar_hex.g and
// square_tri.g, written by make_test_meshes.py): HEX8 and TRI3 elements in
// deal.II's vertex order (every cell has its exact volume), element blocks
// as material ids, side sets as boundary ids, node sets by name (named and
// unnamed: 'nodelist_<id>') as vertex indices after the merge of the
// unmerged block interface, kept through global refinement; and the
// messages for a file of the wrong dimension, a file that is not netCDF and
// a missing file.

#include <pg/base/exceptions.h>
#include <pg/base/parameters.h>
#include <pg/mesh/mesh_generator.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/tria.h>

#include "../geometry_fixture.h"
#include "../tests.h"

#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace
{
  pg::Parameters::Geometry
  geometry(const std::string &file, const unsigned int refinement = 0)
  {
    return geometry_parameters(
      "  set Mesh = file\n  set File name = " + file +
      "\n  set Global refinement = " + std::to_string(refinement) + "\n");
  }



  template <int dim>
  void
  check(const std::string &file, const unsigned int refinement)
  {
    deallog << file.substr(file.rfind('/') + 1) << ", " << dim
            << "-D, refinement " << refinement << std::endl;
    Triangulation<dim>                               triangulation;
    std::string                                      notes;
    std::map<std::string, std::vector<unsigned int>> node_sets;
    pg::Mesh::create_mesh(geometry(file, refinement),
                          triangulation,
                          &notes,
                          {},
                          &node_sets);
    deallog << notes.substr(notes.find("Exodus"),
                            notes.rfind('\n') - notes.find("Exodus"))
            << std::endl;
    deallog << "vertices " << triangulation.n_used_vertices() << ", cells "
            << triangulation.n_active_cells() << std::endl;

    double                               volume = 0, smallest = 1e300;
    std::map<types::material_id, double> block_volume;
    std::map<types::boundary_id, double> boundary_measure;
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        volume += cell->measure();
        smallest = std::min(smallest, cell->measure());
        block_volume[cell->material_id()] += cell->measure();
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            boundary_measure[face->boundary_id()] += face->measure();
      }
    print_rounded("volume", volume, 10);
    deallog << "smallest cell volume > 0: " << (smallest > 0) << std::endl;
    for (const auto &[id, v] : block_volume)
      print_rounded("  block " + std::to_string(id) + " volume", v, 10);
    for (const auto &[id, a] : boundary_measure)
      print_rounded("  boundary id " + std::to_string(id) + " measure", a, 10);

    const auto &vertices = triangulation.get_vertices();
    for (const auto &[name, set] : node_sets)
      {
        Point<dim> lower = vertices[set[0]], upper = vertices[set[0]];
        for (const unsigned int v : set)
          for (unsigned int d = 0; d < dim; ++d)
            {
              lower[d] = std::min(lower[d], vertices[v][d]);
              upper[d] = std::max(upper[d], vertices[v][d]);
            }
        deallog << "  node set " << name << ": " << set.size()
                << " vertices in [" << lower << "] - [" << upper << "]"
                << std::endl;
      }
  }



  template <int dim>
  void
  bad(const std::string &what, const std::string &file)
  {
    Triangulation<dim> triangulation;
    try
      {
        pg::Mesh::create_mesh(geometry(file), triangulation);
        deallog << what << ": no error" << std::endl;
      }
    catch (const std::exception &e)
      {
        std::string message = pg::user_message(e);
        // the path depends on the machine
        const auto at = message.find(file);
        if (at != std::string::npos)
          message.replace(at, file.size(), "<file>");
        deallog << what << ": " << message << std::endl;
      }
  }
} // namespace



int
main()
{
  initlog();
  check<3>(SOURCE_DIR "/bar_hex.g", 0);
  check<3>(SOURCE_DIR "/bar_hex.g", 1);
  check<2>(SOURCE_DIR "/square_tri.g", 0);

  bad<2>("wrong dimension", SOURCE_DIR "/bar_hex.g");
  {
    std::ofstream text("not_netcdf.g");
    text << "this is not an Exodus II file\n";
  }
  bad<3>("not netCDF", "not_netcdf.g");
  bad<3>("missing file", "no_such_file.g");
}
