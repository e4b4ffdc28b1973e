#ifndef pg_tests_history_stateful_split_material_h
#define pg_tests_history_stateful_split_material_h

// A test material with history that offers the volumetric split, so that
// the mixed formulations (UnlP0, U2P1, U2P1C, Unl+P1C, Q1P0/H1P0, IUnlP0)
// can carry it: 'isochoric damage neo-Hooke', the isochoric-volumetric
// neo-Hooke model whose isochoric part is degraded by a damage d(kappa),
//   W = (1 - d(kappa)) W_iso(F) + W_vol(J),
//   W_iso = mu/2 (tr b_iso - 3),  W_vol = K/4 (J^2 - 1 - 2 ln J),
//   e(F) = W_iso(F) / mu  (dimensionless isochoric strain measure),
//   kappa = max(kappa_committed, e(F)),  d = kappa / (kappa + kappa_0),
// kappa_0 the model's entry 'Damage strain'; the update throws where kappa
// would grow by more than 'Increment limit' in one step (for step cuts).
// State per point: [kappa, d];
// state outputs "damage" (d) and "damage_strain" (kappa). On loading
// (e > kappa_committed) the algorithmic tangent is
//   A = (1 - d) A_iso - d'(kappa) P_iso (x) P_iso / mu + A_vol
// (major-symmetric), else (1 - d) A_iso + A_vol. The volumetric part stays
// elastic. Included by one test .cc only (it registers the model).

#include <pg/materials/isochoric_volumetric_neo_hooke.h>
#include <pg/materials/material_registry.h>
#include <pg/materials/volumetric_split.h>

#include <deal.II/base/symmetric_tensor.h>

#include <string>
#include <vector>

namespace pg
{
  namespace Materials
  {
    template <int dim>
    class IsochoricDamageNeoHooke : public Material<dim>,
                                    public VolumetricSplit<dim>
    {
    public:
      IsochoricDamageNeoHooke(const Parameters::Material &parameters)
        : elastic(parameters)
        , mu(parameters.mu())
        , kappa_0(parameters.model_double("Damage strain"))
        , increment_limit(parameters.model_double("Increment limit"))
      {
        AssertThrow(kappa_0 > 0.,
                    ExcBadParameter("Material/isochoric damage neo-Hooke/"
                                    "Damage strain",
                                    std::to_string(kappa_0),
                                    "it must be positive."));
      }

      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Damage strain",
                          "0.01",
                          Patterns::Double(0.),
                          "kappa_0 of d = kappa / (kappa + kappa_0).");
        prm.declare_entry("Increment limit",
                          "1e300",
                          Patterns::Double(0.),
                          "the update throws (like a return mapping that "
                          "does not converge) where kappa would grow by "
                          "more in one step.");
      }

      static void
      parse_parameters(ParameterHandler &prm, Parameters::Material &parameters)
      {
        parameters.model_entries["Damage strain"] = prm.get("Damage strain");
        parameters.model_entries["Increment limit"] =
          prm.get("Increment limit");
      }

      /** The damage of the largest isochoric strain measure @p kappa. */
      double
      damage(const double kappa) const
      {
        return kappa / (kappa + kappa_0);
      }

      /** The isochoric strain measure e(F) = W_iso(F) / mu. */
      double
      strain_measure(const Tensor<2, dim> &F) const
      {
        return elastic.isochoric_strain_energy_density(F) / mu;
      }

      unsigned int
      n_state_variables() const override
      {
        return 2;
      }

      // the isochoric part with history
      void
      evaluate_isochoric_with_state(const Tensor<2, dim>          &F,
                                    const ArrayView<const double> &committed,
                                    const ArrayView<double>       &trial,
                                    Tensor<2, dim>                &P_iso,
                                    Tensor<4, dim> *A_iso) const override
      {
        AssertDimension(committed.size(), 2);
        AssertDimension(trial.size(), 2);
        Tensor<2, dim> P0;
        Tensor<4, dim> A0;
        if (A_iso != nullptr)
          elastic.evaluate_isochoric(F, P0, A0);
        else
          P0 = elastic.isochoric_first_piola_stress(F);
        const double e = strain_measure(F);
        AssertThrow(e - committed[0] <= increment_limit,
                    ExcMessage("the damage update of the test material "
                               "failed (increment limit)"));
        const bool   loading = e > committed[0];
        const double kappa   = loading ? e : committed[0];
        const double d       = damage(kappa);
        trial[0]             = kappa;
        trial[1]             = d;
        P_iso                = (1. - d) * P0;
        if (A_iso == nullptr)
          return;
        *A_iso = (1. - d) * A0;
        if (loading)
          {
            const double d_prime =
              kappa_0 / ((kappa + kappa_0) * (kappa + kappa_0));
            *A_iso -= (d_prime / mu) * outer_product(P0, P0);
          }
      }

      void
      evaluate_with_state(const Tensor<2, dim>          &F,
                          const ArrayView<const double> &committed,
                          const ArrayView<double>       &trial,
                          Tensor<2, dim>                &P,
                          Tensor<4, dim>                *A) const override
      {
        evaluate_isochoric_with_state(F, committed, trial, P, A);
        const double J  = elastic.volume_measure(F);
        const double dW = elastic.volumetric_strain_energy_derivative(J);
        const Tensor<2, dim> dJ = elastic.volume_measure_derivative(F);
        P += dW * dJ;
        if (A == nullptr)
          return;
        *A += elastic.volumetric_strain_energy_second_derivative(J) *
              outer_product(dJ, dJ);
        elastic.add_volume_measure_second_derivative(F, dW, *A);
      }

      Tensor<2, 3>
      cauchy_stress_with_state(
        const Tensor<2, dim>          &F,
        const ArrayView<const double> &state) const override
      {
        // sigma = (1 - d) sigma_iso + p 1, p = W_vol'(J)
        const double p = elastic.volumetric_strain_energy_derivative(
          elastic.volume_measure(F));
        const Tensor<2, 3> I = unit_symmetric_tensor<3>();
        return (1. - state[1]) * (elastic.cauchy_stress(F) - p * I) + p * I;
      }

      std::vector<std::string>
      state_output_names() const override
      {
        return {"damage", "damage_strain"};
      }

      void
      state_outputs(const ArrayView<const double> &state,
                    const ArrayView<double>       &values) const override
      {
        values[0] = state[1];
        values[1] = state[0];
      }

      // The stateless functions: from the initial state kappa = 0.
      void
      evaluate(const Tensor<2, dim> &F,
               Tensor<2, dim>       &P,
               Tensor<4, dim>       &A) const override
      {
        double trial[2];
        evaluate_with_state(F,
                            initial(),
                            make_array_view(trial, trial + 2),
                            P,
                            &A);
      }

      Tensor<2, dim>
      first_piola_stress(const Tensor<2, dim> &F) const override
      {
        double         trial[2];
        Tensor<2, dim> P;
        evaluate_with_state(F,
                            initial(),
                            make_array_view(trial, trial + 2),
                            P,
                            nullptr);
        return P;
      }

      Tensor<2, 3>
      cauchy_stress(const Tensor<2, dim> &F) const override
      {
        const double state[2] = {strain_measure(F), damage(strain_measure(F))};
        return cauchy_stress_with_state(F, make_array_view(state, state + 2));
      }

      double
      strain_energy_density(const Tensor<2, dim> &F) const override
      {
        return isochoric_strain_energy_density(F) +
               elastic.volumetric_strain_energy_density(
                 elastic.volume_measure(F));
      }

      double
      isochoric_strain_energy_density(const Tensor<2, dim> &F) const override
      {
        return (1. - damage(strain_measure(F))) *
               elastic.isochoric_strain_energy_density(F);
      }

      Tensor<2, dim>
      isochoric_first_piola_stress(const Tensor<2, dim> &F) const override
      {
        double         trial[2];
        Tensor<2, dim> P;
        evaluate_isochoric_with_state(F,
                                      initial(),
                                      make_array_view(trial, trial + 2),
                                      P,
                                      nullptr);
        return P;
      }

      void
      evaluate_isochoric(const Tensor<2, dim> &F,
                         Tensor<2, dim>       &P_iso,
                         Tensor<4, dim>       &A_iso) const override
      {
        double trial[2];
        evaluate_isochoric_with_state(F,
                                      initial(),
                                      make_array_view(trial, trial + 2),
                                      P_iso,
                                      &A_iso);
      }

      double
      volume_measure(const Tensor<2, dim> &F) const override
      {
        return elastic.volume_measure(F);
      }

      Tensor<2, dim>
      volume_measure_derivative(const Tensor<2, dim> &F) const override
      {
        return elastic.volume_measure_derivative(F);
      }

      void
      add_volume_measure_second_derivative(const Tensor<2, dim> &F,
                                           const double          factor,
                                           Tensor<4, dim> &A) const override
      {
        elastic.add_volume_measure_second_derivative(F, factor, A);
      }

      double
      volumetric_strain_energy_density(const double Theta) const override
      {
        return elastic.volumetric_strain_energy_density(Theta);
      }

      double
      volumetric_strain_energy_derivative(const double Theta) const override
      {
        return elastic.volumetric_strain_energy_derivative(Theta);
      }

      double
      volumetric_strain_energy_second_derivative(
        const double Theta) const override
      {
        return elastic.volumetric_strain_energy_second_derivative(Theta);
      }

    private:
      static ArrayView<const double>
      initial()
      {
        static const double zero[2] = {0., 0.};
        return make_array_view(zero, zero + 2);
      }

      const IsochoricVolumetricNeoHooke<dim> elastic;
      const double                           mu, kappa_0, increment_limit;
    };

    PG_REGISTER_MATERIAL(IsochoricDamageNeoHooke,
                         "isochoric damage neo-Hooke",
                         "test only: isochoric-volumetric neo-Hooke whose "
                         "isochoric part is degraded by d(max W_iso / mu)")
  } // namespace Materials
} // namespace pg

#endif
