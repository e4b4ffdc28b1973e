#ifndef pg_elements_isochoric_part_at_pressure_h
#define pg_elements_isochoric_part_at_pressure_h

#include <pg/base/global.h>
#include <pg/materials/material.h>
#include <pg/materials/volumetric_split.h>

#include <deal.II/base/exceptions.h>

#include <vector>

namespace pg
{
  /**
   * The material the kernel sees at a point of a condensed-pressure
   * element: the isochoric part (if @p with_isochoric) plus the volumetric
   * stress of the point's pressure p, held fixed,
   *   P = P_iso(F) + p d theta / dF,
   *   A = A_iso(F) + p d^2 theta / dF dF
   * (theta = J: p J F^{-T} and p J (F^{-1}_{BA} F^{-1}_{DC} - F^{-1}_{BC}
   * F^{-1}_{DA})). The part through dp/du is added by the element (it
   * couples the points).
   *
   * Its state per point (what the kernel hands it) is the material's state
   * (@p n_material_state values: the isochoric part carries the history,
   * VolumetricSplit::evaluate_isochoric_with_state()) followed, with
   * @p pressure_per_point (P1 fields: U2P1, U2P1C, Unl+P1C, where p differs
   * per point), by the point's pressure: read, copied unchanged to the
   * trial state. With P0 fields p is the element's constant @p pressure.
   * with_pressure_per_point() builds that layout from the material's
   * slices.
   */
  template <int dim>
  class IsochoricPartAtPressure : public Materials::Material<dim>
  {
  public:
    IsochoricPartAtPressure(const Materials::VolumetricSplit<dim> &split,
                            const double                           pressure,
                            const bool         with_isochoric,
                            const bool         pressure_per_point = false,
                            const unsigned int n_material_state   = 0)
      : split(split)
      , pressure(pressure)
      , with_isochoric(with_isochoric)
      , pressure_per_point(pressure_per_point)
      , n_material_state(with_isochoric ? n_material_state : 0)
    {}

    void
    evaluate(const Tensor<2, dim> &F,
             Tensor<2, dim>       &P,
             Tensor<4, dim>       &A) const override
    {
      Assert(n_state_variables() == 0, ExcInternalError());
      evaluate_at(F, {}, {}, pressure, P, &A);
    }

    unsigned int
    n_state_variables() const override
    {
      return n_material_state + (pressure_per_point ? 1 : 0);
    }

    void
    evaluate_with_state(const Tensor<2, dim>          &F,
                        const ArrayView<const double> &committed_state,
                        const ArrayView<double>       &trial_state,
                        Tensor<2, dim>                &P,
                        Tensor<4, dim>                *A) const override
    {
      AssertDimension(committed_state.size(), n_state_variables());
      const double p =
        pressure_per_point ? committed_state[n_material_state] : pressure;
      evaluate_at(F,
                  make_array_view(committed_state.begin(),
                                  committed_state.begin() + n_material_state),
                  make_array_view(trial_state.begin(),
                                  trial_state.begin() + n_material_state),
                  p,
                  P,
                  A);
      if (pressure_per_point)
        trial_state[n_material_state] = p;
    }

    Tensor<2, dim>
    first_piola_stress(const Tensor<2, dim> &F) const override
    {
      Assert(n_state_variables() == 0, ExcInternalError());
      Tensor<2, dim> P = pressure * split.volume_measure_derivative(F);
      if (with_isochoric)
        P += split.isochoric_first_piola_stress(F);
      return P;
    }

    Tensor<2, 3>
    cauchy_stress(const Tensor<2, dim> &) const override
    {
      AssertThrow(false, ExcInternalError());
      return {};
    }

    double
    strain_energy_density(const Tensor<2, dim> &) const override
    {
      AssertThrow(false, ExcInternalError());
      return 0;
    }

    /**
     * The state slices of this wrapper for @p n_points points: per point
     * the material's n_material_state values of @p material_state
     * followed, with a pressure per point, by @p point_pressures[q].
     */
    std::vector<double>
    with_pressure_per_point(const ArrayView<const double> &material_state,
                            const std::vector<double>     &point_pressures,
                            const unsigned int             n_points) const
    {
      const unsigned int n = n_state_variables();
      AssertDimension(material_state.size(), n_points * n_material_state);
      std::vector<double> state(n_points * n);
      for (unsigned int q = 0; q < n_points; ++q)
        {
          for (unsigned int i = 0; i < n_material_state; ++i)
            state[q * n + i] = material_state[q * n_material_state + i];
          if (pressure_per_point)
            state[q * n + n_material_state] = point_pressures[q];
        }
      return state;
    }

    /**
     * The material's part of the wrapper's state @p state (the inverse of
     * with_pressure_per_point()) into @p material_state.
     */
    void
    extract_material_state(const std::vector<double> &state,
                           const ArrayView<double>   &material_state) const
    {
      const unsigned int n        = n_state_variables();
      const unsigned int n_points = (n == 0 ? 0 : state.size() / n);
      AssertDimension(material_state.size(), n_points * n_material_state);
      for (unsigned int q = 0; q < n_points; ++q)
        for (unsigned int i = 0; i < n_material_state; ++i)
          material_state[q * n_material_state + i] = state[q * n + i];
    }

  private:
    void
    evaluate_at(const Tensor<2, dim>          &F,
                const ArrayView<const double> &committed_state,
                const ArrayView<double>       &trial_state,
                const double                   p,
                Tensor<2, dim>                &P,
                Tensor<4, dim>                *A) const
    {
      if (with_isochoric && n_material_state > 0)
        split.evaluate_isochoric_with_state(F,
                                            committed_state,
                                            trial_state,
                                            P,
                                            A);
      else if (with_isochoric && A != nullptr)
        split.evaluate_isochoric(F, P, *A);
      else if (with_isochoric)
        P = split.isochoric_first_piola_stress(F);
      else
        {
          P = 0;
          if (A != nullptr)
            *A = 0;
        }
      P += p * split.volume_measure_derivative(F);
      if (A != nullptr)
        split.add_volume_measure_second_derivative(F, p, *A);
    }

    const Materials::VolumetricSplit<dim> &split;
    const double                           pressure;
    const bool                             with_isochoric;
    const bool                             pressure_per_point;
    const unsigned int                     n_material_state;
  };
} // namespace pg

#endif
