#include <pg/base/exceptions.h>
#include <pg/elements/second_order_correction.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <cmath>

namespace pg
{
  namespace
  {
    /**
     * d^k and D^k (see the header) of every particle for the factors
     * @p a1, @p a2 (empty: uncorrected).
     */
    template <int dim>
    void
    consistency_residuals(const ParticleSet<dim>            &particles,
                          const FamilySet<dim>              &families,
                          const FamilyElements<dim>         &elements,
                          const std::vector<Tensor<1, dim>> &a1,
                          const std::vector<Tensor<2, dim>> &a2,
                          std::vector<Tensor<1, dim>>       &d,
                          std::vector<Tensor<2, dim>>       &D)
    {
      const unsigned int n = particles.n_particles();
      d.assign(n, Tensor<1, dim>());
      D.assign(n, Tensor<2, dim>());
      for (unsigned int k = 0; k < n; ++k)
        {
          const auto  members = families.members(k);
          const auto  geom    = elements.geometry(k);
          const auto &g       = elements.master_gradients(k);
          const auto &phi     = elements.correction_function_values(k);
          D[k] +=
            particles.volume(k) * Tensor<2, dim>(unit_symmetric_tensor<dim>());
          for (unsigned int j = 1; j < members.size(); ++j)
            {
              Tensor<1, dim> t = g[j];
              if (!a1.empty())
                t += phi[j][0] * (a1[k] + a2[k] * geom.bonds[j]);
              const double w = geom.volumes[j];
              d[members[j]] += w * t;
              d[k] -= w * t;
              D[k] -= w * outer_product(geom.bonds[j], t);
            }
        }
    }



    /** The largest scaled residuals over the free particles. */
    template <int dim>
    std::pair<double, double>
    largest_residuals(const ParticleSet<dim>            &particles,
                      const std::vector<bool>           &fixed,
                      const std::vector<Tensor<1, dim>> &d,
                      const std::vector<Tensor<2, dim>> &D)
    {
      std::pair<double, double> result(0., 0.);
      for (unsigned int k = 0; k < particles.n_particles(); ++k)
        if (!fixed[k])
          {
            const double h = particles.spacing(k);
            result.first =
              std::max(result.first, d[k].norm() / std::pow(h, dim - 1));
            result.second =
              std::max(result.second, D[k].norm() / std::pow(h, dim));
          }
      return result;
    }
  } // namespace



  template <int dim>
  SecondOrderCorrection<dim>
  solve_second_order_correction(const ParticleSet<dim>    &particles,
                                const FamilySet<dim>      &families,
                                const FamilyElements<dim> &elements,
                                const std::vector<bool>   &fixed)
  {
    constexpr unsigned int m = dim + 1; // unknowns and equations per particle
    const unsigned int     n = particles.n_particles();
    AssertDimension(fixed.size(), n);
    SecondOrderCorrection<dim> result;

    std::vector<Tensor<1, dim>> d;
    std::vector<Tensor<2, dim>> D;
    consistency_residuals<dim>(particles, families, elements, {}, {}, d, D);
    std::tie(result.max_first_order_residual_before,
             result.max_second_order_residual_before) =
      largest_residuals(particles, fixed, d, D);

    // The entries of family k: the correction of t^{kj}, component J, is
    // phi^{kj} c^{kj} . beta^k_J with c = (1, dX^{kj}) and the unknowns
    // beta^k_J = (alpha_1J, alpha_2J1, ..., alpha_2Jd).
    const auto for_each_entry = [&](const auto &add) {
      for (unsigned int k = 0; k < n; ++k)
        {
          const auto  members = families.members(k);
          const auto  geom    = elements.geometry(k);
          const auto &phi     = elements.correction_function_values(k);
          for (unsigned int j = 1; j < members.size(); ++j)
            for (unsigned int s = 0; s < m; ++s)
              {
                const double c   = (s == 0 ? 1. : geom.bonds[j][s - 1]);
                const double val = geom.volumes[j] * phi[j][0] * c;
                add(members[j] * m, k * m + s, val);
                add(k * m, k * m + s, -val);
                for (unsigned int e = 0; e < dim; ++e)
                  add(k * m + 1 + e, k * m + s, -val * geom.bonds[j][e]);
              }
        }
    };

    DynamicSparsityPattern dsp(n * m, n * m);
    for (unsigned int row = 0; row < n * m; ++row)
      dsp.add(row, row);
    for_each_entry([&](const unsigned int row, const unsigned int col, double) {
      if (!fixed[row / m])
        dsp.add(row, col);
    });
    SparsityPattern pattern;
    pattern.copy_from(dsp);
    SparseMatrix<double> matrix(pattern);
    for_each_entry(
      [&](const unsigned int row, const unsigned int col, const double value) {
        if (!fixed[row / m])
          matrix.add(row, col, value);
      });
    for (unsigned int k = 0; k < n; ++k)
      if (fixed[k])
        for (unsigned int s = 0; s < m; ++s)
          matrix.set(k * m + s, k * m + s, 1.);

    SparseDirectUMFPACK solver;
    try
      {
        solver.initialize(matrix);
      }
    catch (...)
      {
        AssertThrow(false,
                    ExcMessage(
                      "The VC2 system is singular: a family has too few "
                      "neighbours for the second-order correction, or every "
                      "particle is fixed. Increase 'Horizon factor' in "
                      "subsection 'Discretization'."));
      }

    result.alpha.assign(n, Tensor<1, dim>());
    result.second_order_alpha.assign(n, Tensor<2, dim>());
    Vector<double> x(n * m);
    for (unsigned int J = 0; J < dim; ++J)
      {
        for (unsigned int k = 0; k < n; ++k)
          for (unsigned int s = 0; s < m; ++s)
            x(k * m + s) = fixed[k] ? 0. : -(s == 0 ? d[k][J] : D[k][s - 1][J]);
        solver.solve(x);
        for (unsigned int k = 0; k < n; ++k)
          {
            result.alpha[k][J] = x(k * m);
            for (unsigned int e = 0; e < dim; ++e)
              result.second_order_alpha[k][J][e] = x(k * m + 1 + e);
          }
      }
    for (unsigned int k = 0; k < n; ++k)
      AssertThrow(std::isfinite(result.alpha[k].norm()) &&
                    std::isfinite(result.second_order_alpha[k].norm()),
                  ExcMessage("The VC2 system is singular: increase 'Horizon "
                             "factor' in subsection 'Discretization'."));

    consistency_residuals<dim>(particles,
                               families,
                               elements,
                               result.alpha,
                               result.second_order_alpha,
                               d,
                               D);
    std::tie(result.max_first_order_residual_after,
             result.max_second_order_residual_after) =
      largest_residuals(particles, fixed, d, D);
    return result;
  }



  template SecondOrderCorrection<2>
  solve_second_order_correction<2>(const ParticleSet<2> &,
                                   const FamilySet<2> &,
                                   const FamilyElements<2> &,
                                   const std::vector<bool> &);
  template SecondOrderCorrection<3>
  solve_second_order_correction<3>(const ParticleSet<3> &,
                                   const FamilySet<3> &,
                                   const FamilyElements<3> &,
                                   const std::vector<bool> &);
} // namespace pg
