#ifndef pg_solvers_time_integration_h
#define pg_solvers_time_integration_h

#include <pg/base/global.h>
#include <pg/base/linear_algebra.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <optional>
#include <vector>

namespace pg
{
  /**
   * Pieces of the explicit and implicit time integrators of Problem
   * ('Time/Integrator'): the stable time step estimate, the energy
   * bookkeeping and the disorder indicator of a particle set.
   */
  namespace TimeIntegration
  {
    /**
     * The largest eigenvalue omega_max^2 of M^-1 K for the diagonal mass
     * M, by power iteration: x <- M^-1 K x, normalised in the M norm, with
     * the estimate |M^-1 K x|_M / |x|_M (for symmetric K a lower bound
     * that converges to omega_max^2 from below, never above the Rayleigh
     * quotient's limit). @p inverse_mass is 1/m_i at the free DoFs and 0
     * at constrained ones (they are kept at zero). The start vector is a
     * fixed pseudo-random function of the global DoF index, so the result
     * does not depend on the number of MPI ranks. Stops when the estimate
     * changes by less than @p tolerance (relative) between two iterations,
     * or after @p max_iterations.
     */
    double
    largest_eigenvalue(const LinearAlgebra::SparseMatrix &K,
                       const LinearAlgebra::Vector       &inverse_mass,
                       const unsigned int                 max_iterations = 2000,
                       const double                       tolerance = 1e-6);

    /**
     * The energy account of a dynamic run, every work accumulated with
     * the trapezoidal rule over the steps, e.g. for the internal forces
     * W_int += 1/2 (f_int^n + f_int^{n+1}) . (u^{n+1} - u^n). This is
     * defined for every formulation, including the non-variational PPG
     * ones that have no strain energy. For a hyperelastic variational
     * formulation W_int approximates the stored energy.
     */
    struct Energies
    {
      /** 1/2 v . M v at the current step. */
      double kinetic = 0;
      /** At the initial step. */
      double initial_kinetic = 0;
      double internal_work   = 0;
      /** Body forces and tractions. */
      double external_work = 0;
      /** Work of the reactions at the constrained DoFs. */
      double support_work = 0;
      /**
       * The plastic work, the integral of the committed state's
       * Material::plastic_work_density() over the body (not the trapezoidal
       * rule; part of internal_work, which also holds the stored elastic
       * energy); nothing for a material that does not dissipate. Updated
       * at the output times.
       */
      std::optional<double> plastic_work;

      /**
       * E_kin - E_kin(0) + W_int - W_ext - W_supports: zero for exact
       * energy conservation.
       */
      double
      balance() const
      {
        return kinetic - initial_kinetic + internal_work - external_work -
               support_work;
      }
    };

    /**
     * The disorder indicator of a particle displacement field @p u at the
     * reference positions @p X with volumes @p V: the volume-weighted RMS
     * over the particles k of the deviation of u^k from the linear
     * least-squares fit u ~ a + A (X - X^k) to the displacements of its
     * @p neighbours (without k itself), evaluated at X^k,
     *   sqrt( sum_k V^k |u^k - a^k|^2 / sum_k V^k ).
     * A smooth field gives O(h^2 |grad grad u|) (zero for a linear one),
     * whatever its wave length beyond a few spacings; particle-scale
     * patterns (hourglass, zero-energy modes, pairing) give the full
     * amplitude of the pattern. Particles with fewer than dim + 1
     * neighbours, or with neighbours on a line (plane), are skipped.
     * Callers divide it by a reference amplitude (Problem: the RMS of the
     * initial displacement about its mean).
     */
    template <int dim>
    double
    local_fit_deviation(
      const std::vector<Point<dim>>                &X,
      const std::vector<Tensor<1, dim>>            &u,
      const std::vector<double>                    &V,
      const std::vector<std::vector<unsigned int>> &neighbours);

    /**
     * The volume-weighted RMS of @p u about its mean,
     * sqrt( sum_k V^k |u^k - mean u|^2 / sum_k V^k ).
     */
    template <int dim>
    double
    rms_about_mean(const std::vector<Tensor<1, dim>> &u,
                   const std::vector<double>         &V);
  } // namespace TimeIntegration
} // namespace pg

#endif
