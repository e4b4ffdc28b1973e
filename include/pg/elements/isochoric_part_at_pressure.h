#ifndef pg_elements_isochoric_part_at_pressure_h
#define pg_elements_isochoric_part_at_pressure_h

#include <pg/base/global.h>
#include <pg/materials/material.h>
#include <pg/materials/volumetric_split.h>

#include <deal.II/base/exceptions.h>

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
   * couples the points). With P0 fields p is the element's constant;
   * with P1 fields (U2P1) it differs per point and is handed to the
   * kernel as the point's one "state variable" (read, never changed).
   */
  template <int dim>
  class IsochoricPartAtPressure : public Materials::Material<dim>
  {
  public:
    IsochoricPartAtPressure(const Materials::VolumetricSplit<dim> &split,
                            const double                           pressure,
                            const bool with_isochoric,
                            const bool pressure_per_point = false)
      : split(split)
      , pressure(pressure)
      , with_isochoric(with_isochoric)
      , pressure_per_point(pressure_per_point)
    {}

    void
    evaluate(const Tensor<2, dim> &F,
             Tensor<2, dim>       &P,
             Tensor<4, dim>       &A) const override
    {
      evaluate_at(F, pressure, P, A);
    }

    unsigned int
    n_state_variables() const override
    {
      return pressure_per_point ? 1 : 0;
    }

    void
    evaluate_with_state(const Tensor<2, dim>          &F,
                        const ArrayView<const double> &point_pressure,
                        const ArrayView<double>       &trial_state,
                        Tensor<2, dim>                &P,
                        Tensor<4, dim>                *A) const override
    {
      Tensor<4, dim> A_local;
      evaluate_at(F, point_pressure[0], P, A_local);
      trial_state[0] = point_pressure[0];
      if (A != nullptr)
        *A = A_local;
    }

    Tensor<2, dim>
    first_piola_stress(const Tensor<2, dim> &F) const override
    {
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

  private:
    void
    evaluate_at(const Tensor<2, dim> &F,
                const double          p,
                Tensor<2, dim>       &P,
                Tensor<4, dim>       &A) const
    {
      if (with_isochoric)
        split.evaluate_isochoric(F, P, A);
      else
        {
          P = 0;
          A = 0;
        }
      P += p * split.volume_measure_derivative(F);
      split.add_volume_measure_second_derivative(F, p, A);
    }

    const Materials::VolumetricSplit<dim> &split;
    const double                           pressure;
    const bool                             with_isochoric;
    const bool                             pressure_per_point;
  };
} // namespace pg

#endif
