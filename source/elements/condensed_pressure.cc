#include <pg/elements/condensed_pressure.h>

#include <Eigen/Dense>

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



    /**
     * The basis phi_q of the condensed fields at the points of a table:
     * (1) for P0, (1, (X_q - X_c) / L) for P1, with X_c the weighted
     * centroid of the points and L their radius of gyration (the scaling
     * keeps the moment matrix well conditioned; the projection does not
     * depend on it), and the moment matrix M = sum_q w_q phi_q phi_q^T.
     */
    template <int dim>
    struct FieldBasis
    {
      FieldBasis(const QuadratureTable<dim> &table, const unsigned int degree)
        : m(degree == 0 ? 1 : dim + 1)
        , phi(table.n_points(), Eigen::VectorXd::Ones(m))
      {
        Assert(degree <= 1, ExcNotImplemented());
        double     volume = 0;
        Point<dim> centroid;
        for (unsigned int q = 0; q < table.n_points(); ++q)
          {
            volume += table.weights[q];
            centroid += table.weights[q] * table.points[q];
          }
        AssertThrow(volume > 0,
                    ExcMessage("An element of a condensed-pressure "
                               "formulation (UnlP0, U2P1, Q1P0, H1P0) has no "
                               "volume."));
        if (degree == 1)
          {
            centroid /= volume;
            double gyration = 0;
            for (unsigned int q = 0; q < table.n_points(); ++q)
              gyration +=
                table.weights[q] * (table.points[q] - centroid).norm_square();
            const double L = std::sqrt(gyration / volume);
            for (unsigned int q = 0; q < table.n_points(); ++q)
              for (unsigned int c = 0; c < dim; ++c)
                phi[q][1 + c] = (table.points[q][c] - centroid[c]) / L;
          }
        Eigen::MatrixXd M = Eigen::MatrixXd::Zero(m, m);
        for (unsigned int q = 0; q < table.n_points(); ++q)
          M += table.weights[q] * phi[q] * phi[q].transpose();
        // relative to the volume: 1 for a point cloud that fills a ball
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(M);
        AssertThrow(eigen.eigenvalues().minCoeff() > 1e-8 * volume,
                    ExcMessage(
                      "The evaluation points of a family with a linear "
                      "pressure (U2P1) lie on a line (2-D) or a plane "
                      "(3-D): a linear pressure field is undetermined on "
                      "them. Enlarge the horizon (subsection "
                      "'Discretization')."));
        M_inverse = M.inverse();
      }

      /** The L2 projection coefficients of the point values @p v. */
      Eigen::VectorXd
      project(const QuadratureTable<dim> &table,
              const std::vector<double>  &v) const
      {
        Eigen::VectorXd b = Eigen::VectorXd::Zero(m);
        for (unsigned int q = 0; q < table.n_points(); ++q)
          b += (table.weights[q] * v[q]) * phi[q];
        return M_inverse * b;
      }

      const unsigned int           m;
      std::vector<Eigen::VectorXd> phi;
      Eigen::MatrixXd              M_inverse;
    };



    /**
     * G_{i,aA} = sum_q w_q phi_{q,i} (d theta/dF)_{q,AB} V^{qa}_B over the
     * points of @p table, with V the test vectors (@p test) or the trial
     * vectors: the derivative of the projection moments sum_q w_q phi_q
     * theta_q with respect to u^a_A (for P0, W times d theta-bar / du).
     */
    template <int dim>
    Eigen::MatrixXd
    moment_derivative(const QuadratureTable<dim>            &table,
                      const FieldBasis<dim>                 &basis,
                      const std::vector<Tensor<1, dim>>     &y,
                      const Materials::VolumetricSplit<dim> &split,
                      const bool                             test)
    {
      const unsigned int n = table.n_nodes;
      Eigen::MatrixXd    G = Eigen::MatrixXd::Zero(basis.m, n * dim);
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
                G.col(a * dim + c) += s[c] * basis.phi[q];
            }
        }
      return G;
    }



    /**
     * The condensed fields at the points of @p table: Theta_q, the L2
     * projection of theta onto the basis, and p_q, that of W_vol'(Theta).
     */
    template <int dim>
    void
    condensed_fields(const QuadratureTable<dim>            &table,
                     const FieldBasis<dim>                 &basis,
                     const std::vector<Tensor<1, dim>>     &y,
                     const Materials::VolumetricSplit<dim> &split,
                     std::vector<double>                   &Theta,
                     std::vector<double>                   &p)
    {
      const unsigned int  n_points = table.n_points();
      std::vector<double> theta(n_points);
      for (unsigned int q = 0; q < n_points; ++q)
        theta[q] = split.volume_measure(deformation_gradient(table, q, y));
      const Eigen::VectorXd theta_coefficients = basis.project(table, theta);
      Theta.resize(n_points);
      std::vector<double> dW(n_points);
      for (unsigned int q = 0; q < n_points; ++q)
        {
          Theta[q] = basis.phi[q].dot(theta_coefficients);
          dW[q]    = split.volumetric_strain_energy_derivative(Theta[q]);
        }
      const Eigen::VectorXd p_coefficients = basis.project(table, dW);
      p.resize(n_points);
      for (unsigned int q = 0; q < n_points; ++q)
        p[q] = basis.phi[q].dot(p_coefficients);
    }
  } // namespace



  template <int dim>
  CondensedPressure
  condensed_pressure(const QuadratureTable<dim>            &volumetric_table,
                     const std::vector<Tensor<1, dim>>     &y,
                     const Materials::VolumetricSplit<dim> &split,
                     const unsigned int                     degree)
  {
    const FieldBasis<dim> basis(volumetric_table, degree);
    std::vector<double>   Theta, p;
    condensed_fields(volumetric_table, basis, y, split, Theta, p);
    return {Theta[0], p[0]};
  }



  template <int dim>
  CondensedPressure
  assemble_condensed_pressure_element(
    const QuadratureTable<dim>            &table,
    const QuadratureTable<dim>            *volumetric_table,
    const std::vector<Tensor<1, dim>>     &y,
    const Materials::VolumetricSplit<dim> &split,
    Vector<double>                        &residual,
    FullMatrix<double>                    *tangent,
    const unsigned int                     degree)
  {
    Assert(degree == 0 || volumetric_table == nullptr, ExcNotImplemented());
    const QuadratureTable<dim> &vol_table =
      (volumetric_table != nullptr ? *volumetric_table : table);
    const FieldBasis<dim> basis(vol_table, degree);
    std::vector<double>   Theta, p;
    condensed_fields(vol_table, basis, y, split, Theta, p);

    // The isochoric part and p d^2 theta at every point; for separate
    // volumetric points (PPG) two kernel calls.
    if (degree == 1)
      {
        std::vector<double> unchanged_pressures(p.size());
        assemble_element(table,
                         y,
                         IsochoricPartAtPressure<dim>(split, 0., true, true),
                         residual,
                         tangent,
                         make_array_view(p),
                         make_array_view(unchanged_pressures));
      }
    else if (volumetric_table == nullptr)
      assemble_element(table,
                       y,
                       IsochoricPartAtPressure<dim>(split, p[0], true),
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
                         IsochoricPartAtPressure<dim>(split, p[0], false),
                         volumetric_residual,
                         tangent != nullptr ? &volumetric_tangent : nullptr);
        residual += volumetric_residual;
        if (tangent != nullptr)
          tangent->add(1., volumetric_tangent);
      }

    // The coupling of the points through p(Theta(theta)):
    // G_test^T M^{-1} (sum_q w_q W_vol''(Theta_q) phi_q phi_q^T) M^{-1}
    // G_trial (for P0: W_vol''(Theta) / W g (x) g').
    if (tangent != nullptr)
      {
        Eigen::MatrixXd H = Eigen::MatrixXd::Zero(basis.m, basis.m);
        for (unsigned int q = 0; q < vol_table.n_points(); ++q)
          H += (vol_table.weights[q] *
                split.volumetric_strain_energy_second_derivative(Theta[q])) *
               basis.phi[q] * basis.phi[q].transpose();
        const Eigen::MatrixXd D = basis.M_inverse * H * basis.M_inverse;
        const Eigen::MatrixXd G_test =
          moment_derivative(vol_table, basis, y, split, true);
        const Eigen::MatrixXd DG_trial =
          D * (vol_table.test_is_trial ?
                 G_test :
                 moment_derivative(vol_table, basis, y, split, false));
        for (unsigned int i = 0; i < G_test.cols(); ++i)
          if (!G_test.col(i).isZero(0.))
            for (unsigned int j = 0; j < DG_trial.cols(); ++j)
              (*tangent)(i, j) += G_test.col(i).dot(DG_trial.col(j));
      }
    return {Theta[0], p[0]};
  }



  template CondensedPressure
  condensed_pressure(const QuadratureTable<2> &,
                     const std::vector<Tensor<1, 2>> &,
                     const Materials::VolumetricSplit<2> &,
                     const unsigned int);
  template CondensedPressure
  condensed_pressure(const QuadratureTable<3> &,
                     const std::vector<Tensor<1, 3>> &,
                     const Materials::VolumetricSplit<3> &,
                     const unsigned int);
  template CondensedPressure
  assemble_condensed_pressure_element(const QuadratureTable<2> &,
                                      const QuadratureTable<2> *,
                                      const std::vector<Tensor<1, 2>> &,
                                      const Materials::VolumetricSplit<2> &,
                                      Vector<double> &,
                                      FullMatrix<double> *,
                                      const unsigned int);
  template CondensedPressure
  assemble_condensed_pressure_element(const QuadratureTable<3> &,
                                      const QuadratureTable<3> *,
                                      const std::vector<Tensor<1, 3>> &,
                                      const Materials::VolumetricSplit<3> &,
                                      Vector<double> &,
                                      FullMatrix<double> *,
                                      const unsigned int);
} // namespace pg
