#include <pg/base/exceptions.h>
#include <pg/elements/cpd_interactions.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace pg
{
  namespace CPD
  {
    namespace
    {
      /** v embedded in 3-D (2-D vectors get z = 0). */
      template <int dim>
      Tensor<1, 3>
      embed(const Tensor<1, dim> &v)
      {
        Tensor<1, 3> w;
        for (unsigned int c = 0; c < dim; ++c)
          w[c] = v[c];
        return w;
      }

      /** The skew matrix [a]x with [a]x b = a x b. */
      Tensor<2, 3>
      skew(const Tensor<1, 3> &a)
      {
        Tensor<2, 3> S;
        S[0][1] = -a[2];
        S[0][2] = a[1];
        S[1][0] = a[2];
        S[1][2] = -a[0];
        S[2][0] = -a[1];
        S[2][1] = a[0];
        return S;
      }

      /** The leading dim x dim block of a 3-D matrix. */
      template <int dim>
      Tensor<2, dim> restrict(const Tensor<2, 3> &A)
      {
        Tensor<2, dim> B;
        for (unsigned int p = 0; p < dim; ++p)
          for (unsigned int q = 0; q < dim; ++q)
            B[p][q] = A[p][q];
        return B;
      }

      template <int dim>
      Tensor<1, dim> restrict(const Tensor<1, 3> &a)
      {
        Tensor<1, dim> b;
        for (unsigned int p = 0; p < dim; ++p)
          b[p] = a[p];
        return b;
      }
    } // namespace



    template <int dim, int n>
    double
    reference_measure(const std::array<Tensor<1, dim>, n> &Xi)
    {
      if constexpr (n == 1)
        return Xi[0].norm();
      else if constexpr (n == 2)
        return cross_product_3d(embed(Xi[0]), embed(Xi[1])).norm();
      else
        return std::abs(embed(Xi[0]) *
                        cross_product_3d(embed(Xi[1]), embed(Xi[2])));
    }



    template <int dim, int n>
    EdgeDerivatives<dim, n>
    interaction_derivatives(const double                         C,
                            const std::array<Tensor<1, dim>, n> &Xi,
                            const std::array<Tensor<1, dim>, n> &xi,
                            const bool                           with_hessian)
    {
      EdgeDerivatives<dim, n> d;
      const double            M = reference_measure<dim, n>(Xi);
      if constexpr (n == 1)
        {
          // psi_1 = C (l - L)^2 / (2 L), eqs. (23), (50), (65)
          const double l = xi[0].norm();
          const double s = C * (1. / M - 1. / l);
          d.energy       = 0.5 * C * (l - M) * (l - M) / M;
          d.gradient[0]  = s * xi[0];
          if (with_hessian)
            d.hessian[0][0] = s * unit_symmetric_tensor<dim>() +
                              (C / (l * l * l)) * outer_product(xi[0], xi[0]);
        }
      else if constexpr (n == 2)
        {
          // psi_2 = C (a - A)^2 / (2 A), a = |n|, n = xi^1 x xi^2 (24), (55)
          const Tensor<1, 3> x1 = embed(xi[0]), x2 = embed(xi[1]);
          const Tensor<1, 3> nv = cross_product_3d(x1, x2);
          const double       a  = nv.norm();
          const double       s  = C * (1. / M - 1. / a);
          d.energy              = 0.5 * C * (a - M) * (a - M) / M;
          // dn/dxi^1 = -[xi^2]x, dn/dxi^2 = [xi^1]x
          d.gradient[0] = restrict<dim>(s * cross_product_3d(x2, nv));
          d.gradient[1] = restrict<dim>(s * cross_product_3d(nv, x1));
          if (with_hessian)
            {
              const Tensor<2, 3> Hn = s * unit_symmetric_tensor<3>() +
                                      (C / (a * a * a)) * outer_product(nv, nv);
              const std::array<Tensor<2, 3>, 2> J = {{-skew(x2), skew(x1)}};
              for (unsigned int m = 0; m < 2; ++m)
                for (unsigned int p = 0; p < 2; ++p)
                  d.hessian[m][p] = restrict<dim>(transpose(J[m]) * Hn * J[p]);
              // sum_c (d psi / d n_c) d^2 n_c / d xi^1_p d xi^2_q = -s [n]x
              const Tensor<2, dim> mixed = restrict<dim>(-s * skew(nv));
              d.hessian[0][1] += mixed;
              d.hessian[1][0] += transpose(mixed);
            }
        }
      else
        {
          static_assert(n == 3, "interactions have 1, 2 or 3 edges");
          // psi_3 = C (v - V)^2 / (2 V), v = |w|, w = xi^1 . (xi^2 x xi^3)
          // (25), (60); d psi / dw = C (1/V - 1/v) w, d^2 psi / dw^2 = C/V
          const Tensor<1, 3> x1 = embed(xi[0]), x2 = embed(xi[1]),
                             x3                = embed(xi[2]);
          const std::array<Tensor<1, 3>, 3> dw = {{cross_product_3d(x2, x3),
                                                   cross_product_3d(x3, x1),
                                                   cross_product_3d(x1, x2)}};
          const double                      w  = x1 * dw[0];
          const double                      v  = std::abs(w);
          const double                      s  = C * (1. / M - 1. / v) * w;
          d.energy = 0.5 * C * (v - M) * (v - M) / M;
          for (unsigned int m = 0; m < 3; ++m)
            d.gradient[m] = restrict<dim>(s * dw[m]);
          if (with_hessian)
            {
              // d^2 w / d xi^m_p d xi^(m+1)_q = -[xi^(m+2)]x_pq (cyclic)
              const std::array<Tensor<1, 3>, 3> x = {{x1, x2, x3}};
              for (unsigned int m = 0; m < 3; ++m)
                for (unsigned int p = 0; p < 3; ++p)
                  {
                    Tensor<2, 3> H = (C / M) * outer_product(dw[m], dw[p]);
                    if (p == (m + 1) % 3)
                      H -= s * skew(x[(m + 2) % 3]);
                    else if (m == (p + 1) % 3)
                      H += s * skew(x[(p + 2) % 3]);
                    d.hessian[m][p] = restrict<dim>(H);
                  }
            }
        }
      return d;
    }
  } // namespace CPD



  namespace
  {
    /**
     * Add weight x (energy derivatives of the interaction with the local
     * nodes {0, nodes...}) to the family's residual and tangent: node 0 is
     * the master, xi^m = y[node m] - y[0].
     */
    template <int dim, int n>
    double
    add_interaction(const double                        C,
                    const double                        weight,
                    const std::array<std::uint16_t, n> &nodes,
                    const std::vector<Tensor<1, dim>>  &X,
                    const std::vector<Tensor<1, dim>>  &y,
                    Vector<double>                     *residual,
                    FullMatrix<double>                 *matrix)
    {
      std::array<Tensor<1, dim>, n> Xi, xi;
      for (unsigned int m = 0; m < n; ++m)
        {
          Xi[m] = X[nodes[m]] - X[0];
          xi[m] = y[nodes[m]] - y[0];
        }
      const auto d =
        CPD::interaction_derivatives<dim, n>(C, Xi, xi, matrix != nullptr);
      if (residual != nullptr)
        for (unsigned int m = 0; m < n; ++m)
          for (unsigned int c = 0; c < dim; ++c)
            {
              const double g = weight * d.gradient[m][c];
              (*residual)(nodes[m] * dim + c) += g;
              (*residual)(c) -= g;
            }
      if (matrix != nullptr)
        for (unsigned int m = 0; m < n; ++m)
          for (unsigned int p = 0; p < n; ++p)
            for (unsigned int c = 0; c < dim; ++c)
              for (unsigned int e = 0; e < dim; ++e)
                {
                  // xi^m = x^(nodes m) - x^0: the (0, 0), (0, p), (m, 0)
                  // blocks collect the negated sums
                  const double h = weight * d.hessian[m][p][c][e];
                  (*matrix)(nodes[m] * dim + c, nodes[p] * dim + e) += h;
                  (*matrix)(c, nodes[p] * dim + e) -= h;
                  (*matrix)(nodes[m] * dim + c, e) -= h;
                  (*matrix)(c, e) += h;
                }
      return weight * d.energy;
    }
  } // namespace



  template <int dim>
  CpdInteractions<dim>::CpdInteractions(const ParticleSet<dim> &particles,
                                        const FamilySet<dim>   &families,
                                        const CpdConstants     &constants,
                                        const double            horizon_factor,
                                        const double            horizon)
    : particles(particles)
    , families(families)
    , cpd(constants)
    , horizon_factor(horizon_factor)
    , horizon(horizon)
  {
    AssertThrow(cpd.C1 > 0,
                ExcBadParameter("CPD/C1",
                                std::to_string(cpd.C1),
                                "it must be positive: without one-neighbour "
                                "interactions triangles of equal area and "
                                "tetrahedra of equal volume have the same "
                                "energy, and the system is unstable (Javili "
                                "et al., section 4.4, Fig. 16)."));
    AssertThrow(dim == 3 || cpd.C3 == 0,
                ExcBadParameter("CPD/C3",
                                std::to_string(cpd.C3),
                                "three-neighbour interactions exist in 3-D "
                                "only; set it to 0 in a 2-D run."));

    // With mirror planes the vertices of an interaction may be images
    // (numbered from n_particles on, after every real particle): the
    // interaction is stored at its smallest (real) vertex, and only the
    // real vertices take its energy and count it in their quadrature.
    const unsigned int n_particles = particles.n_particles();
    for (auto &o : offsets)
      o.assign(n_particles + 1, 0);
    quadrature.assign(n_particles, {{0., 0., 0., 0.}});
    // sums over the ordered tuples at each particle of prod(beta V)
    std::vector<std::array<double, 3>> tuple_sums(n_particles, {{0, 0, 0}});

    // whether j is in the family of i; for an image i, reflect both so that
    // i becomes its original (no image has a family of its own)
    const auto is_neighbour = [&](const unsigned int i, const unsigned int j) {
      const unsigned int o = particles.original(i);
      const unsigned int r =
        (o == i ? j : particles.reflection(j, particles.mirror_mask(i)));
      const auto m = families.members(o);
      return r != numbers::invalid_unsigned_int &&
             std::binary_search(m.begin() + 1, m.end(), r);
    };
    const auto count =
      [&](const unsigned int v, const unsigned int order, const double tuples) {
        if (v < n_particles)
          quadrature[v][order] += tuples;
      };
    const double collinear = 1e-8;

    std::vector<char> adjacent;
    for (unsigned int a = 0; a < n_particles; ++a)
      {
        const auto         M = families.members(a);
        const unsigned int n = M.size();
        if (n < 2)
          {
            std::ostringstream where;
            where << particles.position(a);
            AssertThrow(false,
                        ExcMessage(
                          "CPD: particle " + std::to_string(a) + " at (" +
                          where.str() +
                          ") has no neighbour within its horizon. Increase "
                          "'Horizon factor' or 'Horizon' in subsection "
                          "'Discretization'."));
          }
        AssertThrow(n <= 65535, ExcMessage("CPD: a family has 65536 members"));
        for (unsigned int p = 1; p < n; ++p)
          quadrature[a][3] +=
            bond_factor(a, M[p]) * particles.member_volume(M[p]);

        // the first member with a larger index than the master
        unsigned int first = 1;
        while (first < n && M[first] < a)
          ++first;
        for (unsigned int p = first; p < n; ++p)
          if (bond_factor(a, M[p]) > 0)
            {
              vertices[0].push_back(p);
              count(a, 0, 1);
              count(M[p], 0, 1);
            }
        offsets[0][a + 1] = vertices[0].size();
        if (cpd.C2 != 0 || cpd.C3 != 0)
          {
            adjacent.assign(n * n, 0);
            for (unsigned int p = first; p < n; ++p)
              for (unsigned int q = p + 1; q < n; ++q)
                adjacent[p * n + q] =
                  is_neighbour(M[p], M[q]) && bond_factor(a, M[p]) > 0 &&
                  bond_factor(a, M[q]) > 0 && bond_factor(M[p], M[q]) > 0;
            const auto X = [&](const unsigned int p) {
              return particles.position(M[p]) - particles.position(a);
            };
            for (unsigned int p = first; p < n; ++p)
              for (unsigned int q = p + 1; q < n; ++q)
                if (adjacent[p * n + q])
                  {
                    const std::array<Tensor<1, dim>, 2> Xi = {{X(p), X(q)}};
                    const double A = CPD::reference_measure<dim, 2>(Xi);
                    if (cpd.C2 != 0 &&
                        A > collinear * Xi[0].norm() * Xi[1].norm())
                      {
                        vertices[1].push_back(p);
                        vertices[1].push_back(q);
                        for (const unsigned int v : {a, M[p], M[q]})
                          count(v, 1, 2);
                      }
                    if (dim == 3 && cpd.C3 != 0)
                      for (unsigned int r = q + 1; r < n; ++r)
                        if (adjacent[p * n + r] && adjacent[q * n + r])
                          {
                            const std::array<Tensor<1, dim>, 3> Xi3 = {
                              {X(p), X(q), X(r)}};
                            if (CPD::reference_measure<dim, 3>(Xi3) >
                                collinear * Xi3[0].norm() * Xi3[1].norm() *
                                  Xi3[2].norm())
                              {
                                vertices[2].push_back(p);
                                vertices[2].push_back(q);
                                vertices[2].push_back(r);
                                for (const unsigned int v :
                                     {a, M[p], M[q], M[r]})
                                  count(v, 2, 6);
                              }
                          }
                  }
          }
        offsets[1][a + 1] = vertices[1].size() / 2;
        offsets[2][a + 1] = vertices[2].size() / 3;
      }

    // prod(beta V) of the other vertices of an interaction, seen from v
    const auto others = [&](const unsigned int               v,
                            const std::vector<unsigned int> &tuple) {
      double product = 1;
      for (const unsigned int m : tuple)
        if (m != v)
          product *= bond_factor(v, m) * particles.member_volume(m);
      return product;
    };
    std::vector<unsigned int> tuple;
    const auto                for_each_interaction = [&](const auto &f) {
      for (unsigned int order = 1; order < 3; ++order)
        for (unsigned int a = 0; a < n_particles; ++a)
          {
            const auto M = families.members(a);
            for (std::size_t e = offsets[order][a]; e < offsets[order][a + 1];
                 ++e)
              {
                tuple.assign(1, a);
                for (unsigned int m = 0; m <= order; ++m)
                  tuple.push_back(M[vertices[order][e * (order + 1) + m]]);
                f(order, e, tuple);
              }
          }
    };
    // ordered tuples: 2 orderings of a pair, 6 of a triplet
    for_each_interaction([&](const unsigned int order,
                             const std::size_t,
                             const std::vector<unsigned int> &t) {
      for (const unsigned int v : t)
        if (v < n_particles)
          tuple_sums[v][order] += (order == 1 ? 2. : 6.) * others(v, t);
    });

    // The weights sum over the real vertices v only, with the volume V^v
    // of the model (a share 1/2^m of the member volume for v on m mirror
    // planes; the members' volumes are the full body's). Then the energy is
    // sum_v V^v Psi^v over the real particles, the full body's divided by
    // the number of its mirrored copies.
    // bonds: 1/2 (V^a w_1^a(i) + V^i w_1^i(a)) with w_1^a(i) = beta V^i
    for (unsigned int a = 0; a < n_particles; ++a)
      {
        const auto M = families.members(a);
        for (std::size_t e = offsets[0][a]; e < offsets[0][a + 1]; ++e)
          {
            const unsigned int i = M[vertices[0][e]];
            const double       w =
              (i < n_particles ?
                 0.5 * (particles.volume(a) * particles.member_volume(i) +
                        particles.volume(i) * particles.member_volume(a)) :
                 0.5 * particles.volume(a) * particles.member_volume(i));
            weights[0].push_back(bond_factor(a, i) * w);
          }
      }
    // triangles: 1/3 sum_v V^v 2 w_2^v, tetrahedra: 1/4 sum_v V^v 6 w_3^v,
    // w_n^v = (V_H^v)^n prod(beta V) / tuple_sums
    weights[1].resize(offsets[1].back());
    weights[2].resize(offsets[2].back());
    for_each_interaction([&](const unsigned int               order,
                             const std::size_t                e,
                             const std::vector<unsigned int> &t) {
      double w = 0;
      for (const unsigned int v : t)
        if (v < n_particles)
          w += particles.volume(v) * std::pow(quadrature[v][3], order + 1) *
               others(v, t) / tuple_sums[v][order];
      weights[order][e] = (order == 1 ? 2. / 3. : 6. / 4.) * w;
    });
  }



  template <int dim>
  double
  CpdInteractions<dim>::bond_factor(const unsigned int a,
                                    const unsigned int i) const
  {
    if (!cpd.partial_volumes)
      return 1.;
    const double h     = 0.5 * (particles.spacing(a) + particles.spacing(i));
    const double delta = horizon_factor * h + horizon;
    const double xi    = (particles.position(i) - particles.position(a)).norm();
    return std::clamp((delta + 0.5 * h - xi) / h, 0., 1.);
  }



  template <int dim>
  double
  CpdInteractions<dim>::evaluate(const unsigned int                 k,
                                 const std::vector<Tensor<1, dim>> &y,
                                 Vector<double>                    *residual,
                                 FullMatrix<double> *matrix) const
  {
    const auto                  M = families.members(k);
    std::vector<Tensor<1, dim>> X(M.size());
    for (unsigned int b = 0; b < M.size(); ++b)
      X[b] = particles.position(M[b]) - particles.position(k);

    double E = 0;
    for (std::size_t e = offsets[0][k]; e < offsets[0][k + 1]; ++e)
      E += add_interaction<dim, 1>(cpd.C1,
                                   weights[0][e],
                                   {{vertices[0][e]}},
                                   X,
                                   y,
                                   residual,
                                   matrix);
    for (std::size_t e = offsets[1][k]; e < offsets[1][k + 1]; ++e)
      E +=
        add_interaction<dim, 2>(cpd.C2,
                                weights[1][e],
                                {{vertices[1][2 * e], vertices[1][2 * e + 1]}},
                                X,
                                y,
                                residual,
                                matrix);
    if constexpr (dim == 3)
      for (std::size_t e = offsets[2][k]; e < offsets[2][k + 1]; ++e)
        E += add_interaction<dim, 3>(cpd.C3,
                                     weights[2][e],
                                     {{vertices[2][3 * e],
                                       vertices[2][3 * e + 1],
                                       vertices[2][3 * e + 2]}},
                                     X,
                                     y,
                                     residual,
                                     matrix);
    return E;
  }



  template <int dim>
  void
  CpdInteractions<dim>::assemble(const unsigned int                 k,
                                 const std::vector<Tensor<1, dim>> &y,
                                 Vector<double>                    &residual,
                                 FullMatrix<double> *matrix) const
  {
    const unsigned int n = families.members(k).size() * dim;
    residual.reinit(n);
    if (matrix != nullptr)
      matrix->reinit(n, n);
    evaluate(k, y, &residual, matrix);
  }



  template <int dim>
  double
  CpdInteractions<dim>::energy(const unsigned int                 k,
                               const std::vector<Tensor<1, dim>> &y) const
  {
    return evaluate(k, y, nullptr, nullptr);
  }



  template <int dim>
  std::array<std::size_t, 3>
  CpdInteractions<dim>::n_interactions() const
  {
    return {{offsets[0].back(), offsets[1].back(), offsets[2].back()}};
  }



  template <int dim>
  std::array<std::size_t, 3>
  CpdInteractions<dim>::n_interactions(const unsigned int k) const
  {
    return {{offsets[0][k + 1] - offsets[0][k],
             offsets[1][k + 1] - offsets[1][k],
             offsets[2][k + 1] - offsets[2][k]}};
  }



  template <int dim>
  std::vector<std::pair<unsigned int, unsigned int>>
  CpdInteractions<dim>::coupled_members(const unsigned int k) const
  {
    std::vector<std::pair<unsigned int, unsigned int>> pairs;
    for (unsigned int order = 1; order < 3; ++order)
      for (std::size_t e = offsets[order][k]; e < offsets[order][k + 1]; ++e)
        for (unsigned int m = 0; m <= order; ++m)
          for (unsigned int l = m + 1; l <= order; ++l)
            pairs.emplace_back(vertices[order][(order + 1) * e + m],
                               vertices[order][(order + 1) * e + l]);
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    return pairs;
  }



  template <int dim>
  std::array<double, 4>
  CpdInteractions<dim>::point_quadrature(const unsigned int v) const
  {
    return quadrature[v];
  }



  template <int dim>
  const CpdConstants &
  CpdInteractions<dim>::constants() const
  {
    return cpd;
  }



  template class CpdInteractions<2>;
  template class CpdInteractions<3>;
  namespace CPD
  {
    template EdgeDerivatives<2, 1>
    interaction_derivatives<2, 1>(const double,
                                  const std::array<Tensor<1, 2>, 1> &,
                                  const std::array<Tensor<1, 2>, 1> &,
                                  const bool);
    template EdgeDerivatives<2, 2>
    interaction_derivatives<2, 2>(const double,
                                  const std::array<Tensor<1, 2>, 2> &,
                                  const std::array<Tensor<1, 2>, 2> &,
                                  const bool);
    template EdgeDerivatives<3, 1>
    interaction_derivatives<3, 1>(const double,
                                  const std::array<Tensor<1, 3>, 1> &,
                                  const std::array<Tensor<1, 3>, 1> &,
                                  const bool);
    template EdgeDerivatives<3, 2>
    interaction_derivatives<3, 2>(const double,
                                  const std::array<Tensor<1, 3>, 2> &,
                                  const std::array<Tensor<1, 3>, 2> &,
                                  const bool);
    template EdgeDerivatives<3, 3>
    interaction_derivatives<3, 3>(const double,
                                  const std::array<Tensor<1, 3>, 3> &,
                                  const std::array<Tensor<1, 3>, 3> &,
                                  const bool);
  } // namespace CPD
} // namespace pg
