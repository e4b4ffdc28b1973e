#include <pg/elements/isochoric_part_at_pressure.h>
#include <pg/elements/nodal_pressure.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/symmetric_tensor.h>

#include <Eigen/Dense>

namespace pg
{
  namespace
  {
    /**
     * The bubble's local residual r_b = sum_q w_q P_q beta_q and its
     * tangent K_bb = sum_q w_q beta_q . A_q . beta_q at the bubble @p u_b,
     * with F_q = F^0_q + u_b (x) beta_q and P = P_iso + p_q d theta / dF
     * (@p point_state: the state of @p material at each point, the
     * committed material state and p_q; the trial state is discarded);
     * @p scale = sum_q w_q (|P_q| + |A_q|) |beta_q|, the size of r_b's
     * terms (|A| that of P at a unit strain, for states near F = I).
     */
    template <int dim>
    void
    bubble_equation(const QuadratureTable<dim>         &table,
                    const std::vector<Tensor<2, dim>>  &F0,
                    const std::vector<Tensor<1, dim>>  &beta,
                    const std::vector<double>          &point_state,
                    const IsochoricPartAtPressure<dim> &material,
                    const Tensor<1, dim>               &u_b,
                    Eigen::Matrix<double, dim, 1>      &r_b,
                    Eigen::Matrix<double, dim, dim>    &K_bb,
                    double                             &scale)
    {
      scale = 0;
      r_b.setZero();
      K_bb.setZero();
      const unsigned int  n_state = material.n_state_variables();
      std::vector<double> unused(n_state);
      for (unsigned int q = 0; q < table.n_points(); ++q)
        {
          const Tensor<2, dim> F = F0[q] + outer_product(u_b, beta[q]);
          Tensor<2, dim>       P;
          Tensor<4, dim>       A;
          material.evaluate_with_state(
            F,
            make_array_view(point_state.begin() + q * n_state,
                            point_state.begin() + (q + 1) * n_state),
            make_array_view(unused),
            P,
            &A);
          const double w = table.weights[q];
          scale += w * (P.norm() + A.norm()) * beta[q].norm();
          for (unsigned int i = 0; i < dim; ++i)
            {
              r_b[i] += w * (P[i] * beta[q]);
              for (unsigned int k = 0; k < dim; ++k)
                {
                  double s = 0;
                  for (unsigned int j = 0; j < dim; ++j)
                    for (unsigned int l = 0; l < dim; ++l)
                      s += beta[q][j] * A[i][j][k][l] * beta[q][l];
                  K_bb(i, k) += w * s;
                }
            }
        }
    }
  } // namespace



  template <int dim>
  double
  rest_volume_measure(const Materials::VolumetricSplit<dim> &material)
  {
    return material.volume_measure(
      Tensor<2, dim>(unit_symmetric_tensor<dim>()));
  }



  template <int dim>
  std::vector<double>
  nodal_field_interpolation(const QuadratureTable<dim> &table)
  {
    const unsigned int    n = table.n_nodes;
    std::vector<double>   pi(table.n_points() * n);
    const Tensor<1, dim> *B0 = &table.trial[0];
    for (unsigned int q = 0; q < table.n_points(); ++q)
      {
        const Tensor<1, dim> dX = table.points[q] - table.points[0];
        for (unsigned int a = 0; a < n; ++a)
          pi[q * n + a] = (a == 0 ? 1. : 0.) + B0[a] * dX;
      }
    return pi;
  }



  template <int dim>
  QuadratureTable<dim>
  with_bubble_node(const QuadratureTable<dim> &table)
  {
    AssertThrow(table.test_is_trial, ExcNotImplemented());
    const unsigned int n = table.n_nodes, n_q = table.n_points();
    double             volume = 0;
    Point<dim>         centroid;
    for (unsigned int q = 0; q < n_q; ++q)
      {
        volume += table.weights[q];
        centroid += table.weights[q] * table.points[q];
      }
    centroid /= volume;
    QuadratureTable<dim>        augmented;
    std::vector<Tensor<1, dim>> row(n + 1);
    augmented.reinit(n + 1, true);
    for (unsigned int q = 0; q < n_q; ++q)
      {
        for (unsigned int a = 0; a < n; ++a)
          row[a] = table.trial[q * n + a];
        row[n] = table.points[q] - centroid;
        augmented.add_point(table.weights[q], row, table.points[q]);
      }
    return augmented;
  }



  template <int dim>
  void
  assemble_nodal_pressure_family(const QuadratureTable<dim>        &table,
                                 const std::vector<Tensor<1, dim>> &y,
                                 const std::vector<double>         &p,
                                 const std::vector<double>         &vartheta,
                                 const Materials::VolumetricSplit<dim> &split,
                                 const bool                             bubble,
                                 Vector<double>                &residual,
                                 FullMatrix<double>            *tangent,
                                 CondensedFieldIterate         *iterate,
                                 const ArrayView<const double> &committed_state,
                                 const ArrayView<double>       &trial_state)
  {
    const unsigned int n = table.n_nodes, n_q = table.n_points();
    AssertDimension(y.size(), n);
    AssertDimension(p.size(), n);
    AssertDimension(vartheta.size(), n);
    const std::vector<double> pi      = nodal_field_interpolation(table);
    const double              theta_0 = rest_volume_measure(split);
    std::vector<double>       p_q(n_q, 0.), Theta_q(n_q, theta_0);
    for (unsigned int q = 0; q < n_q; ++q)
      for (unsigned int a = 0; a < n; ++a)
        {
          p_q[q] += pi[q * n + a] * p[a];
          Theta_q[q] += pi[q * n + a] * vartheta[a];
        }
    // the kernel's state per point: the material's, then p_q
    const IsochoricPartAtPressure<dim> material(split,
                                                0.,
                                                true,
                                                true,
                                                (committed_state.size() == 0) ?
                                                  0 :
                                                  committed_state.size() / n_q);
    const std::vector<double>          point_state =
      material.with_pressure_per_point(committed_state, p_q, n_q);

    // The kernel's table: the family's, with the bubble as node n whose
    // trial vectors are beta_q = X_q - X_c (eq. 6.15), and y_n = u_b.
    const unsigned int          n_u = n + (bubble ? 1 : 0);
    QuadratureTable<dim>        augmented;
    std::vector<Tensor<1, dim>> y_u = y;
    std::vector<Tensor<1, dim>> beta;
    if (bubble)
      {
        augmented = with_bubble_node(table);
        beta.resize(n_q);
        std::vector<Tensor<2, dim>> F0(n_q);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            beta[q] = augmented.trial[q * n_u + n];
            F0[q]   = deformation_gradient(table, q, y);
          }

        // u_b: the iterate's, or local equilibrium r_b = 0
        Tensor<1, dim> u_b;
        if (iterate != nullptr && !iterate->at_equilibrium)
          {
            AssertDimension(iterate->bubble.size(), dim);
            for (unsigned int i = 0; i < dim; ++i)
              u_b[i] = iterate->bubble[i];
          }
        else
          {
            // Newton's method with backtracking: the bubble's local
            // problem is not convex where p d^2 J dominates K_bb
            Eigen::Matrix<double, dim, 1>   r_b, r_trial;
            Eigen::Matrix<double, dim, dim> K_bb, K_trial;
            double                          scale;
            const auto                      evaluate_at_u_b = [&]() {
              bubble_equation(table,
                              F0,
                              beta,
                              point_state,
                              material,
                              u_b,
                              r_b,
                              K_bb,
                              scale);
            };
            // Newton's iteration on r_b(u_b) = 0 from the u_b it finds;
            // false if it stalls
            const auto local_newton = [&]() {
              for (unsigned int it = 0; it < 25 && r_b.norm() > 1e-14 * scale;
                   ++it)
                {
                  const Eigen::Matrix<double, dim, 1> d = K_bb.lu().solve(r_b);
                  bool                                accepted = false;
                  for (double step = 1.; step > 1e-3 && !accepted; step /= 2)
                    {
                      Tensor<1, dim> trial       = u_b;
                      double         trial_scale = 0;
                      for (unsigned int i = 0; i < dim; ++i)
                        trial[i] -= step * d[i];
                      try
                        {
                          bubble_equation(table,
                                          F0,
                                          beta,
                                          point_state,
                                          material,
                                          trial,
                                          r_trial,
                                          K_trial,
                                          trial_scale);
                        }
                      catch (const ExceptionBase &)
                        {
                          continue; // J <= 0 somewhere: a shorter step
                        }
                      if (r_trial.norm() < r_b.norm())
                        {
                          u_b      = trial;
                          r_b      = r_trial;
                          K_bb     = K_trial;
                          scale    = trial_scale;
                          accepted = true;
                        }
                    }
                  // (no decrease at round-off level: converged)
                  if (!accepted && r_b.norm() <= 1e-10 * scale)
                    return true;
                  if (!accepted)
                    return false;
                }
              return true;
            };
            // from the last bubble where there is one (kept through
            // reset_local_fields()), else, or if that inverts the family
            // at the new displacement or the iteration stalls from there
            // (e.g. the bubble of a failed attempt before a step cut),
            // from u_b = 0
            bool started = false;
            if (iterate != nullptr && iterate->bubble.size() == dim)
              try
                {
                  for (unsigned int i = 0; i < dim; ++i)
                    u_b[i] = iterate->bubble[i];
                  evaluate_at_u_b();
                  started = local_newton();
                }
              catch (const ExceptionBase &)
                {
                  started = false;
                }
            if (!started)
              {
                u_b = Tensor<1, dim>();
                evaluate_at_u_b();
                AssertThrow(local_newton(),
                            ExcMessage(
                              "The bubble of an Unl+P1C family has no local "
                              "equilibrium at this state (its local Newton "
                              "iteration stalled). Reduce the load step."));
              }
            if (iterate != nullptr)
              {
                iterate->bubble.resize(dim);
                for (unsigned int i = 0; i < dim; ++i)
                  iterate->bubble[i] = u_b[i];
                iterate->at_equilibrium = false;
                iterate->bubble_S.clear();
              }
          }
        y_u.push_back(u_b);
      }
    const QuadratureTable<dim> &kernel_table = bubble ? augmented : table;

    // The u block (with p_q d theta/dF in the stress and p_q d^2 theta in
    // the tangent): the kernel, p_q handed as each point's state. The
    // bubble's condensation needs K_gb and K_bb also for the residual.
    const bool          full_tangent = (tangent != nullptr || bubble);
    const unsigned int  N_u = n_u * dim, N = N_u + 2 * n;
    Vector<double>      r_u;
    FullMatrix<double>  K_u;
    std::vector<double> trial_point_state(point_state.size());
    assemble_element(kernel_table,
                     y_u,
                     material,
                     r_u,
                     full_tangent ? &K_u : nullptr,
                     make_array_view(point_state),
                     make_array_view(trial_point_state));
    material.extract_material_state(trial_point_state, trial_state);
    Eigen::VectorXd r = Eigen::VectorXd::Zero(N);
    Eigen::MatrixXd K;
    for (unsigned int i = 0; i < N_u; ++i)
      r[i] = r_u[i];
    if (full_tangent)
      {
        K = Eigen::MatrixXd::Zero(N, N);
        for (unsigned int i = 0; i < N_u; ++i)
          for (unsigned int j = 0; j < N_u; ++j)
            K(i, j) = K_u(i, j);
      }

    // The p and Theta rows and their couplings
    for (unsigned int q = 0; q < n_q; ++q)
      {
        const double         w     = table.weights[q];
        const double        *pq    = &pi[q * n];
        const Tensor<2, dim> F     = deformation_gradient(kernel_table, q, y_u);
        const double         theta = split.volume_measure(F);
        const double dW = split.volumetric_strain_energy_derivative(Theta_q[q]);
        for (unsigned int a = 0; a < n; ++a)
          {
            r[N_u + a] += w * (theta - Theta_q[q]) * pq[a];
            r[N_u + n + a] += w * (dW - p_q[q]) * pq[a];
          }
        if (!full_tangent)
          continue;
        const Tensor<2, dim> D = split.volume_measure_derivative(F);
        const double         ddW =
          split.volumetric_strain_energy_second_derivative(Theta_q[q]);
        const Tensor<1, dim> *B = &kernel_table.trial[q * n_u];
        for (unsigned int b = 0; b < n_u; ++b)
          {
            const Tensor<1, dim> s = w * (D * B[b]);
            for (unsigned int c = 0; c < dim; ++c)
              for (unsigned int a = 0; a < n; ++a)
                {
                  K(b * dim + c, N_u + a) += s[c] * pq[a];
                  K(N_u + a, b * dim + c) += s[c] * pq[a];
                }
          }
        for (unsigned int a = 0; a < n; ++a)
          for (unsigned int b = 0; b < n; ++b)
            {
              const double pp = w * pq[a] * pq[b];
              K(N_u + a, N_u + n + b) -= pp;
              K(N_u + n + a, N_u + b) -= pp;
              K(N_u + n + a, N_u + n + b) += ddW * pp;
            }
      }

    // Condense the bubble (rows and columns n dim ... n dim + dim - 1).
    const unsigned int        N_g = N - (bubble ? dim : 0);
    std::vector<unsigned int> g(N_g);
    for (unsigned int i = 0, j = 0; i < N; ++i)
      if (!bubble || i < n * dim || i >= N_u)
        g[j++] = i;
    residual.reinit(N_g);
    if (tangent != nullptr)
      tangent->reinit(N_g, N_g);
    if (!bubble)
      {
        for (unsigned int i = 0; i < N_g; ++i)
          residual[i] = r[i];
        if (tangent != nullptr)
          for (unsigned int i = 0; i < N_g; ++i)
            for (unsigned int j = 0; j < N_g; ++j)
              (*tangent)(i, j) = K(i, j);
        return;
      }
    Eigen::MatrixXd K_gb(N_g, dim);
    Eigen::MatrixXd K_bb(dim, dim);
    Eigen::VectorXd r_b(dim);
    for (unsigned int i = 0; i < dim; ++i)
      {
        r_b[i] = r[n * dim + i];
        for (unsigned int j = 0; j < dim; ++j)
          K_bb(i, j) = K(n * dim + i, n * dim + j);
        for (unsigned int j = 0; j < N_g; ++j)
          K_gb(j, i) = K(g[j], n * dim + i);
      }
    const Eigen::PartialPivLU<Eigen::MatrixXd> K_bb_lu(K_bb);
    const Eigen::VectorXd                      a_b = -K_bb_lu.solve(r_b);
    const Eigen::MatrixXd S_b = -K_bb_lu.solve(K_gb.transpose());
    for (unsigned int i = 0; i < N_g; ++i)
      residual[i] = r[g[i]] + K_gb.row(i).dot(a_b);
    if (tangent == nullptr)
      return;
    const Eigen::MatrixXd KS = K_gb * S_b;
    for (unsigned int i = 0; i < N_g; ++i)
      for (unsigned int j = 0; j < N_g; ++j)
        (*tangent)(i, j) = K(g[i], g[j]) + KS(i, j);
    if (iterate != nullptr)
      {
        iterate->bubble_a.assign(a_b.data(), a_b.data() + dim);
        // row by row: S_b is column-major
        iterate->bubble_S.resize(dim * N_g);
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < N_g; ++j)
            iterate->bubble_S[i * N_g + j] = S_b(i, j);
      }
  }



  template QuadratureTable<2>
  with_bubble_node(const QuadratureTable<2> &);
  template QuadratureTable<3>
  with_bubble_node(const QuadratureTable<3> &);
  template double
  rest_volume_measure(const Materials::VolumetricSplit<2> &);
  template double
  rest_volume_measure(const Materials::VolumetricSplit<3> &);
  template std::vector<double>
  nodal_field_interpolation(const QuadratureTable<2> &);
  template std::vector<double>
  nodal_field_interpolation(const QuadratureTable<3> &);
  template void
  assemble_nodal_pressure_family(const QuadratureTable<2> &,
                                 const std::vector<Tensor<1, 2>> &,
                                 const std::vector<double> &,
                                 const std::vector<double> &,
                                 const Materials::VolumetricSplit<2> &,
                                 const bool,
                                 Vector<double> &,
                                 FullMatrix<double> *,
                                 CondensedFieldIterate *,
                                 const ArrayView<const double> &,
                                 const ArrayView<double> &);
  template void
  assemble_nodal_pressure_family(const QuadratureTable<3> &,
                                 const std::vector<Tensor<1, 3>> &,
                                 const std::vector<double> &,
                                 const std::vector<double> &,
                                 const Materials::VolumetricSplit<3> &,
                                 const bool,
                                 Vector<double> &,
                                 FullMatrix<double> *,
                                 CondensedFieldIterate *,
                                 const ArrayView<const double> &,
                                 const ArrayView<double> &);
} // namespace pg
