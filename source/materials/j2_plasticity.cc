#include <pg/base/exceptions.h>
#include <pg/materials/j2_plasticity.h>
#include <pg/materials/j2_update.h>
#include <pg/materials/material_registry.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace pg
{
  namespace Materials
  {
    // A named namespace: the unity build may compile this file together
    // with other materials' helpers (J2 also holds the local update of
    // j2_update.h).
    namespace J2
    {
      /** The name in error messages. */
      constexpr const char *model_name = "J2 plasticity";

      /** @p x with 6 significant digits, for messages. */
      inline std::string
      short_number(const double x)
      {
        std::ostringstream s;
        s << x;
        return s.str();
      }

      /** C_p^{-1} of the state (3x3). */
      Matrix3<double>
      inverse_plastic_strain(const ArrayView<const double> &state)
      {
        return symmetric_matrix(state.data());
      }
    } // namespace J2



    template <int dim>
    J2Plasticity<dim>::J2Plasticity(const Parameters::Material &parameters)
      : JacobianVolumetricSplit<dim>(parameters.lambda() +
                                       2. / 3. * parameters.mu(),
                                     J2::model_name)
      , kappa(parameters.lambda() + 2. / 3. * parameters.mu())
      , mu(parameters.mu())
      , initial_yield_stress(parameters.initial_yield_stress)
      , saturation_yield_stress(parameters.saturation_yield_stress)
      , hardening_modulus(parameters.linear_hardening_modulus)
      , saturation_exponent(parameters.saturation_exponent)
    {
      AssertThrow(dim == 3 || parameters.plane == "strain",
                  ExcBadParameter("Material/Plane",
                                  parameters.plane,
                                  "plane stress is not available for 'Model "
                                  "= J2 plasticity' (its plastic state is "
                                  "3-D); use 'Plane = strain' or a 3-D "
                                  "model."));
      AssertThrow(initial_yield_stress > 0. &&
                    std::isfinite(initial_yield_stress),
                  ExcBadParameter("Material/Initial yield stress",
                                  J2::short_number(initial_yield_stress),
                                  "the initial yield stress sigma_y0 of 'Model "
                                  "= J2 plasticity' must be positive (force "
                                  "per area)."));
      AssertThrow(
        saturation_yield_stress >= initial_yield_stress &&
          std::isfinite(saturation_yield_stress),
        ExcBadParameter("Material/Saturation yield stress",
                        J2::short_number(saturation_yield_stress),
                        "the saturation yield stress sigma_yinf of 'Model = J2 "
                        "plasticity' must not be smaller than 'Initial yield "
                        "stress' (" +
                          J2::short_number(initial_yield_stress) +
                          "): the hardening would soften. Set it equal to the "
                          "initial yield stress for no saturation hardening."));
      AssertThrow(hardening_modulus >= 0. && std::isfinite(hardening_modulus),
                  ExcBadParameter("Material/Linear hardening modulus",
                                  J2::short_number(hardening_modulus),
                                  "the linear hardening modulus H of 'Model = "
                                  "J2 plasticity' must be zero (no linear "
                                  "hardening) or positive (force per area)."));
      AssertThrow(saturation_exponent >= 0. &&
                    std::isfinite(saturation_exponent),
                  ExcBadParameter("Material/Saturation exponent",
                                  J2::short_number(saturation_exponent),
                                  "the saturation exponent delta of 'Model = "
                                  "J2 plasticity' must be zero (no saturation "
                                  "hardening) or positive (dimensionless)."));
    }



    template <int dim>
    bool
    J2Plasticity<dim>::tangent_has_major_symmetry() const
    {
      return true;
    }



    template <int dim>
    unsigned int
    J2Plasticity<dim>::n_state_variables() const
    {
      return n_state;
    }



    template <int dim>
    void
    J2Plasticity<dim>::initialize_state(const ArrayView<double> &state) const
    {
      AssertDimension(state.size(), n_state);
      for (unsigned int i = 0; i < n_state; ++i)
        state[i] = (i < 3 ? 1. : 0.);
    }



    template <int dim>
    void
    J2Plasticity<dim>::evaluate_part(
      const Tensor<2, dim>          &F,
      const ArrayView<const double> &committed_state,
      const ArrayView<double>       &trial_state,
      const bool                     with_volumetric_part,
      Tensor<2, dim>                &P,
      Tensor<4, dim>                *A) const
    {
      using namespace J2;
      using AD = TangentAD<dim>;
      AssertDimension(committed_state.size(), n_state);
      AssertDimension(trial_state.size(), n_state);

      const Constants       c{mu,
                        kappa,
                        initial_yield_stress,
                        saturation_yield_stress,
                        hardening_modulus,
                        saturation_exponent};
      const double          J         = checked_jacobian(F, model_name);
      const double          alpha_n   = committed_state[alpha_index];
      const Matrix3<double> C_p_inv_n = inverse_plastic_strain(committed_state);
      const Matrix3<double> F3        = embed(F);
      const Matrix3<double> b_e_trial =
        multiply(multiply(F3, C_p_inv_n), transpose(F3));

      // The elastic predictor (with a margin of round-off, so that a state
      // on the yield surface does not flow under the same F).
      const double sigma_y = c.yield_stress(alpha_n);
      const bool   plastic =
        von_mises(isochoric_kirchhoff_stress(c, b_e_trial, J)) - sigma_y >
        1e-12 * sigma_y;

      // The converged b_e, Delta alpha; P and A.
      Matrix3<double> b_e;
      double          dalpha = 0.;
      if (!plastic)
        {
          b_e = b_e_trial;
          if (A != nullptr)
            {
              const Matrix3<AD> F_ad = embed_ad(F);
              const AD          J_ad = determinant(F_ad);
              const Matrix3<AD> b_ad =
                multiply(multiply(F_ad, C_p_inv_n), transpose(F_ad));
              const Matrix3<AD> P_ad =
                piola_stress(c, b_ad, F_ad, J_ad, with_volumetric_part);
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int b = 0; b < dim; ++b)
                  {
                    P[a][b] = P_ad[a][b].val();
                    for (unsigned int k = 0; k < dim; ++k)
                      for (unsigned int d = 0; d < dim; ++d)
                        (*A)[a][b][k][d] = P_ad[a][b].dx(k * dim + d);
                  }
            }
          else
            {
              const Matrix3<double> P3 =
                piola_stress(c, b_e, F3, J, with_volumetric_part);
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int b = 0; b < dim; ++b)
                  P[a][b] = P3[a][b];
            }
        }
      else
        {
          const LocalSolution solution = solve_update(c, b_e_trial, J, alpha_n);
          if (A != nullptr)
            {
              // x(F) = x* - (dR/dx)^{-1} R(x*, F) in AD numbers: its
              // derivatives are dx/dF (eq. 4.62), and P(x(F), F) has
              // dP/dF = A.
              const Matrix3<AD> F_ad = embed_ad(F);
              const AD          J_ad = determinant(F_ad);
              const Matrix3<AD> b_trial_ad =
                multiply(multiply(F_ad, C_p_inv_n), transpose(F_ad));
              const std::array<AD, n_unknowns> x_ad =
                corrected_unknowns<AD>(c, solution, b_trial_ad, J_ad, alpha_n);
              const Matrix3<AD> b_ad = symmetric_matrix(x_ad.data());
              const Matrix3<AD> P_ad =
                piola_stress(c, b_ad, F_ad, J_ad, with_volumetric_part);
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int b = 0; b < dim; ++b)
                  {
                    P[a][b] = P_ad[a][b].val();
                    for (unsigned int k = 0; k < dim; ++k)
                      for (unsigned int d = 0; d < dim; ++d)
                        (*A)[a][b][k][d] = P_ad[a][b].dx(k * dim + d);
                  }
              for (unsigned int i = 0; i < 6; ++i)
                b_e[voigt_row[i]][voigt_column[i]] =
                  b_e[voigt_column[i]][voigt_row[i]] = x_ad[i].val();
              dalpha = x_ad[6].val();
            }
          else
            {
              const std::array<double, n_unknowns> x =
                corrected_unknowns<double>(c, solution, b_e_trial, J, alpha_n);
              b_e    = symmetric_matrix(x.data());
              dalpha = x[6];
              const Matrix3<double> P3 =
                piola_stress(c, b_e, F3, J, with_volumetric_part);
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int b = 0; b < dim; ++b)
                  P[a][b] = P3[a][b];
            }
        }

      // The trial state: C_p^{-1} = F^{-1} b_e F^{-T}, alpha, the flag.
      if (plastic)
        {
          const Matrix3<double> F_inv = invert(F3);
          const Matrix3<double> C_p_inv =
            multiply(multiply(F_inv, b_e), transpose(F_inv));
          for (unsigned int i = 0; i < 6; ++i)
            trial_state[i] = 0.5 * (C_p_inv[voigt_row[i]][voigt_column[i]] +
                                    C_p_inv[voigt_column[i]][voigt_row[i]]);
          // (In plane strain C_p^{-1}_13 = C_p^{-1}_23 = 0 exactly.)
          if (dim == 2)
            trial_state[4] = trial_state[5] = 0.;
        }
      else
        for (unsigned int i = 0; i < 6; ++i)
          trial_state[i] = committed_state[i];
      trial_state[alpha_index]      = alpha_n + dalpha;
      trial_state[yield_flag_index] = plastic ? 1. : 0.;
    }



    template <int dim>
    void
    J2Plasticity<dim>::evaluate_with_state(
      const Tensor<2, dim>          &F,
      const ArrayView<const double> &committed_state,
      const ArrayView<double>       &trial_state,
      Tensor<2, dim>                &P,
      Tensor<4, dim>                *A) const
    {
      evaluate_part(F, committed_state, trial_state, true, P, A);
    }



    template <int dim>
    void
    J2Plasticity<dim>::evaluate_isochoric_with_state(
      const Tensor<2, dim>          &F,
      const ArrayView<const double> &committed_state,
      const ArrayView<double>       &trial_state,
      Tensor<2, dim>                &P_iso,
      Tensor<4, dim>                *A_iso) const
    {
      evaluate_part(F, committed_state, trial_state, false, P_iso, A_iso);
    }



    template <int dim>
    Tensor<2, 3>
    J2Plasticity<dim>::cauchy_stress_with_state(
      const Tensor<2, dim>          &F,
      const ArrayView<const double> &state) const
    {
      using namespace J2;
      AssertDimension(state.size(), n_state);
      const Constants       c{mu, kappa, 0., 0., 0., 0.};
      const double          J  = checked_jacobian(F, model_name);
      const Matrix3<double> F3 = embed(F);
      const Matrix3<double> b_e =
        multiply(multiply(F3, inverse_plastic_strain(state)), transpose(F3));
      const Matrix3<double> tau = isochoric_kirchhoff_stress(c, b_e, J);
      const double          p   = 0.5 * kappa * (J * J - 1.);
      Tensor<2, 3>          sigma;
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = 0; b < 3; ++b)
          sigma[a][b] = (tau[a][b] + (a == b ? p : 0.)) / J;
      return sigma;
    }



    template <int dim>
    double
    J2Plasticity<dim>::yield_function(
      const Tensor<2, dim>          &F,
      const ArrayView<const double> &state) const
    {
      using namespace J2;
      AssertDimension(state.size(), n_state);
      const Constants       c{mu, kappa, 0., 0., 0., 0.};
      const double          J  = checked_jacobian(F, model_name);
      const Matrix3<double> F3 = embed(F);
      const Matrix3<double> b_e =
        multiply(multiply(F3, inverse_plastic_strain(state)), transpose(F3));
      return von_mises(isochoric_kirchhoff_stress(c, b_e, J)) -
             yield_stress(state[alpha_index]);
    }



    template <int dim>
    std::vector<std::string>
    J2Plasticity<dim>::state_output_names() const
    {
      return {"equivalent_plastic_strain", "yield_state"};
    }



    template <int dim>
    void
    J2Plasticity<dim>::state_outputs(const ArrayView<const double> &state,
                                     const ArrayView<double> &values) const
    {
      AssertDimension(state.size(), n_state);
      AssertDimension(values.size(), 2);
      values[0] = state[alpha_index];
      values[1] = state[yield_flag_index];
    }



    template <int dim>
    bool
    J2Plasticity<dim>::is_dissipative() const
    {
      return true;
    }



    template <int dim>
    double
    J2Plasticity<dim>::plastic_work_density(
      const ArrayView<const double> &state) const
    {
      AssertDimension(state.size(), n_state);
      const double a = state[alpha_index];
      const double saturation =
        saturation_exponent > 0 ?
          a - (1. - std::exp(-saturation_exponent * a)) / saturation_exponent :
          0.;
      return initial_yield_stress * a + 0.5 * hardening_modulus * a * a +
             (saturation_yield_stress - initial_yield_stress) * saturation;
    }



    template <int dim>
    void
    J2Plasticity<dim>::evaluate(const Tensor<2, dim> &F,
                                Tensor<2, dim>       &P,
                                Tensor<4, dim>       &A) const
    {
      std::array<double, n_state> initial, trial;
      initialize_state(ArrayView<double>(initial.data(), n_state));
      evaluate_part(F,
                    ArrayView<const double>(initial.data(), n_state),
                    ArrayView<double>(trial.data(), n_state),
                    true,
                    P,
                    &A);
    }



    template <int dim>
    Tensor<2, dim>
    J2Plasticity<dim>::first_piola_stress(const Tensor<2, dim> &F) const
    {
      std::array<double, n_state> initial, trial;
      initialize_state(ArrayView<double>(initial.data(), n_state));
      Tensor<2, dim> P;
      evaluate_part(F,
                    ArrayView<const double>(initial.data(), n_state),
                    ArrayView<double>(trial.data(), n_state),
                    true,
                    P,
                    nullptr);
      return P;
    }



    template <int dim>
    Tensor<2, 3>
    J2Plasticity<dim>::cauchy_stress(const Tensor<2, dim> &F) const
    {
      std::array<double, n_state> initial, trial;
      initialize_state(ArrayView<double>(initial.data(), n_state));
      Tensor<2, dim> P;
      evaluate_part(F,
                    ArrayView<const double>(initial.data(), n_state),
                    ArrayView<double>(trial.data(), n_state),
                    true,
                    P,
                    nullptr);
      return cauchy_stress_with_state(F,
                                      ArrayView<const double>(trial.data(),
                                                              n_state));
    }



    template <int dim>
    double
    J2Plasticity<dim>::strain_energy_density(const Tensor<2, dim> &F) const
    {
      return isochoric_strain_energy_density(F) +
             this->volumetric_strain_energy_density(
               checked_jacobian(F, J2::model_name));
    }



    template <int dim>
    double
    J2Plasticity<dim>::isochoric_strain_energy_density(
      const Tensor<2, dim> &F) const
    {
      using namespace J2;
      std::array<double, n_state> initial, trial;
      initialize_state(ArrayView<double>(initial.data(), n_state));
      Tensor<2, dim> P;
      evaluate_part(F,
                    ArrayView<const double>(initial.data(), n_state),
                    ArrayView<double>(trial.data(), n_state),
                    false,
                    P,
                    nullptr);
      const double          J  = checked_jacobian(F, model_name);
      const Matrix3<double> F3 = embed(F);
      const Matrix3<double> b_e =
        multiply(multiply(F3, symmetric_matrix(trial.data())), transpose(F3));
      return 0.5 * mu * (std::pow(J, -2. / 3.) * trace(b_e) - 3.);
    }



    template <int dim>
    Tensor<2, dim>
    J2Plasticity<dim>::isochoric_first_piola_stress(
      const Tensor<2, dim> &F) const
    {
      std::array<double, n_state> initial, trial;
      initialize_state(ArrayView<double>(initial.data(), n_state));
      Tensor<2, dim> P_iso;
      evaluate_part(F,
                    ArrayView<const double>(initial.data(), n_state),
                    ArrayView<double>(trial.data(), n_state),
                    false,
                    P_iso,
                    nullptr);
      return P_iso;
    }



    template <int dim>
    void
    J2Plasticity<dim>::evaluate_isochoric(const Tensor<2, dim> &F,
                                          Tensor<2, dim>       &P_iso,
                                          Tensor<4, dim>       &A_iso) const
    {
      std::array<double, n_state> initial, trial;
      initialize_state(ArrayView<double>(initial.data(), n_state));
      evaluate_part(F,
                    ArrayView<const double>(initial.data(), n_state),
                    ArrayView<double>(trial.data(), n_state),
                    false,
                    P_iso,
                    &A_iso);
    }



    template <int dim>
    double
    J2Plasticity<dim>::yield_stress(const double alpha) const
    {
      return initial_yield_stress + hardening_modulus * alpha +
             (saturation_yield_stress - initial_yield_stress) *
               (1. - std::exp(-saturation_exponent * alpha));
    }



    template <int dim>
    double
    J2Plasticity<dim>::bulk_modulus() const
    {
      return kappa;
    }



    template <int dim>
    double
    J2Plasticity<dim>::shear_modulus() const
    {
      return mu;
    }



    template class J2Plasticity<2>;
    template class J2Plasticity<3>;

    // Listed after the elastic models (10-40).
    PG_REGISTER_MATERIAL(J2Plasticity,
                         "J2 plasticity",
                         "finite von Mises plasticity, F = Fe Fp, with "
                         "nonlinear isotropic hardening, eqs. 2.46-2.54, "
                         "4.41",
                         50)
  } // namespace Materials
} // namespace pg
