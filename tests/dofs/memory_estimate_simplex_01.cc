// The memory estimate on tetrahedral meshes (issue 49, deliverable 5;
// pg/dofs/memory_estimate.h). It was made for hypercubes: a refined mesh
// file had about one vertex per cell (a tetrahedral mesh has 5 to 6 cells
// per vertex), a P1 row the 27 nodes of a Q1 row (P1 couples a node to its
// edge neighbours only). On
// tests/mesh/cube_tetrahedra.msh (Gmsh, the unit cube, 457 vertices):
// - the predicted vertices and cells against the mesh built, unrefined and
//   refined once (exact: a refinement adds one vertex per edge);
// - the P1 nonzeros per row against deal.II's sparsity pattern of
//   FE_SimplexP(1) (equal: every edge is counted);
// - the estimated family size and coupled particles per row (PG, 'Horizon
//   factor = 1.51') against pg's families (FamilySet) at the particles more
//   than a horizon inside, beside the same on a distorted hexahedral
//   cube, whose estimate was made for it: the lattice counts within 1.51
//   and 3.02 spacings, for both (within 25 %; a tetrahedral family is 1.2
//   times larger).

#include <pg/base/formulation_code.h>
#include <pg/base/parameters.h>
#include <pg/dofs/memory_estimate.h>
#include <pg/families/family_set.h>
#include <pg/mesh/linear_cells.h>
#include <pg/mesh/mesh_generator.h>
#include <pg/mesh/particle_set.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include "../geometry_fixture.h"
#include "../tests.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>


namespace
{
  constexpr int dim = 3;



  pg::Parameters::Discretization
  discretization(const double horizon_factor)
  {
    pg::Parameters::Discretization p;
    p.shape_functions    = "MTE1";
    p.horizon_factor     = horizon_factor;
    p.horizon            = 0;
    p.nearest_neighbours = 0;
    p.weight_exponent    = 1;
    return p;
  }



  /** The mesh of @p entries and the size predicted for it. */
  pg::Mesh::MeshSize
  build(const std::string &entries, Triangulation<dim> &triangulation)
  {
    pg::Mesh::MeshSize predicted;
    pg::Mesh::create_mesh(geometry_parameters(entries),
                          triangulation,
                          nullptr,
                          [&](const pg::Mesh::MeshSize &size) {
                            predicted = size;
                          });
    return predicted;
  }



  /** true if @p a and @p b differ by at most the fraction @p tolerance. */
  bool
  close(const double a, const double b, const double tolerance)
  {
    return std::abs(a - b) <= tolerance * std::max(std::abs(a), std::abs(b));
  }



  /**
   * pg's families at 'Horizon factor = 1.51' on every cell of
   * @p triangulation: the mean family size (master included) and the mean
   * number of particles that share a family with a particle (itself
   * included: the nonzeros of its rows per component), over the particles
   * more than a horizon from the boundary of the unit cube (their families
   * are whole, the particles coupled to them not quite), against the
   * estimate for @p size.
   */
  void
  families(const std::string        &name,
           const Triangulation<dim> &triangulation,
           const pg::Mesh::MeshSize &size)
  {
    const pg::LinearCells<dim> cells(triangulation);
    DoFHandler<dim>            dof_handler(triangulation);
    const FESystem<dim>        fe(cells.scalar_element(), dim);
    dof_handler.distribute_dofs(fe);
    pg::ParticleSet<dim> particles;
    particles.reinit(dof_handler,
                     std::vector<bool>(triangulation.n_active_cells(), true));
    pg::FamilySet<dim> family_set;
    family_set.reinit(particles, 1.51, 0);

    std::vector<std::set<unsigned int>> coupled(particles.n_particles());
    for (unsigned int k = 0; k < family_set.n_families(); ++k)
      for (const unsigned int i : family_set.members(k))
        for (const unsigned int j : family_set.members(k))
          coupled[i].insert(j);

    double       family_sum = 0, coupled_sum = 0;
    unsigned int n_inside = 0;
    for (unsigned int k = 0; k < particles.n_particles(); ++k)
      {
        const Point<dim> &x     = particles.position(k);
        double            depth = 1.;
        for (unsigned int d = 0; d < dim; ++d)
          depth = std::min({depth, x[d], 1. - x[d]});
        if (depth <= family_set.horizon(k))
          continue;
        family_sum += family_set.n_neighbours(k) + 1;
        coupled_sum += coupled[k].size();
        ++n_inside;
      }
    AssertThrow(n_inside > 10, ExcInternalError());
    const double family = family_sum / n_inside;
    const double row    = coupled_sum / n_inside;

    const pg::MemoryEstimate e =
      pg::estimate_memory<dim>(size,
                               pg::parse_formulation_code("VCBCPBG V5sn Unl"),
                               discretization(1.51));
    deallog << name << ": " << particles.n_particles() << " particles, "
            << "inside: family " << std::round(family) << " (estimate "
            << e.family_size << ", within 25 %: "
            << (close(family, e.family_size, 0.25) ? "yes" : "NO")
            << "), particles per row " << std::round(row) << " (estimate "
            << e.nonzeros_per_row / dim << ", within 25 %: "
            << (close(row, e.nonzeros_per_row / dim, 0.25) ? "yes" : "NO")
            << ")" << std::endl;
  }
} // namespace



int
main()
{
  initlog();
  const std::string file = "set Mesh = file\nset File name = " SOURCE_DIR
                           "/../mesh/cube_tetrahedra.msh\n";

  // the counts, unrefined (exact) and refined once (an estimate)
  for (const unsigned int refinement : {0u, 1u})
    {
      Triangulation<dim>       triangulation;
      const pg::Mesh::MeshSize size =
        build(file + "set Global refinement = " + std::to_string(refinement) +
                "\n",
              triangulation);
      deallog << "tetrahedra, refinement " << refinement << ": simplex "
              << (size.simplex ? "yes" : "no") << ", cells "
              << static_cast<long long>(size.n_cells) << " (built "
              << triangulation.n_active_cells() << "), vertices "
              << static_cast<long long>(size.n_vertices) << " (built "
              << triangulation.n_used_vertices() << ", within 10 %: "
              << (close(size.n_vertices, triangulation.n_used_vertices(), 0.1) ?
                    "yes" :
                    "no")
              << ")" << std::endl;
    }

  // P1 rows: the edge neighbours and the node itself
  {
    Triangulation<dim>         triangulation;
    const pg::Mesh::MeshSize   size = build(file, triangulation);
    const pg::LinearCells<dim> cells(triangulation);
    DoFHandler<dim>            dof_handler(triangulation);
    dof_handler.distribute_dofs(cells.scalar_element());
    DynamicSparsityPattern pattern(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, pattern);
    const double row =
      static_cast<double>(pattern.n_nonzero_elements()) / dof_handler.n_dofs();
    const pg::MemoryEstimate e =
      pg::estimate_memory<dim>(size,
                               pg::parse_formulation_code("FEM"),
                               discretization(1.51));
    deallog << "P1 nonzeros per row: sparsity pattern "
            << std::round(row * dim * 1e6) / 1e6 << ", estimate "
            << std::round(e.nonzeros_per_row * 1e6) / 1e6
            << " (Q1: " << std::pow(3, dim) * dim << "), equal: "
            << (std::abs(row * dim - e.nonzeros_per_row) < 1e-9 ? "yes" : "NO")
            << std::endl;
  }

  // families
  {
    Triangulation<dim>       triangulation;
    const pg::Mesh::MeshSize size = build(file, triangulation);
    families("tetrahedra", triangulation, size);
  }
  {
    Triangulation<dim>       triangulation;
    const pg::Mesh::MeshSize size =
      build("set Lower corner = 0, 0, 0\nset Upper corner = 1, 1, 1\n"
            "set Subdivisions = 12, 12, 12\nset Distortion = 0.3\n"
            "set Random seed = 1\n",
            triangulation);
    families("hexahedra 12^3, distortion 0.3", triangulation, size);
  }
}
