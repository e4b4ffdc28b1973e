// The VC correction system (pg-methods.md sections 11.4-11.7) on its own,
// without a Problem: on a distorted all-meshfree particle set,
// 1. after CorrectionSystem::reinit() + solve() and the factors handed to
//    the family elements, the corrected unit-stress residual d^k vanishes
//    to round-off (|d^k| / h^(dim-1) < 1e-12) at every interior particle,
//    for PBG (V5sn), PPG (V3s, V3sn, V3p) and VC2 (PPG2, V1s U2);
// 2. the linear patch test holds at interior particles: for u = H X and
//    the linear elastic material the assembled internal force is zero to
//    round-off, and (PBG: the trial functions are corrected too) F = 1 + H
//    at every evaluation point;
// 3. a rebuild (new family elements from the same families: what an
//    updated-Lagrangian reference update does) followed by reinit() and
//    solve() gives bitwise the same factors, and a rebuild after the
//    families changed (another horizon) gives a new system that again
//    corrects d^k to round-off;
// 4. a tangent-like matrix filled before the correction is untouched (the
//    correction system owns its own matrix).

#include <pg/base/formulation_code.h>
#include <pg/base/linear_algebra.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include "../tests.h"
#include "correction_fixture.h"

using namespace pg;

template <int dim>
void
test(const std::string &name)
{
  ParticleFixture<dim>  fixture(dim == 2 ? 8 : 4, 0.25, dim == 2 ? 2.51 : 2.01);
  const FormulationCode code = parse_formulation_code(name);
  const unsigned int    n    = fixture.particles.n_particles();
  deallog << dim << "d " << code.text << std::endl;

  // 4. a tangent-like matrix of the family couplings, filled beforehand
  DynamicSparsityPattern dsp(fixture.dof_handler.n_dofs());
  for (unsigned int k = 0; k < n; ++k)
    for (const unsigned int a : fixture.families.members(k))
      for (const unsigned int b : fixture.families.members(k))
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            dsp.add(fixture.particles.dof(a, i), fixture.particles.dof(b, j));
  const IndexSet all = complete_index_set(fixture.dof_handler.n_dofs());
  pg::LinearAlgebra::SparseMatrix tangent;
  tangent.reinit(all, all, dsp, MPI_COMM_WORLD);
  const auto value = [](const unsigned int i, const unsigned int j) {
    return 1. + i + 1e-3 * j;
  };
  for (unsigned int i = 0; i < dsp.n_rows(); ++i)
    for (auto p = dsp.begin(i); p != dsp.end(i); ++p)
      tangent.set(i, p->column(), value(i, p->column()));
  tangent.compress(VectorOperation::insert);

  CorrectionSystem<dim> system(code, MPI_COMM_WORLD);
  const Corrected<dim>  first = correct(fixture, code, system);

  // 1. interior d^k at round-off
  const double interior =
    max_interior_unit_stress_residual(fixture.particles, first.unit_stress);
  print_bound("  interior |d^k| / h^(dim-1)", interior, 1e-12);
  AssertThrow(interior < 1e-12, ExcInternalError());
  print_rounded("  max |alpha| h",
                first.factors.max_scaled_factor(fixture.particles),
                3);
  if (code.second_order_consistency)
    {
      print_bound("  interior |D^k| / h^dim",
                  first.factors.max_second_order_residual,
                  1e-12);
      AssertThrow(first.factors.max_second_order_residual < 1e-12,
                  ExcInternalError());
    }

  // 2. linear patch test: internal force of u = H X at interior particles
  Tensor<2, dim> H;
  for (unsigned int i = 0; i < dim; ++i)
    for (unsigned int j = 0; j < dim; ++j)
      H[i][j] = 1e-3 * (1. + i + 2. * j);
  const auto                  material = make_material<dim>("linear elastic");
  std::vector<Tensor<1, dim>> force(n);
  double                      largest_F_error = 0;
  Vector<double>              residual;
  for (unsigned int k = 0; k < n; ++k)
    {
      const auto                  members = fixture.families.members(k);
      std::vector<Tensor<1, dim>> y(members.size());
      for (unsigned int b = 0; b < members.size(); ++b)
        {
          const Tensor<1, dim> X = fixture.particles.position(members[b]);
          y[b] =
            X - Tensor<1, dim>(fixture.particles.position(members[0])) + H * X;
        }
      assemble_element(first.tables[k], y, *material, residual, nullptr);
      for (unsigned int b = 0; b < members.size(); ++b)
        for (unsigned int c = 0; c < dim; ++c)
          force[members[b]][c] += residual(b * dim + c);
      for (unsigned int q = 0; q < first.tables[k].n_points(); ++q)
        largest_F_error =
          std::max(largest_F_error,
                   (deformation_gradient(first.tables[k], q, y) -
                    unit_symmetric_tensor<dim>() - H)
                     .norm());
    }
  double largest_force = 0;
  for (unsigned int k = 0; k < n; ++k)
    if (fixture.particles.boundary_area_vectors(k).empty())
      largest_force =
        std::max(largest_force,
                 force[k].norm() /
                   (100. * H.norm() *
                    std::pow(fixture.particles.spacing(k), dim - 1)));
  print_bound("  interior |f^k| / (E |H| h^(dim-1)) for u = H X",
              largest_force,
              1e-11);
  AssertThrow(largest_force < 1e-11, ExcInternalError());
  print_bound("  max |F_q - (1 + H)|", largest_F_error, 1e-12);
  AssertThrow(largest_F_error < 1e-12, ExcInternalError());

  // 3. rebuild: the same families again, then other families
  const Corrected<dim> second = correct(fixture, code, system);
  bool                 identical =
    (second.factors.alpha == first.factors.alpha &&
     second.factors.second_order_alpha == first.factors.second_order_alpha);
  deallog << "  second reinit + solve gives identical factors: "
          << (identical ? "yes" : "NO") << std::endl;
  AssertThrow(identical, ExcInternalError());

  fixture.families.reinit(fixture.particles, dim == 2 ? 3.01 : 2.51, 0);
  const Corrected<dim> third = correct(fixture, code, system);
  const double         rebuilt =
    max_interior_unit_stress_residual(fixture.particles, third.unit_stress);
  print_bound("  other families: interior |d^k| / h^(dim-1)", rebuilt, 1e-12);
  AssertThrow(rebuilt < 1e-12, ExcInternalError());
  AssertThrow(third.factors.alpha != first.factors.alpha, ExcInternalError());
  AssertThrow(code.second_order_consistency ||
                third.matrix_nonzeros > first.matrix_nonzeros,
              ExcInternalError());

  // 4. the tangent is untouched
  bool untouched = true;
  for (unsigned int i = 0; i < dsp.n_rows(); ++i)
    for (auto p = dsp.begin(i); p != dsp.end(i); ++p)
      untouched =
        untouched && (tangent.el(i, p->column()) == value(i, p->column()));
  deallog << "  tangent untouched: " << (untouched ? "yes" : "NO") << std::endl;
  AssertThrow(untouched, ExcInternalError());
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  for (const std::string code : {"VCBCPBG V5sn Unl",
                                 "VCBCPPG V3s Unl",
                                 "VCPPG V3sn Unl",
                                 "VCPPG V3p Unl"})
    test<2>(code);
  test<2>("VC2PPG V1s U2");
  test<3>("VCBCPBG V5sn Unl");
}
