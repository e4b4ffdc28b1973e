#include <pg/elements/condensed_pressure.h>

namespace pg
{
  namespace
  {
    /**
     * The material the kernel sees at a point of a condensed-pressure
     * element: the isochoric part (if @p with_isochoric) plus the volumetric
     * stress of the element's fixed pressure p,
     *   P = P_iso(F) + p d theta / dF,
     *   A = A_iso(F) + p d^2 theta / dF dF
     * (theta = J: p J F^{-T} and p J (F^{-1}_{BA} F^{-1}_{DC} - F^{-1}_{BC}
     * F^{-1}_{DA})). The rank-one part through dp/du is added by the
     * element (it couples the points).
     */
    template <int dim>
    class IsochoricPartAtPressure : public Materials::Material<dim>
    {
    public:
      IsochoricPartAtPressure(const Materials::VolumetricSplit<dim> &split,
                              const double                           pressure,
                              const bool with_isochoric)
        : split(split)
        , pressure(pressure)
        , with_isochoric(with_isochoric)
      {}

      void
      evaluate(const Tensor<2, dim> &F,
               Tensor<2, dim>       &P,
               Tensor<4, dim>       &A) const override
      {
        if (with_isochoric)
          split.evaluate_isochoric(F, P, A);
        else
          {
            P = 0;
            A = 0;
          }
        P += pressure * split.volume_measure_derivative(F);
        split.add_volume_measure_second_derivative(F, pressure, A);
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
      const Materials::VolumetricSplit<dim> &split;
      const double                           pressure;
      const bool                             with_isochoric;
    };



    /**
     * g_{aA} = sum_q w_q (d theta/dF)_{q,AB} V^{qa}_B over the points of
     * @p table, with V the test vectors (@p test) or the trial vectors:
     * W times the derivative of theta-bar with respect to u^a_A.
     */
    template <int dim>
    void
    mean_volume_measure_derivative(const QuadratureTable<dim>            &table,
                                   const std::vector<Tensor<1, dim>>     &y,
                                   const Materials::VolumetricSplit<dim> &split,
                                   const bool                             test,
                                   Vector<double>                        &g)
    {
      const unsigned int n = table.n_nodes;
      g.reinit(n * dim);
      for (unsigned int q = 0; q < table.n_points(); ++q)
        {
          const Tensor<2, dim> dtheta =
            table.weights[q] *
            split.volume_measure_derivative(deformation_gradient(table, q, y));
          const Tensor<1, dim> *B         = &table.trial[q * n];
          const bool            own_tests = test && !table.test_is_trial;
          const unsigned int    begin = own_tests ? table.test_offsets[q] : 0;
          const unsigned int    end = own_tests ? table.test_offsets[q + 1] : n;
          for (unsigned int t = begin; t < end; ++t)
            {
              const unsigned int    a = own_tests ? table.test_nodes[t] : t;
              const Tensor<1, dim> &V =
                own_tests ? table.test_vectors[t] : B[t];
              const Tensor<1, dim> s = dtheta * V;
              for (unsigned int c = 0; c < dim; ++c)
                g[a * dim + c] += s[c];
            }
        }
    }
  } // namespace



  template <int dim>
  CondensedPressure
  condensed_pressure(const QuadratureTable<dim>            &volumetric_table,
                     const std::vector<Tensor<1, dim>>     &y,
                     const Materials::VolumetricSplit<dim> &split)
  {
    double volume = 0, volume_change = 0; // W, sum_q w_q theta_q
    for (unsigned int q = 0; q < volumetric_table.n_points(); ++q)
      {
        const double w = volumetric_table.weights[q];
        volume += w;
        volume_change += w * split.volume_measure(
                               deformation_gradient(volumetric_table, q, y));
      }
    AssertThrow(volume > 0,
                ExcMessage("An element of a condensed-pressure formulation "
                           "(UnlP0, Q1P0, H1P0) has no volume."));
    const double Theta = volume_change / volume;
    return {Theta, split.volumetric_strain_energy_derivative(Theta)};
  }



  template <int dim>
  CondensedPressure
  assemble_condensed_pressure_element(
    const QuadratureTable<dim>            &table,
    const QuadratureTable<dim>            *volumetric_table,
    const std::vector<Tensor<1, dim>>     &y,
    const Materials::VolumetricSplit<dim> &split,
    Vector<double>                        &residual,
    FullMatrix<double>                    *tangent)
  {
    const QuadratureTable<dim> &vol_table =
      (volumetric_table != nullptr ? *volumetric_table : table);
    const CondensedPressure fields = condensed_pressure(vol_table, y, split);

    // The isochoric part and p d^2 theta at every point; for separate
    // volumetric points (PPG) two kernel calls.
    if (volumetric_table == nullptr)
      assemble_element(table,
                       y,
                       IsochoricPartAtPressure<dim>(split,
                                                    fields.pressure,
                                                    true),
                       residual,
                       tangent);
    else
      {
        assemble_element(table,
                         y,
                         IsochoricPartAtPressure<dim>(split, 0., true),
                         residual,
                         tangent);
        Vector<double>     volumetric_residual;
        FullMatrix<double> volumetric_tangent;
        assemble_element(*volumetric_table,
                         y,
                         IsochoricPartAtPressure<dim>(split,
                                                      fields.pressure,
                                                      false),
                         volumetric_residual,
                         tangent != nullptr ? &volumetric_tangent : nullptr);
        residual += volumetric_residual;
        if (tangent != nullptr)
          tangent->add(1., volumetric_tangent);
      }

    // The coupling of the points through p(theta-bar):
    // W_vol''(Theta) / W g (x) g' (test and trial vectors).
    if (tangent != nullptr)
      {
        double volume = 0;
        for (const double w : vol_table.weights)
          volume += w;
        Vector<double> g_test, g_trial;
        mean_volume_measure_derivative(vol_table, y, split, true, g_test);
        if (vol_table.test_is_trial)
          g_trial = g_test;
        else
          mean_volume_measure_derivative(vol_table, y, split, false, g_trial);
        const double factor =
          split.volumetric_strain_energy_second_derivative(fields.dilatation) /
          volume;
        for (unsigned int i = 0; i < g_test.size(); ++i)
          if (g_test[i] != 0.)
            for (unsigned int j = 0; j < g_trial.size(); ++j)
              (*tangent)(i, j) += factor * g_test[i] * g_trial[j];
      }
    return fields;
  }



  template CondensedPressure
  condensed_pressure(const QuadratureTable<2> &,
                     const std::vector<Tensor<1, 2>> &,
                     const Materials::VolumetricSplit<2> &);
  template CondensedPressure
  condensed_pressure(const QuadratureTable<3> &,
                     const std::vector<Tensor<1, 3>> &,
                     const Materials::VolumetricSplit<3> &);
  template CondensedPressure
  assemble_condensed_pressure_element(const QuadratureTable<2> &,
                                      const QuadratureTable<2> *,
                                      const std::vector<Tensor<1, 2>> &,
                                      const Materials::VolumetricSplit<2> &,
                                      Vector<double> &,
                                      FullMatrix<double> *);
  template CondensedPressure
  assemble_condensed_pressure_element(const QuadratureTable<3> &,
                                      const QuadratureTable<3> *,
                                      const std::vector<Tensor<1, 3>> &,
                                      const Materials::VolumetricSplit<3> &,
                                      Vector<double> &,
                                      FullMatrix<double> *);
} // namespace pg
