// 'Geometry/Cells = simplices' (issue 49): the built-in meshes split into
// triangles (tetrahedra) by GridGenerator::convert_hypercube_to_simplex_mesh
// after 'Global refinement', 'Distortion' and 'Hole'. For each mesh, the
// split against the same parameters with 'Cells = hypercubes':
// - 8 triangles per quadrilateral (24 tetrahedra per hexahedron), every
//   cell a simplex, every hypercube vertex kept, and the cell and vertex
//   counts that predict_mesh_size() gives before the mesh is built;
// - the same volume (sum of cell->measure()) and, for each boundary id,
//   the same boundary measure (relative 1e-13), the same material ids;
// - no manifold left on the simplices (straight P1 cells);
// - on the plate with a hole the new vertices of the hole lie on its
//   circle (deal.II 9.4 puts them at the mean of the old ones; pg moves
//   them), so the split's hole length is closer to pi R / 2 than the
//   chords of the quadrilaterals (both printed to 6 digits);
// - on the box [-1,1]^dim the split is its own mirror image across every
//   coordinate plane (the set of simplex centres is reflected onto
//   itself), which the quarter-versus-full tests of
//   problem/simplex_mirror_symmetry_01 need;
// - on a parallel::shared::Triangulation (the one pg runs on) it gives the
//   same cells as on a serial Triangulation.

#include <pg/base/parameters.h>
#include <pg/mesh/mesh_generator.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/grid/tria.h>

#include "../geometry_fixture.h"
#include "../tests.h"

#include <array>
#include <cmath>
#include <map>
#include <set>
#include <string>

template <int dim>
pg::Parameters::Geometry
geometry(const std::string &text, const std::string &cells)
{
  return geometry_parameters(text + "  set Cells = " + cells + "\n");
}



/** Volume, and the boundary measure of each id. */
template <int dim>
std::pair<double, std::map<types::boundary_id, double>>
measures(const Triangulation<dim> &tria)
{
  double                               volume = 0;
  std::map<types::boundary_id, double> boundary;
  for (const auto &cell : tria.active_cell_iterators())
    {
      volume += cell->measure();
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          boundary[face->boundary_id()] += face->measure();
    }
  return {volume, boundary};
}



template <int dim>
std::array<long, dim>
key(const Point<dim> &p)
{
  std::array<long, dim> k;
  for (unsigned int d = 0; d < dim; ++d)
    k[d] = std::lround(p[d] * 1e9);
  return k;
}



template <int dim>
void
check(const std::string &name, const std::string &text)
{
  const pg::Parameters::Geometry hypercube_geometry =
    geometry<dim>(text, "hypercubes");
  const pg::Parameters::Geometry simplex_geometry =
    geometry<dim>(text, "simplices");
  Triangulation<dim> hypercubes;
  pg::Mesh::create_mesh(hypercube_geometry, hypercubes);
  parallel::shared::Triangulation<dim> simplices(MPI_COMM_WORLD);
  std::string                          notes;
  pg::Mesh::MeshSize                   predicted;
  pg::Mesh::create_mesh(simplex_geometry,
                        simplices,
                        &notes,
                        [&](const pg::Mesh::MeshSize &size) {
                          predicted = size;
                        });
  Triangulation<dim> serial;
  pg::Mesh::create_mesh(simplex_geometry, serial);

  deallog << name << ": " << hypercubes.n_active_cells() << " -> "
          << simplices.n_active_cells() << " cells, "
          << simplices.n_used_vertices() << " vertices" << std::endl;
  // the banner's line, without its indentation and line end
  deallog << "  "
          << notes.substr(notes.find("split"),
                          notes.find('\n') - notes.find("split"))
          << std::endl;
  const unsigned int per_cell = (dim == 2 ? 8 : 24);
  deallog << "  " << per_cell << " simplices per cell, all simplices: "
          << (simplices.n_active_cells() ==
                    per_cell * hypercubes.n_active_cells() &&
                  simplices.all_reference_cells_are_simplex() ?
                "yes" :
                "NO")
          << std::endl;
  // the predicted counts (only for generated meshes without a hole)
  if (text.find("Hole") == std::string::npos)
    deallog << "  predicted cells and vertices: "
            << (predicted.n_cells == simplices.n_active_cells() &&
                    predicted.n_vertices == simplices.n_used_vertices() ?
                  "yes" :
                  "NO")
            << std::endl;
  std::set<std::array<long, dim>> simplex_vertices;
  for (unsigned int v = 0; v < simplices.n_vertices(); ++v)
    if (simplices.get_used_vertices()[v])
      simplex_vertices.insert(key(simplices.get_vertices()[v]));
  unsigned int lost = 0;
  for (unsigned int v = 0; v < hypercubes.n_vertices(); ++v)
    if (hypercubes.get_used_vertices()[v] &&
        simplex_vertices.count(key(hypercubes.get_vertices()[v])) == 0)
      ++lost;
  deallog << "  hypercube vertices lost: " << lost << std::endl;

  const auto [v_h, b_h] = measures(hypercubes);
  const auto [v_s, b_s] = measures(simplices);
  const bool curved     = (name.find("plate") != std::string::npos);
  if (!curved)
    print_bound("  |volume - hypercube volume| / volume",
                std::abs(v_s - v_h) / v_h,
                1e-13);
  bool same_ids = (b_h.size() == b_s.size());
  for (const auto &[id, a] : b_h)
    if (!(curved && id == 0))
      same_ids =
        same_ids && b_s.count(id) == 1 && std::abs(b_s.at(id) - a) <= 1e-13 * a;
  deallog << "  boundary ids " << b_h.begin()->first << ".."
          << b_h.rbegin()->first << " with the same measures"
          << (curved ? " (the straight ones)" : "") << ": "
          << (same_ids ? "yes" : "NO") << std::endl;
  if (curved)
    {
      const double       exact = numbers::PI / 2;
      std::ostringstream line;
      line << std::setprecision(6) << "  hole length: quadrilaterals "
           << b_h.at(0) << ", triangles " << b_s.at(0) << ", pi R / 2 " << exact
           << ": closer "
           << (std::abs(b_s.at(0) - exact) < std::abs(b_h.at(0) - exact) ?
                 "yes" :
                 "NO");
      deallog << line.str() << std::endl;
      // the vertices of the hole on its circle (R = 1)
      double off_circle = 0;
      for (const auto &cell : simplices.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && face->boundary_id() == 0)
            for (const unsigned int v : face->vertex_indices())
              off_circle =
                std::max(off_circle, std::abs(face->vertex(v).norm() - 1.));
      print_bound("  max | |x| - R | on the hole", off_circle, 1e-14);
    }
  std::map<types::material_id, double> material_h, material_s;
  for (const auto &cell : hypercubes.active_cell_iterators())
    material_h[cell->material_id()] += cell->measure();
  for (const auto &cell : simplices.active_cell_iterators())
    material_s[cell->material_id()] += cell->measure();
  bool same_materials = (material_h.size() == material_s.size());
  for (const auto &[id, m] : material_h)
    same_materials = same_materials && material_s.count(id) == 1 &&
                     (curved || std::abs(material_s.at(id) - m) <= 1e-13 * m);
  deallog << "  material ids kept: " << (same_materials ? "yes" : "NO")
          << std::endl;
  bool flat = true;
  for (const auto &cell : simplices.active_cell_iterators())
    {
      flat = flat && cell->manifold_id() == numbers::flat_manifold_id;
      for (const auto &face : cell->face_iterators())
        flat = flat && face->manifold_id() == numbers::flat_manifold_id;
    }
  deallog << "  manifold ids flat: " << (flat ? "yes" : "NO") << std::endl;
  bool same_serial = (serial.n_active_cells() == simplices.n_active_cells());
  auto c           = serial.begin_active();
  for (const auto &cell : simplices.active_cell_iterators())
    if (same_serial)
      {
        same_serial = cell->center().distance(c->center()) < 1e-14;
        ++c;
      }
  deallog << "  shared = serial triangulation: " << (same_serial ? "yes" : "NO")
          << std::endl;

  if (name.find("box") != std::string::npos)
    {
      std::set<std::array<long, dim>> centres;
      for (const auto &cell : simplices.active_cell_iterators())
        centres.insert(key(cell->center()));
      unsigned int missing = 0;
      for (unsigned int d = 0; d < dim; ++d)
        for (const auto &cell : simplices.active_cell_iterators())
          {
            Point<dim> p = cell->center();
            p[d]         = -p[d];
            missing += (centres.count(key(p)) == 0);
          }
      deallog << "  mirror image of itself across the " << dim
              << " coordinate planes: " << (missing == 0 ? "yes" : "NO")
              << std::endl;
    }
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  check<2>("2-D box",
           "  set Lower corner = -1, -1\n  set Upper corner = 1, 1\n"
           "  set Subdivisions = 3, 2\n  set Global refinement = 1\n");
  check<2>("2-D distorted rectangle",
           "  set Lower corner = 0, 0\n  set Upper corner = 2, 1\n"
           "  set Subdivisions = 6, 3\n  set Distortion = 0.3\n");
  check<2>("2-D rectangle with a hole",
           "  set Subdivisions = 5\n  set Hole = box 0.3,0.3 : 0.7,0.7\n");
  check<2>("2-D cook membrane",
           "  set Mesh = cook membrane\n  set Subdivisions = 4\n"
           "  set Global refinement = 1\n");
  check<2>("2-D plate with hole",
           "  set Mesh = plate with hole\n  set Global refinement = 1\n");
  check<3>("3-D box",
           "  set Lower corner = -1, -1, -1\n  set Upper corner = 1, 1, 1\n"
           "  set Subdivisions = 2, 3, 2\n  set Global refinement = 1\n");
  check<3>("3-D cook membrane",
           "  set Mesh = cook membrane\n  set Subdivisions = 2\n"
           "  set Thickness = 10\n");
}
