// The families of the mixed formulations with nodal pressure and dilatation
// (assemble_nodal_pressure_family(), pg-methods.md sections 12.2.2-12.2.3),
// on an interior and a corner family of a distorted particle set, for the
// isochoric-volumetric neo-Hooke at nu = 0.4999, in 2-D and 3-D:
// - PBG U2P1C (no bubble) and BCPBG Unl+P1C with the bubble at local
//   equilibrium: the tangent is the central-difference Jacobian of the
//   residual with respect to (u, p, vartheta) (for Unl+P1C: of the
//   residual with the bubble re-solved at every perturbed state), and it is
//   symmetric;
// - Unl+P1C with the bubble as a Newton iterate away from equilibrium: the
//   local update with du = 0 is one Newton step of r_b = 0, so it shrinks
//   the bubble's distance to equilibrium quadratically, and the condensed
//   residual from the stored equilibrium bubble equals the equilibrium
//   residual;
// - a homogeneous deformation (u = (F - I) X, p = W_vol'(J), vartheta =
//   J - 1 at every node): the p and Theta rows vanish and the bubble is 0.

#include <pg/base/formulation_code.h>
#include <pg/elements/family_elements.h>
#include <pg/elements/nodal_pressure.h>
#include <pg/materials/material.h>

#include "../particle_fixture.h"
#include "../tests.h"

using namespace pg;

template <int dim>
struct FamilyState
{
  std::vector<Tensor<1, dim>> y;
  std::vector<double>         p, vartheta;

  /** Local DoF i (u node-major, then p, then vartheta) += @p delta. */
  void
  perturb(const unsigned int i, const double delta)
  {
    const unsigned int n = y.size();
    if (i < n * dim)
      y[i / dim][i % dim] += delta;
    else if (i < n * dim + n)
      p[i - n * dim] += delta;
    else
      vartheta[i - n * dim - n] += delta;
  }
};



double
max_abs(const FullMatrix<double> &A)
{
  double m = 0;
  for (unsigned int i = 0; i < A.m(); ++i)
    for (unsigned int j = 0; j < A.n(); ++j)
      m = std::max(m, std::abs(A(i, j)));
  return m;
}



template <int dim>
void
test()
{
  const ParticleFixture<dim> fixture(dim == 2 ? 6 : 4,
                                     0.25,
                                     dim == 2 ? 2.51 : 2.01);
  const double                           h = 1. / (dim == 2 ? 6 : 4);
  std::mt19937                           rng(5);
  std::uniform_real_distribution<double> random(-1., 1.);

  Parameters::Material parameters;
  parameters.model          = "isochoric-volumetric neo-Hooke";
  parameters.youngs_modulus = 100.;
  parameters.poissons_ratio = 0.4999;
  parameters.density        = 1.;
  parameters.plane          = "strain";
  const auto  material      = Materials::create_material<dim>(parameters);
  const auto &split =
    dynamic_cast<const Materials::VolumetricSplit<dim> &>(*material);
  const double K = parameters.lambda() + 2. / 3. * parameters.mu();
  // (K: the scale of the pressure perturbations)

  for (const std::string code : {"PBG U2P1C", "BCPBG Unl+P1C"})
    {
      const FormulationCode formulation = parse_formulation_code(code);
      const bool            bubble      = formulation.bubble;
      FamilyElements<dim>   elements(fixture.particles,
                                   fixture.families,
                                   formulation,
                                   ShapeFunctions::parse_base("MTE1"),
                                   1.);
      elements.initialize();
      double fd_error = 0, asymmetry = 0, local_contraction = 0,
             equilibrium_difference = 0, patch_rows = 0, patch_bubble = 0;
      for (const unsigned int k : fixture.interior_and_corner())
        {
          QuadratureTable<dim> table;
          elements.build(k, table);
          const std::vector<Tensor<1, dim>> X = elements.geometry(k).bonds;
          const unsigned int                n = X.size();

          // A finite deformation with nodal fields near their equilibrium
          FamilyState<dim> state;
          state.y = X;
          state.p.resize(n);
          state.vartheta.resize(n);
          for (unsigned int b = 0; b < n; ++b)
            {
              // a nearly isochoric stretch and shear, J about 1
              state.y[b][0] += 0.05 * X[b][0] + 0.03 * X[b][1];
              state.y[b][1] += -0.05 / 1.05 * X[b][1];
              for (unsigned int c = 0; c < dim; ++c)
                state.y[b][c] += 0.01 * h * random(rng);
              state.vartheta[b] = 0.002 * random(rng);
              state.p[b]        = split.volumetric_strain_energy_derivative(
                             1. + state.vartheta[b]) +
                           0.02 * parameters.mu() * random(rng);
            }
          const auto residual_at = [&](const FamilyState<dim> &s) {
            Vector<double> r;
            assemble_nodal_pressure_family(table,
                                           s.y,
                                           s.p,
                                           s.vartheta,
                                           split,
                                           bubble,
                                           r,
                                           nullptr);
            return r;
          };
          Vector<double>     r;
          FullMatrix<double> K_family;
          assemble_nodal_pressure_family(table,
                                         state.y,
                                         state.p,
                                         state.vartheta,
                                         split,
                                         bubble,
                                         r,
                                         &K_family);
          const unsigned int N = r.size();
          AssertThrow(N == n * (dim + 2), ExcInternalError());
          FullMatrix<double> J(N, N);
          for (unsigned int j = 0; j < N; ++j)
            {
              const double     eps  = (j < n * dim     ? 1e-6 * h :
                                       j < n * dim + n ? 1e-6 * K :
                                                         1e-6);
              FamilyState<dim> plus = state, minus = state;
              plus.perturb(j, eps);
              minus.perturb(j, -eps);
              const Vector<double> rp = residual_at(plus),
                                   rm = residual_at(minus);
              for (unsigned int i = 0; i < N; ++i)
                J(i, j) = (rp[i] - rm[i]) / (2 * eps);
            }
          // compare block by block, each relative to its own size
          const unsigned int begin[4] = {0, n * dim, n * dim + n, N};
          for (unsigned int bi = 0; bi < 3; ++bi)
            for (unsigned int bj = 0; bj < 3; ++bj)
              {
                double diff = 0, size = 0;
                for (unsigned int i = begin[bi]; i < begin[bi + 1]; ++i)
                  for (unsigned int j = begin[bj]; j < begin[bj + 1]; ++j)
                    {
                      diff = std::max(diff, std::abs(K_family(i, j) - J(i, j)));
                      size = std::max(size, std::abs(J(i, j)));
                    }
                if (size > 0)
                  fd_error = std::max(fd_error, diff / size);
              }
          FullMatrix<double> KT(N, N);
          KT.copy_transposed(K_family);
          KT.add(-1., K_family);
          asymmetry = std::max(asymmetry, max_abs(KT) / max_abs(K_family));

          if (bubble)
            {
              // the equilibrium bubble, then a perturbed one as the iterate
              CondensedFieldIterate iterate;
              Vector<double>        r_iterate;
              FullMatrix<double>    K_iterate;
              assemble_nodal_pressure_family(table,
                                             state.y,
                                             state.p,
                                             state.vartheta,
                                             split,
                                             true,
                                             r_iterate,
                                             nullptr,
                                             &iterate);
              // again, now from the stored bubble (r_b = 0 up to round-off)
              assemble_nodal_pressure_family(table,
                                             state.y,
                                             state.p,
                                             state.vartheta,
                                             split,
                                             true,
                                             r_iterate,
                                             nullptr,
                                             &iterate);
              equilibrium_difference =
                std::max(equilibrium_difference,
                         (Vector<double>(r_iterate) -= r).linfty_norm() /
                           r.linfty_norm());
              const std::vector<double> u_b    = iterate.bubble;
              double                    before = 0;
              for (unsigned int i = 0; i < dim; ++i)
                {
                  iterate.bubble[i] += 0.01 * std::abs(u_b[i]) + 1e-3;
                  before =
                    std::max(before, std::abs(iterate.bubble[i] - u_b[i]));
                }
              assemble_nodal_pressure_family(table,
                                             state.y,
                                             state.p,
                                             state.vartheta,
                                             split,
                                             true,
                                             r_iterate,
                                             &K_iterate,
                                             &iterate);
              update_condensed_fields(iterate, std::vector<double>(N, 0.));
              double after = 0;
              for (unsigned int i = 0; i < dim; ++i)
                after = std::max(after, std::abs(iterate.bubble[i] - u_b[i]));
              local_contraction =
                std::max(local_contraction, after / (before * before));
            }

          // homogeneous deformation
          Tensor<2, dim> F;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              F[i][j] = (i == j ? 1.1 : 0.) + 0.05 * (i + 2 * j + 1) / dim;
          const double     J_F = determinant(F);
          FamilyState<dim> patch;
          patch.y.resize(n);
          for (unsigned int b = 0; b < n; ++b)
            patch.y[b] = F * X[b];
          patch.p.assign(n, split.volumetric_strain_energy_derivative(J_F));
          patch.vartheta.assign(n, J_F - 1.);
          CondensedFieldIterate patch_iterate;
          Vector<double>        r_patch;
          assemble_nodal_pressure_family(table,
                                         patch.y,
                                         patch.p,
                                         patch.vartheta,
                                         split,
                                         bubble,
                                         r_patch,
                                         nullptr,
                                         &patch_iterate);
          double volume = 0;
          for (const double w : table.weights)
            volume += w;
          for (unsigned int i = n * dim; i < N; ++i)
            patch_rows =
              std::max(patch_rows,
                       std::abs(r_patch[i]) /
                         (volume *
                          (i < n * dim + n ? 1. : std::abs(patch.p[0]))));
          if (bubble)
            for (const double b : patch_iterate.bubble)
              patch_bubble = std::max(patch_bubble, std::abs(b));
        }
      deallog << dim << "-D " << formulation.text << ":" << std::endl;
      deallog << "  tangent = central differences (relative, per block) "
              << (fd_error < 1e-5 ? "yes" : "NO") << std::endl;
      deallog << "  tangent symmetric " << (asymmetry < 1e-12 ? "yes" : "NO")
              << std::endl;
      if (bubble)
        {
          deallog << "  iterate at equilibrium gives the equilibrium residual "
                  << (equilibrium_difference < 1e-10 ? "yes" : "NO")
                  << std::endl;
          deallog << "  local update converges quadratically "
                  << (local_contraction < 100. ? "yes" : "NO") << std::endl;
        }
      deallog << "  homogeneous deformation: p and Theta rows vanish "
              << (patch_rows < 1e-12 ? "yes" : "NO");
      if (bubble)
        deallog << ", bubble vanishes "
                << (patch_bubble < 1e-12 ? "yes" : "NO");
      deallog << std::endl;
      if (fd_error >= 1e-5 || asymmetry >= 1e-12 || patch_rows >= 1e-12 ||
          (bubble && (equilibrium_difference >= 1e-10 ||
                      local_contraction >= 100. || patch_bubble >= 1e-12)))
        deallog << "  errors: " << fd_error << " " << asymmetry << " "
                << equilibrium_difference << " " << local_contraction << " "
                << patch_rows << " " << patch_bubble << std::endl;
    }
}



int
main()
{
  initlog();
  test<2>();
  test<3>();
}
