#include <pg/elements/condensed_pressure.h>
#include <pg/elements/isochoric_part_at_pressure.h>
#include <pg/elements/nodal_pressure.h>

#include <Eigen/Dense>

namespace pg
{
  namespace
  {
    /** The layout of CondensedFieldIterate's S and T. */
    using RowMajorMatrix =
      Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;



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
        moments   = M;
      }

      /** The point values sum_i c_i phi_{q,i} of the coefficients @p c. */
      std::vector<double>
      values(const Eigen::VectorXd &c) const
      {
        std::vector<double> v(phi.size());
        for (unsigned int q = 0; q < phi.size(); ++q)
          v[q] = phi[q].dot(c);
        return v;
      }

      /** The moments sum_q w_q v_q phi_q of the point values @p v. */
      Eigen::VectorXd
      project_moments(const QuadratureTable<dim> &table,
                      const std::vector<double>  &v) const
      {
        Eigen::VectorXd b = Eigen::VectorXd::Zero(m);
        for (unsigned int q = 0; q < table.n_points(); ++q)
          b += (table.weights[q] * v[q]) * phi[q];
        return b;
      }

      /** The L2 projection coefficients of the point values @p v. */
      Eigen::VectorXd
      project(const QuadratureTable<dim> &table,
              const std::vector<double>  &v) const
      {
        return M_inverse * project_moments(table, v);
      }

      const unsigned int           m;
      std::vector<Eigen::VectorXd> phi;
      Eigen::MatrixXd              M_inverse, moments;
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



    /** The volume measure theta(F_q) at the points of @p table. */
    template <int dim>
    std::vector<double>
    volume_measures(const QuadratureTable<dim>            &table,
                    const std::vector<Tensor<1, dim>>     &y,
                    const Materials::VolumetricSplit<dim> &split)
    {
      std::vector<double> theta(table.n_points());
      for (unsigned int q = 0; q < table.n_points(); ++q)
        theta[q] = split.volume_measure(deformation_gradient(table, q, y));
      return theta;
    }



    /** W_vol'(Theta_q) at the point values @p Theta. */
    template <int dim>
    std::vector<double>
    pressures_of(const std::vector<double>             &Theta,
                 const Materials::VolumetricSplit<dim> &split)
    {
      std::vector<double> dW(Theta.size());
      for (unsigned int q = 0; q < Theta.size(); ++q)
        dW[q] = split.volumetric_strain_energy_derivative(Theta[q]);
      return dW;
    }



    /**
     * The coefficients of the condensed fields at local equilibrium (the
     * closed form): c_Theta, the L2 projection of the volume measures
     * @p theta onto the basis, and c_p, that of W_vol'(Theta).
     */
    template <int dim>
    void
    condensed_fields(const QuadratureTable<dim>            &table,
                     const FieldBasis<dim>                 &basis,
                     const std::vector<double>             &theta,
                     const Materials::VolumetricSplit<dim> &split,
                     Eigen::VectorXd                       &c_Theta,
                     Eigen::VectorXd                       &c_p)
    {
      c_Theta = basis.project(table, theta);
      c_p = basis.project(table, pressures_of(basis.values(c_Theta), split));
    }



    Eigen::VectorXd
    to_eigen(const std::vector<double> &v)
    {
      return Eigen::Map<const Eigen::VectorXd>(v.data(), v.size());
    }



    std::vector<double>
    to_std(const Eigen::VectorXd &v)
    {
      return std::vector<double>(v.data(), v.data() + v.size());
    }



    /**
     * The material's state variables per point of @p table, from the size
     * of its slice @p committed_state (0: stateless).
     */
    template <int dim>
    unsigned int
    n_material_state(const QuadratureTable<dim>    &table,
                     const ArrayView<const double> &committed_state)
    {
      if ((committed_state.size() == 0))
        return 0;
      AssertThrow(table.n_points() > 0 &&
                    committed_state.size() % table.n_points() == 0,
                  ExcInternalError());
      return committed_state.size() / table.n_points();
    }



    /**
     * The isochoric part at every point of @p table and the volumetric
     * stress p d theta / dF (with its tangent p d^2 theta) of the constant
     * pressure @p p at the volumetric points: those of @p table itself
     * (@p volumetric_table nullptr; one kernel call) or of a separate table
     * (a PPG family's master; two calls). The isochoric part carries the
     * material's state (@p committed_state, @p trial_state: the material's
     * slices of the points of @p table; empty if stateless).
     */
    template <int dim>
    void
    assemble_isochoric_part_at_pressure(
      const QuadratureTable<dim>            &table,
      const QuadratureTable<dim>            *volumetric_table,
      const std::vector<Tensor<1, dim>>     &y,
      const Materials::VolumetricSplit<dim> &split,
      const double                           p,
      Vector<double>                        &residual,
      FullMatrix<double>                    *tangent,
      const ArrayView<const double>         &committed_state,
      const ArrayView<double>               &trial_state)
    {
      const unsigned int n_state = n_material_state(table, committed_state);
      if (volumetric_table == nullptr)
        {
          assemble_element(
            table,
            y,
            IsochoricPartAtPressure<dim>(split, p, true, false, n_state),
            residual,
            tangent,
            committed_state,
            trial_state);
          return;
        }
      assemble_element(
        table,
        y,
        IsochoricPartAtPressure<dim>(split, 0., true, false, n_state),
        residual,
        tangent,
        committed_state,
        trial_state);
      Vector<double>     volumetric_residual;
      FullMatrix<double> volumetric_tangent;
      assemble_element(*volumetric_table,
                       y,
                       IsochoricPartAtPressure<dim>(split, p, false),
                       volumetric_residual,
                       tangent != nullptr ? &volumetric_tangent : nullptr);
      residual += volumetric_residual;
      if (tangent != nullptr)
        tangent->add(1., volumetric_tangent);
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
    Eigen::VectorXd       c_Theta, c_p;
    condensed_fields(volumetric_table,
                     basis,
                     volume_measures(volumetric_table, y, split),
                     split,
                     c_Theta,
                     c_p);
    return {basis.phi[0].dot(c_Theta), basis.phi[0].dot(c_p)};
  }



  void
  update_condensed_fields(CondensedFieldIterate     &iterate,
                          const std::vector<double> &du)
  {
    if (!iterate.bubble_S.empty())
      {
        const unsigned int                     m = iterate.bubble.size();
        const Eigen::Map<const RowMajorMatrix> S(iterate.bubble_S.data(),
                                                 m,
                                                 du.size());
        const Eigen::VectorXd                  d_bubble =
          to_eigen(iterate.bubble_a) +
          S * Eigen::Map<const Eigen::VectorXd>(du.data(), du.size());
        for (unsigned int i = 0; i < m; ++i)
          iterate.bubble[i] += d_bubble[i];
        iterate.bubble_S.clear();
      }
    if (iterate.S.empty())
      return;
    const unsigned int m = iterate.a.size();
    AssertDimension(iterate.S.size(), m * du.size());
    const Eigen::Map<const RowMajorMatrix> S(iterate.S.data(), m, du.size());
    const Eigen::Map<const RowMajorMatrix> T(iterate.T.data(), m, m);
    const Eigen::VectorXd                  d_Theta =
      to_eigen(iterate.a) +
      S * Eigen::Map<const Eigen::VectorXd>(du.data(), du.size());
    const Eigen::VectorXd d_p = to_eigen(iterate.b) + T * d_Theta;
    for (unsigned int i = 0; i < m; ++i)
      {
        iterate.dilatation[i] += d_Theta[i];
        iterate.pressure[i] += d_p[i];
      }
    // the linearisation belongs to the previous iterate
    iterate.S.clear();
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
    const unsigned int                     degree,
    CondensedFieldIterate                 *iterate,
    const ArrayView<const double>         &committed_state,
    const ArrayView<double>               &trial_state)
  {
    Assert(degree == 0 || volumetric_table == nullptr, ExcNotImplemented());
    const QuadratureTable<dim> &vol_table =
      (volumetric_table != nullptr ? *volumetric_table : table);
    const FieldBasis<dim>     basis(vol_table, degree);
    const std::vector<double> theta = volume_measures(vol_table, y, split);
    Eigen::VectorXd           c_Theta, c_p;
    if (iterate == nullptr || iterate->at_equilibrium)
      {
        condensed_fields(vol_table, basis, theta, split, c_Theta, c_p);
        if (iterate != nullptr)
          {
            iterate->dilatation     = to_std(c_Theta);
            iterate->pressure       = to_std(c_p);
            iterate->at_equilibrium = false;
            iterate->S.clear();
          }
      }
    else
      {
        AssertDimension(iterate->dilatation.size(), basis.m);
        c_Theta = to_eigen(iterate->dilatation);
        c_p     = to_eigen(iterate->pressure);
      }
    const std::vector<double> Theta = basis.values(c_Theta);
    const std::vector<double> p     = basis.values(c_p);

    // The isochoric part and p d^2 theta at every point.
    if (degree == 1)
      {
        // p differs per point: the kernel reads it from the state, after
        // the material's own variables
        const IsochoricPartAtPressure<dim>
          part(split, 0., true, true, n_material_state(table, committed_state));
        const std::vector<double> committed =
          part.with_pressure_per_point(committed_state, p, table.n_points());
        std::vector<double> trial(committed.size());
        assemble_element(table,
                         y,
                         part,
                         residual,
                         tangent,
                         make_array_view(committed),
                         make_array_view(trial));
        part.extract_material_state(trial, trial_state);
      }
    else
      assemble_isochoric_part_at_pressure(table,
                                          volumetric_table,
                                          y,
                                          split,
                                          p[0],
                                          residual,
                                          tangent,
                                          committed_state,
                                          trial_state);

    // Three fields: the local residuals R_p, R_Theta of the iterate enter
    // the condensed residual through G_test^T M^{-1} (R_Theta + H M^{-1}
    // R_p). The coupling of the points through p(Theta(theta)) is the
    // tangent's G_test^T M^{-1} H M^{-1} G_trial (for P0: W_vol''(Theta) /
    // W g (x) g').
    if (tangent == nullptr && iterate == nullptr)
      return {Theta[0], p[0]};
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(basis.m, basis.m);
    for (unsigned int q = 0; q < vol_table.n_points(); ++q)
      H += (vol_table.weights[q] *
            split.volumetric_strain_energy_second_derivative(Theta[q])) *
           basis.phi[q] * basis.phi[q].transpose();
    const Eigen::MatrixXd G_test =
      moment_derivative(vol_table, basis, y, split, true);
    if (iterate != nullptr)
      {
        const Eigen::VectorXd a =
          basis.M_inverse *
          (basis.project_moments(vol_table, theta) - basis.moments * c_Theta);
        const Eigen::VectorXd b =
          basis.M_inverse *
          (basis.project_moments(vol_table, pressures_of(Theta, split)) -
           basis.moments * c_p);
        const Eigen::VectorXd correction =
          G_test.transpose() * (b + basis.M_inverse * H * a);
        for (unsigned int i = 0; i < correction.size(); ++i)
          residual[i] += correction[i];
        if (tangent != nullptr)
          {
            iterate->a = to_std(a);
            iterate->b = to_std(b);
          }
      }
    if (tangent == nullptr)
      return {Theta[0], p[0]};
    const Eigen::MatrixXd MG_trial =
      basis.M_inverse *
      (vol_table.test_is_trial ?
         G_test :
         moment_derivative(vol_table, basis, y, split, false));
    const Eigen::MatrixXd DG_trial = basis.M_inverse * H * MG_trial;
    for (unsigned int i = 0; i < G_test.cols(); ++i)
      if (!G_test.col(i).isZero(0.))
        for (unsigned int j = 0; j < DG_trial.cols(); ++j)
          (*tangent)(i, j) += G_test.col(i).dot(DG_trial.col(j));
    if (iterate != nullptr)
      {
        const RowMajorMatrix S = MG_trial, T = basis.M_inverse * H;
        iterate->S.assign(S.data(), S.data() + S.size());
        iterate->T.assign(T.data(), T.data() + T.size());
      }
    return {Theta[0], p[0]};
  }



  template <int dim>
  double
  assemble_incompressible_p0_element(
    const QuadratureTable<dim>            &table,
    const QuadratureTable<dim>            *volumetric_table,
    const std::vector<Tensor<1, dim>>     &y,
    const Materials::VolumetricSplit<dim> &split,
    const double                           pressure,
    Vector<double>                        &residual,
    FullMatrix<double>                    *tangent,
    const ArrayView<const double>         &committed_state,
    const ArrayView<double>               &trial_state)
  {
    const QuadratureTable<dim> &vol_table =
      (volumetric_table != nullptr ? *volumetric_table : table);
    const unsigned int n_u = table.n_nodes * dim;
    Vector<double>     r_u;
    FullMatrix<double> k_uu;
    assemble_isochoric_part_at_pressure(table,
                                        volumetric_table,
                                        y,
                                        split,
                                        pressure,
                                        r_u,
                                        tangent != nullptr ? &k_uu : nullptr,
                                        committed_state,
                                        trial_state);
    AssertDimension(r_u.size(), n_u);

    const FieldBasis<dim>     basis(vol_table, 0);
    const std::vector<double> theta      = volume_measures(vol_table, y, split);
    const double              theta_0    = rest_volume_measure(split);
    double                    constraint = 0, volume = 0;
    for (unsigned int q = 0; q < vol_table.n_points(); ++q)
      {
        constraint += vol_table.weights[q] * (theta[q] - theta_0);
        volume += vol_table.weights[q];
      }
    residual.reinit(n_u + 1);
    for (unsigned int i = 0; i < n_u; ++i)
      residual[i] = r_u[i];
    residual[n_u] = constraint;
    if (tangent != nullptr)
      {
        const Eigen::MatrixXd g_test =
          moment_derivative(vol_table, basis, y, split, true);
        const Eigen::MatrixXd g_trial =
          vol_table.test_is_trial ?
            g_test :
            moment_derivative(vol_table, basis, y, split, false);
        tangent->reinit(n_u + 1, n_u + 1);
        for (unsigned int i = 0; i < n_u; ++i)
          {
            for (unsigned int j = 0; j < n_u; ++j)
              (*tangent)(i, j) = k_uu(i, j);
            (*tangent)(i, n_u) = g_test(0, i);
            (*tangent)(n_u, i) = g_trial(0, i);
          }
      }
    return theta_0 + constraint / volume;
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
                                      const unsigned int,
                                      CondensedFieldIterate *,
                                      const ArrayView<const double> &,
                                      const ArrayView<double> &);
  template CondensedPressure
  assemble_condensed_pressure_element(const QuadratureTable<3> &,
                                      const QuadratureTable<3> *,
                                      const std::vector<Tensor<1, 3>> &,
                                      const Materials::VolumetricSplit<3> &,
                                      Vector<double> &,
                                      FullMatrix<double> *,
                                      const unsigned int,
                                      CondensedFieldIterate *,
                                      const ArrayView<const double> &,
                                      const ArrayView<double> &);
  template double
  assemble_incompressible_p0_element(const QuadratureTable<2> &,
                                     const QuadratureTable<2> *,
                                     const std::vector<Tensor<1, 2>> &,
                                     const Materials::VolumetricSplit<2> &,
                                     const double,
                                     Vector<double> &,
                                     FullMatrix<double> *,
                                     const ArrayView<const double> &,
                                     const ArrayView<double> &);
  template double
  assemble_incompressible_p0_element(const QuadratureTable<3> &,
                                     const QuadratureTable<3> *,
                                     const std::vector<Tensor<1, 3>> &,
                                     const Materials::VolumetricSplit<3> &,
                                     const double,
                                     Vector<double> &,
                                     FullMatrix<double> *,
                                     const ArrayView<const double> &,
                                     const ArrayView<double> &);
} // namespace pg
