// Particles of Gmsh triangle and tetrahedron meshes (issue 49): each
// simplex gives 1/(dim+1) of its volume to each vertex, each boundary face
// 1/dim of its area vector to each of its vertices. Checked on
// distorted_triangles.msh and distorted_tetrahedra.msh (both [-1,1]^dim):
// - the lumped volumes against the simplex sums computed here from the
//   vertices (largest difference < 1e-14),
// - their total against the mesh volume 2^dim (relative < 1e-13),
// - the area vectors of each boundary id against the face's area vector
//   (2^(dim-1) n, relative < 1e-13), and no area vector at interior
//   particles (the vertices off a face get nothing from it).
// Then the same for a refined mesh ('Global refinement = 1').

#include <pg/base/parameters.h>
#include <pg/mesh/linear_cells.h>
#include <pg/mesh/mesh_generator.h>
#include <pg/mesh/particle_set.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include "../geometry_fixture.h"
#include "../tests.h"

#include <cmath>
#include <map>
#include <string>
#include <vector>

template <int dim>
void
check(const std::string &file, const unsigned int refinement)
{
  const pg::Parameters::Geometry geometry = geometry_parameters(
    "  set Mesh = file\n  set File name = " SOURCE_DIR "/" + file +
    "\n  set Global refinement = " + std::to_string(refinement) + "\n");

  Triangulation<dim> tria;
  pg::Mesh::create_mesh(geometry, tria);
  const pg::LinearCells<dim> cells(tria);
  DoFHandler<dim>            dof_handler(tria);
  const FESystem<dim>        fe(cells.scalar_element(), dim);
  dof_handler.distribute_dofs(fe);
  pg::ParticleSet<dim> particles;
  particles.reinit(dof_handler, std::vector<bool>(tria.n_active_cells(), true));

  // the simplex sums, from the vertices alone
  std::vector<double> lumped(tria.n_vertices(), 0.);
  for (const auto &cell : tria.active_cell_iterators())
    {
      Tensor<2, dim> edges;
      for (unsigned int d = 0; d < dim; ++d)
        edges[d] = cell->vertex(d + 1) - cell->vertex(0);
      const double measure =
        std::abs(determinant(edges)) / (dim == 2 ? 2. : 6.);
      for (const unsigned int v : cell->vertex_indices())
        lumped[cell->vertex_index(v)] += measure / (dim + 1);
    }
  double total = 0, largest_difference = 0, measures = 0;
  for (const auto &cell : tria.active_cell_iterators())
    measures += cell->measure();
  std::map<types::boundary_id, Tensor<1, dim>> area;
  unsigned int                                 interior_with_area = 0;
  std::vector<bool> on_boundary(tria.n_vertices(), false);
  for (const auto &face : tria.active_face_iterators())
    if (face->at_boundary())
      for (const unsigned int v : face->vertex_indices())
        on_boundary[face->vertex_index(v)] = true;
  for (unsigned int k = 0; k < particles.n_particles(); ++k)
    {
      total += particles.volume(k);
      largest_difference =
        std::max(largest_difference,
                 std::abs(particles.volume(k) - lumped[particles.vertex(k)]));
      for (const auto &[id, a] : particles.boundary_area_vectors(k))
        area[id] += a;
      if (!on_boundary[particles.vertex(k)] &&
          !particles.boundary_area_vectors(k).empty())
        ++interior_with_area;
    }
  const double volume = std::pow(2., dim);
  deallog << file << ", refinement " << refinement << ": "
          << tria.n_active_cells() << " " << cells.name() << ", "
          << particles.n_particles() << " particles" << std::endl;
  deallog << "  volumes = simplex sums: "
          << (largest_difference < 1e-14 ? "yes" : "NO") << std::endl;
  deallog << "  total volume = " << volume << ": "
          << (std::abs(total - volume) < 1e-13 * volume ? "yes" : "NO")
          << " (sum of cell->measure(): "
          << (std::abs(measures - volume) < 1e-13 * volume ? "yes" : "NO")
          << ")" << std::endl;
  bool areas_exact = (area.size() == 2 * dim);
  for (const auto &[id, a] : area)
    {
      Tensor<1, dim> expected;
      expected[id / 2] = (id % 2 == 0 ? -1. : 1.) * std::pow(2., dim - 1);
      areas_exact =
        areas_exact && (a - expected).norm() < 1e-13 * expected.norm();
    }
  deallog << "  area vectors of the " << area.size()
          << " boundary ids = face area vectors: "
          << (areas_exact ? "yes" : "NO") << std::endl;
  deallog << "  interior particles with an area vector: " << interior_with_area
          << std::endl;
}



int
main()
{
  initlog();
  check<2>("distorted_triangles.msh", 0);
  check<2>("distorted_triangles.msh", 1);
  check<3>("distorted_tetrahedra.msh", 0);
  check<3>("distorted_tetrahedra.msh", 1);
}
