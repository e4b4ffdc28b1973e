#ifndef pg_materials_j2_plasticity_h
#define pg_materials_j2_plasticity_h

#include <pg/materials/jacobian_volumetric_split.h>
#include <pg/materials/material.h>

#include <array>
#include <string>
#include <vector>

namespace pg
{
  namespace Materials
  {
    /**
     * Finite J2 (von Mises) elasto-plasticity with nonlinear isotropic
     * hardening, dissertation §2.3.2 and §4.4.2, eqs. (2.46)-(2.54), (4.41),
     * (4.42), (4.62); pg-methods.md §3.4 and §13.3. `Model = J2 plasticity`
     * in subsection `Material`.
     *
     * <b>Model.</b> F = F_e F_p, plastic flow isochoric (det F_p = 1, so
     * J_e = J = det F). The elastic energy (2.46), per reference volume,
     * @f[ W = \frac{\mu}{2} (\mathrm{tr}\, \bar b_e - 3)
     *       + \frac{K}{4} (J^2 - 1 - 2 \ln J), \qquad
     *     b_e = F C_p^{-1} F^T, \quad \bar b_e = J^{-2/3} b_e, @f]
     * gives the Kirchhoff stress and, at fixed C_p^{-1}, the first
     * Piola-Kirchhoff stress of the global weak form (2.48):
     * @f[ \tau = \underbrace{\mu\, \mathrm{dev}\, \bar b_e}_{\tau_{iso}}
     *       + \underbrace{\tfrac{K}{2} (J^2 - 1)\, 1}_{\tau_{vol}}, \qquad
     *     P = \tau F^{-T} = P_{iso} + P_{vol}. @f]
     * The von Mises yield function (2.49), (2.50) on the Kirchhoff stress:
     * @f[ f = \sigma_{vM}(\tau) - \sigma_y(\alpha), \quad
     *     \sigma_{vM} = \sqrt{\tfrac32\, \mathrm{dev}\tau : \mathrm{dev}\tau},
     *     \quad \sigma_y(\alpha) = \sigma_{y0} + H \alpha
     *       + (\sigma_{y\infty} - \sigma_{y0}) (1 - e^{-\delta \alpha}), @f]
     * with the equivalent plastic strain alpha (the hardening variable).
     * Associative flow (2.51), (2.52) without plastic spin:
     * n = 3/2 dev tau / sigma_vM, d/dt C_p^{-1} = -2 lambda' F^{-1} n F
     * C_p^{-1}, d/dt alpha = lambda'.
     *
     * <b>Update (4.41).</b> If the elastic predictor (C_p^{-1} = C_{p,n}^{-1},
     * alpha = alpha_n) gives f > 1e-12 sigma_y(alpha_n) (the margin keeps a
     * state on the yield surface from flowing again under the same F),
     * solve
     * @f[ C_p^{-1} = F^{-1} \exp(-2 \Delta\alpha\, n) F C_{p,n}^{-1}, \qquad
     *     f(\tau, \alpha_n + \Delta\alpha) = 0. @f]
     * <em>Rebuilt sign:</em> the dissertation prints the exponent as
     * "2 Delta alpha n"; the minus sign follows from integrating (2.52)
     * exponentially, and with + the yield function grows with Delta alpha
     * (pg-methods §3.4). Multiplied by F from the left and F^T from the
     * right, (4.41) is b_e = exp(-2 Delta alpha n) b_e^tr with
     * b_e^tr = F C_{p,n}^{-1} F^T; n is a function of b_e, so n, b_e and
     * b_e^tr are coaxial and this equals the symmetric form
     * @f[ R_1 = b_e - \exp(-\Delta\alpha\, n)\, b_e^{tr}\, \exp(-\Delta\alpha\,
     *     n) = 0, \qquad R_2 = [\sigma_{vM}(b_e) - \sigma_y(\alpha_n +
     *     \Delta\alpha)] / \mu = 0, @f]
     * which pg solves by Newton's method for the seven unknowns
     * x = (b_e, Delta alpha) (local Jacobian (4.42) by forward AD, Sacado),
     * starting from (b_e^tr, 0), with a backtracking line search; then
     * C_p^{-1} = F^{-1} b_e F^{-T}. The exponential is a scaling-and-squaring
     * Taylor series (SmallMatrix::exponential), so repeated principal
     * stretches (uniaxial states) need no special case. tr n = 0 keeps
     * det C_p^{-1} = 1. Since only dev tau enters f and the flow, the
     * volumetric response stays elastic.
     *
     * <b>Tangent (4.62).</b> A = dP/dF at fixed committed state is the
     * consistent algorithmic tangent dP/dF|_x + dP/dx dx/dF with
     * dx/dF = -(dR/dx)^{-1} dR/dF at the converged x*. pg evaluates one more
     * Newton correction in AD numbers whose derivatives are those with
     * respect to F: x(F) = x* - (dR/dx)^{-1} R(x*, F), which has the value
     * x* (to round-off: it is one more Newton step) and the exact
     * derivative dx/dF, and then P(x(F), F). In the elastic range
     * A = dP/dF at fixed C_{p,n}^{-1}. The algorithmic tangent is
     * major-symmetric, A_ABCD = A_CDAB (tangent_has_major_symmetry() is
     * true): in principal logarithmic elastic strains eps_a the update is
     * the closest-point projection eps = eps^tr - Delta alpha n with
     * tau_a = dW/d eps_a of the isotropic W, which has an incremental
     * potential; the tests measure |A_ABCD - A_CDAB| <= 2e-15 max |A| in
     * plastic steps (tests/materials/j2_plasticity_01).
     *
     * <b>State</b> (n_state_variables() = 8 per evaluation point, also in
     * 2-D): [C_p^{-1}_11, C_p^{-1}_22, C_p^{-1}_33, C_p^{-1}_12,
     * C_p^{-1}_13, C_p^{-1}_23, alpha, yield flag]; initially
     * [1, 1, 1, 0, 0, 0, 0, 0]. The yield flag is 1 if the step that
     * produced the state was plastic (Delta alpha > 0), else 0. C_p^{-1} and
     * alpha are dimensionless. Outputs (state_output_names()):
     * "equivalent_plastic_strain" (alpha) and "yield_state" (the flag).
     *
     * <b>Parameters</b> (entries of subsection `Material`): the elastic
     * constants from `Young's modulus`/`Poisson's ratio` or `Bulk
     * modulus`/`Shear modulus` (mu and K = lambda + 2/3 mu), `Initial yield
     * stress` sigma_y0 > 0, `Saturation yield stress` sigma_yinf >=
     * sigma_y0, `Linear hardening modulus` H >= 0 (force per area each) and
     * `Saturation exponent` delta >= 0 (dimensionless). The constructor
     * refuses other values, and 2-D plane stress, with a message naming the
     * entry.
     *
     * <b>2-D</b>: plane strain only (F_33 = 1); the state and the update
     * are 3-D (C_p^{-1}_13 = C_p^{-1}_23 = 0 stay zero), P and A are the
     * in-plane parts, and the Cauchy stress includes sigma_33.
     *
     * <b>Stateless functions</b> (evaluate(), first_piola_stress(),
     * cauchy_stress(), strain_energy_density() and the isochoric ones):
     * one step from the initial state, as the Material contract says; at
     * stresses below the yield stress they are the isochoric-volumetric
     * neo-Hooke. Beyond it W is the elastic energy at the updated state,
     * not a potential of P.
     *
     * <b>VolumetricSplit.</b> W_vol(Theta) = K/4 (Theta^2 - 1 - 2 ln Theta)
     * (theta = J), and evaluate_isochoric_with_state() returns
     * P_iso = tau_iso F^{-T} and A_iso = dP_iso/dF with the same update (it
     * does not depend on the pressure), so that P_iso + P_vol(J) and
     * A_iso + A_vol(J) are P and A of evaluate_with_state().
     *
     * Every function of F throws if J <= 0; the update throws with advice
     * if the local Newton iteration does not converge.
     */
    template <int dim>
    class J2Plasticity : public Material<dim>,
                         public JacobianVolumetricSplit<dim>
    {
    public:
      /** Number of state variables per evaluation point. */
      static constexpr unsigned int n_state = 8;
      /** Position of alpha in the state. */
      static constexpr unsigned int alpha_index = 6;
      /** Position of the yield flag in the state. */
      static constexpr unsigned int yield_flag_index = 7;

      /**
       * Store the moduli and hardening parameters of @p parameters; throws
       * ExcBadParameter for plane stress and for hardening parameters out
       * of range.
       */
      J2Plasticity(const Parameters::Material &parameters);

      /** The algorithmic tangent is major-symmetric (class doc). */
      bool
      tangent_has_major_symmetry() const final;

      /** @name State */
      /** @{ */
      unsigned int
      n_state_variables() const final;

      /** C_p^{-1} = 1, alpha = 0, flag 0. */
      void
      initialize_state(const ArrayView<double> &state) const final;

      /**
       * The update (4.41) from @p committed_state at @p F, the stress P and,
       * unless @p A is nullptr, the algorithmic tangent (4.62); writes the
       * whole @p trial_state.
       */
      void
      evaluate_with_state(const Tensor<2, dim>          &F,
                          const ArrayView<const double> &committed_state,
                          const ArrayView<double>       &trial_state,
                          Tensor<2, dim>                &P,
                          Tensor<4, dim>                *A) const final;

      /** sigma = tau(F C_p^{-1} F^T) / J of @p state, 3x3 (no update). */
      Tensor<2, 3>
      cauchy_stress_with_state(
        const Tensor<2, dim>          &F,
        const ArrayView<const double> &state) const final;

      /** "equivalent_plastic_strain", "yield_state". */
      std::vector<std::string>
      state_output_names() const final;

      void
      state_outputs(const ArrayView<const double> &state,
                    const ArrayView<double>       &values) const final;

      /** True. */
      bool
      is_dissipative() const final;

      /**
       * int_0^alpha sigma_y(a) da = sigma_y0 alpha + H alpha^2 / 2 +
       * (sigma_y_inf - sigma_y0) (alpha - (1 - exp(-delta alpha)) / delta)
       * (eq. 2.49 integrated; the last term is 0 for delta = 0): the
       * dissipation tau : d_p = sigma_y(alpha) d alpha / dt of the flow
       * rule on the yield surface, integrated over the history.
       */
      double
      plastic_work_density(const ArrayView<const double> &state) const final;
      /** @} */

      /** @name Stateless: one step from the initial state */
      /** @{ */
      void
      evaluate(const Tensor<2, dim> &F,
               Tensor<2, dim>       &P,
               Tensor<4, dim>       &A) const final;

      Tensor<2, dim>
      first_piola_stress(const Tensor<2, dim> &F) const final;

      Tensor<2, 3>
      cauchy_stress(const Tensor<2, dim> &F) const final;

      double
      strain_energy_density(const Tensor<2, dim> &F) const final;
      /** @} */

      /** @name The split, for the mixed formulations */
      /** @{ */

      /**
       * P_iso = mu dev(bbar_e) F^{-T} and, unless @p A_iso is nullptr,
       * A_iso = dP_iso/dF, with the update of evaluate_with_state().
       */
      void
      evaluate_isochoric_with_state(
        const Tensor<2, dim>          &F,
        const ArrayView<const double> &committed_state,
        const ArrayView<double>       &trial_state,
        Tensor<2, dim>                &P_iso,
        Tensor<4, dim>                *A_iso) const final;

      /** mu/2 (tr bbar_e - 3), one step from the initial state. */
      double
      isochoric_strain_energy_density(const Tensor<2, dim> &F) const final;

      Tensor<2, dim>
      isochoric_first_piola_stress(const Tensor<2, dim> &F) const final;

      void
      evaluate_isochoric(const Tensor<2, dim> &F,
                         Tensor<2, dim>       &P_iso,
                         Tensor<4, dim>       &A_iso) const final;

      // theta = J and W_vol: JacobianVolumetricSplit.
      /** @} */

      /** sigma_y(alpha), force per area. */
      double
      yield_stress(const double alpha) const;

      /**
       * The yield function f = sigma_vM(tau) - sigma_y(alpha) of @p state
       * at @p F (no update), force per area.
       */
      double
      yield_function(const Tensor<2, dim>          &F,
                     const ArrayView<const double> &state) const;

      /** The bulk modulus K = lambda + 2/3 mu. */
      double
      bulk_modulus() const;

      /** The shear modulus mu. */
      double
      shear_modulus() const;

    private:
      /** The update and stress with or without the volumetric part. */
      void
      evaluate_part(const Tensor<2, dim>          &F,
                    const ArrayView<const double> &committed_state,
                    const ArrayView<double>       &trial_state,
                    const bool                     with_volumetric_part,
                    Tensor<2, dim>                &P,
                    Tensor<4, dim>                *A) const;

      /** Bulk modulus K. */
      const double kappa;
      /** Shear modulus mu. */
      const double mu;
      /** sigma_y0, sigma_yinf, H (force per area), delta. */
      const double initial_yield_stress;
      const double saturation_yield_stress;
      const double hardening_modulus;
      const double saturation_exponent;
    };
  } // namespace Materials
} // namespace pg

#endif
