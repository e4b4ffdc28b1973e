// A material with history, defined and registered in this file only (the
// recipe of doc/adding-a-material.md): 'maximum strain damage', linear
// elasticity degraded by d(kappa) = kappa / (kappa + kappa_0), where the
// state kappa is the largest strain norm |eps| seen so far and kappa_0 is
// the material's own entry 'Damage strain'. The kernel drives it on a Q1
// cell (dense Bubnov-Galerkin tangent) and on a table with separate test
// vectors (point-by-point tangent), both in one QuadraturePointHistory:
// step 1 accepted (commit), step 2 with a larger load whose Newton
// iteration fails (revert, bit for bit), a cut step accepted (commit), and
// an unloading step that keeps the memory. The committed states are checked
// exactly, the tangent against finite differences at a state, and the
// stateful evaluation of the three stateless materials against the
// stateless one.

#include <pg/elements/q1_cell.h>
#include <pg/elements/quadrature_table.h>
#include <pg/history/quadrature_point_history.h>
#include <pg/materials/material_registry.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include "../tests.h"

#include <cstring>

using namespace pg;

namespace pg
{
  namespace Materials
  {
    /**
     * P = (1 - d) sigma(eps), eps = sym(F - I), sigma = lambda tr(eps) 1 +
     * 2 mu eps, d = kappa / (kappa + kappa_0), with the state [kappa, d],
     * kappa = max(kappa_committed, |eps|). On loading (|eps| > kappa_c)
     * A = (1 - d) C - d'(kappa) sigma (x) eps / |eps|, else (1 - d) C.
     */
    template <int dim>
    class MaximumStrainDamage : public Material<dim>
    {
    public:
      MaximumStrainDamage(const Parameters::Material &parameters)
        : lambda(parameters.lambda())
        , mu(parameters.mu())
        , kappa_0(parameters.model_double("Damage strain"))
      {
        AssertThrow(kappa_0 > 0.,
                    ExcBadParameter("Material/maximum strain damage/Damage "
                                    "strain",
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
      }

      static void
      parse_parameters(ParameterHandler &prm, Parameters::Material &parameters)
      {
        parameters.model_entries["Damage strain"] = prm.get("Damage strain");
      }

      /** -d' sigma (x) eps / |eps| is not major-symmetric. */
      bool
      tangent_has_major_symmetry() const override
      {
        return false;
      }

      unsigned int
      n_state_variables() const override
      {
        return 2;
      }

      void
      evaluate_with_state(const Tensor<2, dim>          &F,
                          const ArrayView<const double> &committed,
                          const ArrayView<double>       &trial,
                          Tensor<2, dim>                &P,
                          Tensor<4, dim>                *A) const override
      {
        const Tensor<2, dim> eps     = strain(F);
        const double         e       = eps.norm();
        const bool           loading = e > committed[0];
        const double         kappa   = loading ? e : committed[0];
        const double         d       = kappa / (kappa + kappa_0);
        trial[0]                     = kappa;
        trial[1]                     = d;
        const Tensor<2, dim> sigma   = elastic_stress(eps);
        P                            = (1. - d) * sigma;
        if (A == nullptr)
          return;
        const double d_prime =
          kappa_0 / ((kappa + kappa_0) * (kappa + kappa_0));
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            for (unsigned int c = 0; c < dim; ++c)
              for (unsigned int k = 0; k < dim; ++k)
                (*A)[a][b][c][k] =
                  (1. - d) * ((a == b && c == k ? lambda : 0.) +
                              (a == c && b == k ? mu : 0.) +
                              (a == k && b == c ? mu : 0.)) -
                  (loading ? d_prime * sigma[a][b] * eps[c][k] / e : 0.);
      }

      // The stateless functions: at the initial state kappa = 0.
      void
      evaluate(const Tensor<2, dim> &F,
               Tensor<2, dim>       &P,
               Tensor<4, dim>       &A) const override
      {
        const double initial[2] = {0., 0.};
        double       trial[2];
        evaluate_with_state(F,
                            make_array_view(initial, initial + 2),
                            make_array_view(trial, trial + 2),
                            P,
                            &A);
      }

      Tensor<2, dim>
      first_piola_stress(const Tensor<2, dim> &F) const override
      {
        Tensor<2, dim> P;
        Tensor<4, dim> A;
        evaluate(F, P, A);
        return P;
      }

      Tensor<2, 3>
      cauchy_stress(const Tensor<2, dim> &F) const override
      {
        const Tensor<2, dim> P = first_piola_stress(F);
        Tensor<2, 3>         sigma;
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            sigma[a][b] = P[a][b];
        return sigma;
      }

      double
      strain_energy_density(const Tensor<2, dim> &F) const override
      {
        return 0.5 * scalar_product(first_piola_stress(F), strain(F));
      }

    private:
      static Tensor<2, dim>
      strain(const Tensor<2, dim> &F)
      {
        const Tensor<2, dim> I = unit_symmetric_tensor<dim>();
        return 0.5 * (F + transpose(F)) - I;
      }

      Tensor<2, dim>
      elastic_stress(const Tensor<2, dim> &eps) const
      {
        const Tensor<2, dim> I = unit_symmetric_tensor<dim>();
        return lambda * trace(eps) * I + 2. * mu * eps;
      }

      const double lambda, mu, kappa_0;
    };

    PG_REGISTER_MATERIAL(MaximumStrainDamage,
                         "maximum strain damage",
                         "test only: elasticity degraded by the largest "
                         "strain so far")
  } // namespace Materials
} // namespace pg



/** A bitwise copy of @p values, for exact comparisons. */
std::vector<double>
copy_of(const ArrayView<const double> &values)
{
  return std::vector<double>(values.begin(), values.end());
}



bool
bitwise_equal(const std::vector<double> &a, const std::vector<double> &b)
{
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}



/** Two tables: a Q1 cell and a table with separate test vectors. */
struct Tables
{
  std::vector<QuadratureTable<2>>        tables;
  std::vector<std::vector<Tensor<1, 2>>> X; // nodes relative to node 0
};



Tables
make_tables()
{
  Tables result;
  // The Q1 cell [0, 2] x [0, 1] with 2 x 2 Gauss points.
  Triangulation<2> tria;
  GridGenerator::hyper_rectangle(tria, Point<2>(0, 0), Point<2>(2, 1));
  FE_Q<2>     fe(1);
  QGauss<2>   quadrature(2);
  FEValues<2> fe_values(fe,
                        quadrature,
                        update_gradients | update_JxW_values |
                          update_quadrature_points);
  fe_values.reinit(tria.begin_active());
  QuadratureTable<2> q1;
  fill_q1_table(fe_values, q1);
  std::vector<Tensor<1, 2>> X_q1;
  for (unsigned int v = 0; v < 4; ++v)
    X_q1.push_back(tria.begin_active()->vertex(v) -
                   tria.begin_active()->vertex(0));
  result.tables.push_back(q1);
  result.X.push_back(X_q1);

  // Three points of a 'family' of the nodes (0,0), (1,0), (0,1): the trial
  // vectors of the linear interpolant (they sum to zero), and two test
  // vectors per point, as for PPG.
  QuadratureTable<2> family;
  family.reinit(3, false);
  const std::vector<Tensor<1, 2>> B = {Tensor<1, 2>({-1., -1.}),
                                       Tensor<1, 2>({1., 0.}),
                                       Tensor<1, 2>({0., 1.})};
  for (unsigned int q = 0; q < 3; ++q)
    {
      family.add_point(1. / 6., B, Point<2>(0.2 * q, 0.1 * q));
      family.add_test_vector(q, B[q]);
      family.add_test_vector((q + 1) % 3, 0.5 * B[(q + 1) % 3]);
    }
  result.tables.push_back(family);
  result.X.push_back(
    {Tensor<1, 2>(), Tensor<1, 2>({1., 0.}), Tensor<1, 2>({0., 1.})});
  return result;
}



/** y = X + u with u = (s X_0 + 0.3 s X_1, -0.2 s X_1). */
std::vector<Tensor<1, 2>>
deformed(const std::vector<Tensor<1, 2>> &X, const double s)
{
  std::vector<Tensor<1, 2>> y(X);
  for (Tensor<1, 2> &v : y)
    {
      const Tensor<1, 2> x = v;
      v[0] += s * x[0] + 0.3 * s * x[1];
      v[1] += -0.2 * s * x[1];
    }
  return y;
}



/** Assemble every element of @p tables at load @p s with the history. */
void
assemble_all(const Tables                    &tables,
             const Materials::Material<2>    &material,
             QuadraturePointHistory          &history,
             const double                     s,
             std::vector<Vector<double>>     &residuals,
             std::vector<FullMatrix<double>> &tangents)
{
  residuals.resize(tables.tables.size());
  tangents.resize(tables.tables.size());
  for (unsigned int g = 0; g < tables.tables.size(); ++g)
    assemble_element(tables.tables[g],
                     deformed(tables.X[g], s),
                     material,
                     residuals[g],
                     &tangents[g],
                     history.committed(g, 0),
                     history.trial(g, 0));
}



/** Check that the trial kappa of every point is max(committed, |eps_q|). */
void
check_trial(const Tables              &tables,
            QuadraturePointHistory    &history,
            const std::vector<double> &committed_before,
            const double               s,
            const double               kappa_0)
{
  unsigned int i = 0;
  for (unsigned int g = 0; g < tables.tables.size(); ++g)
    for (unsigned int q = 0; q < history.n_points(g, 0); ++q, ++i)
      {
        const Tensor<2, 2> F =
          deformation_gradient(tables.tables[g], q, deformed(tables.X[g], s));
        const Tensor<2, 2> I     = unit_symmetric_tensor<2>();
        const double       e     = (0.5 * (F + transpose(F)) - I).norm();
        const double       kappa = std::max(committed_before[2 * i], e);
        AssertThrow(history.trial(g, 0, q)[0] == kappa, ExcInternalError());
        AssertThrow(history.trial(g, 0, q)[1] == kappa / (kappa + kappa_0),
                    ExcInternalError());
      }
}



int
main()
{
  initlog();
  const double kappa_0 = 0.004;

  // The material by name, its own entry parsed from subsection
  // 'Material/maximum strain damage'.
  ParameterHandler prm;
  Parameters::Material::declare_parameters(prm);
  prm.parse_input_from_string("subsection Material\n"
                              "  set Model = maximum strain damage\n"
                              "  set Young's modulus = 100\n"
                              "  subsection maximum strain damage\n"
                              "    set Damage strain = 0.004\n"
                              "  end\n"
                              "end\n");
  Parameters::Material parameters;
  parameters.parse_parameters(prm);
  AssertThrow(parameters.model_double("Damage strain") == kappa_0,
              ExcInternalError());
  const std::unique_ptr<Materials::Material<2>> material =
    Materials::create_material<2>(parameters);
  AssertThrow(material->n_state_variables() == 2, ExcInternalError());
  AssertThrow(Materials::material_registry().names().back() ==
                "maximum strain damage",
              ExcInternalError());
  deallog << "registered: " << Materials::material_registry().listing()
          << std::endl;

  const Tables           tables = make_tables();
  QuadraturePointHistory history;
  history.reinit({{tables.tables[0].n_points()}, {tables.tables[1].n_points()}},
                 material->n_state_variables(),
                 [&](const ArrayView<double> &state) {
                   material->initialize_state(state);
                 });
  AssertThrow(history.n_groups() == 2 && history.n_points(0, 0) == 4 &&
                history.n_points(1, 0) == 3 &&
                history.committed_values().size() == 14 &&
                history.committed(1, 0).data() ==
                  history.committed(0, 0).data() + 8 &&
                history.memory_consumption() > 28 * sizeof(double),
              ExcInternalError());
  for (const double v : history.committed_values())
    AssertThrow(v == 0., ExcInternalError());

  std::vector<Vector<double>>     r;
  std::vector<FullMatrix<double>> K;
  const auto committed = [&]() { return history.committed_values(); };

  // Step 1, load 0.01: accepted.
  std::vector<double> before = committed();
  assemble_all(tables, *material, history, 0.01, r, K);
  check_trial(tables, history, before, 0.01, kappa_0);
  AssertThrow(bitwise_equal(committed(), before), ExcInternalError());
  history.commit();
  const std::vector<double> step_1 = committed();
  check_trial(tables, history, before, 0.01, kappa_0);
  deallog << "step 1 committed: kappa = " << step_1[0] << ", d = " << step_1[1]
          << std::endl;

  // Step 2, load 0.03: the trial state grows, Newton fails -> revert.
  assemble_all(tables, *material, history, 0.03, r, K);
  check_trial(tables, history, step_1, 0.03, kappa_0);
  AssertThrow(history.trial(0, 0, 0)[0] > step_1[0], ExcInternalError());
  AssertThrow(bitwise_equal(committed(), step_1), ExcInternalError());
  history.revert();
  AssertThrow(bitwise_equal(copy_of(history.trial(0, 0)),
                            copy_of(history.committed(0, 0))) &&
                bitwise_equal(copy_of(history.trial(1, 0)),
                              copy_of(history.committed(1, 0))) &&
                bitwise_equal(committed(), step_1),
              ExcInternalError());
  deallog << "step 2 reverted: trial = committed of step 1, bit for bit"
          << std::endl;

  // The cut step, load 0.02: accepted.
  assemble_all(tables, *material, history, 0.02, r, K);
  check_trial(tables, history, step_1, 0.02, kappa_0);
  history.commit();
  const std::vector<double> step_2 = committed();
  check_trial(tables, history, step_1, 0.02, kappa_0);
  AssertThrow(step_2[0] > step_1[0], ExcInternalError());
  deallog << "cut step committed: kappa = " << step_2[0]
          << ", d = " << step_2[1] << std::endl;

  // Unloading to 0.005: the memory stays, and the stress is the elastic
  // one times (1 - d) of the committed kappa (the deformation is affine,
  // so every point has the same F).
  assemble_all(tables, *material, history, 0.005, r, K);
  check_trial(tables, history, step_2, 0.005, kappa_0);
  AssertThrow(bitwise_equal(copy_of(history.trial(0, 0)),
                            std::vector<double>(step_2.begin(),
                                                step_2.begin() + 8)),
              ExcInternalError());
  {
    const std::unique_ptr<Materials::Material<2>> elastic =
      Materials::create_material<2>([&]() {
        Parameters::Material p = parameters;
        p.model                = "linear elastic";
        return p;
      }());
    for (unsigned int g = 0; g < 2; ++g)
      {
        Vector<double> r_elastic;
        assemble_element(tables.tables[g],
                         deformed(tables.X[g], 0.005),
                         *elastic,
                         r_elastic,
                         nullptr);
        r_elastic *= 1. - step_2[1];
        r_elastic -= r[g];
        AssertThrow(r_elastic.linfty_norm() <= 1e-13 * r[g].linfty_norm(),
                    ExcInternalError());
      }
    deallog << "unloading: kappa kept, residual = (1 - d) x elastic residual"
            << std::endl;
  }

  // The tangent at a committed state, against central differences of the
  // residual (the committed state fixed), on loading (0.03 > kappa_c) and
  // unloading (0.005), for both tables, and the residual-only path.
  for (const double s : {0.03, 0.005})
    for (unsigned int g = 0; g < 2; ++g)
      {
        const QuadratureTable<2> &table = tables.tables[g];
        std::vector<Tensor<1, 2>> y     = deformed(tables.X[g], s);
        Vector<double>            r0, rp, rm;
        FullMatrix<double>        K0;
        assemble_element(table,
                         y,
                         *material,
                         r0,
                         &K0,
                         history.committed(g, 0),
                         history.trial(g, 0));
        const std::vector<double> trial_with_tangent =
          copy_of(history.trial(g, 0));
        assemble_element(table,
                         y,
                         *material,
                         rp,
                         nullptr,
                         history.committed(g, 0),
                         history.trial(g, 0));
        AssertThrow(bitwise_equal(copy_of(history.trial(g, 0)),
                                  trial_with_tangent),
                    ExcInternalError());
        rp -= r0;
        AssertThrow(rp.linfty_norm() == 0., ExcInternalError());
        double       error = 0., scale = K0.linfty_norm();
        const double h = 1e-7;
        for (unsigned int b = 0; b < table.n_nodes; ++b)
          for (unsigned int c = 0; c < 2; ++c)
            {
              y[b][c] += h;
              assemble_element(table,
                               y,
                               *material,
                               rp,
                               nullptr,
                               history.committed(g, 0),
                               history.trial(g, 0));
              y[b][c] -= 2 * h;
              assemble_element(table,
                               y,
                               *material,
                               rm,
                               nullptr,
                               history.committed(g, 0),
                               history.trial(g, 0));
              y[b][c] += h;
              for (unsigned int i = 0; i < r0.size(); ++i)
                error = std::max(error,
                                 std::abs((rp[i] - rm[i]) / (2 * h) -
                                          K0(i, b * 2 + c)));
            }
        print_bound("load " + std::to_string(s) + ", table " +
                      std::to_string(g) +
                      ": tangent vs finite differences, relative",
                    error / scale,
                    1e-6);
        AssertThrow(error <= 1e-6 * scale, ExcInternalError());
        // The loading tangent is not the elastic-damage secant.
        AssertThrow(s == 0.005 || K0.linfty_norm() > 0., ExcInternalError());
      }
  history.revert();
  AssertThrow(bitwise_equal(committed(), step_2), ExcInternalError());

  // The existing materials: the stateful evaluation is the stateless one,
  // point by point and through the kernel with and without empty slices.
  for (const std::string model :
       {"linear elastic", "saint venant kirchhoff", "neo-Hooke"})
    {
      Parameters::Material p = parameters;
      p.model                = model;
      const std::unique_ptr<Materials::Material<2>> m =
        Materials::create_material<2>(p);
      AssertThrow(m->n_state_variables() == 0, ExcInternalError());
      Tensor<2, 2> F = unit_symmetric_tensor<2>();
      F[0][0] += 0.1, F[0][1] += 0.05, F[1][1] -= 0.02;
      Tensor<2, 2> P1, P2, P3;
      Tensor<4, 2> A1, A2;
      m->evaluate(F, P1, A1);
      m->evaluate_with_state(F, {}, {}, P2, &A2);
      m->evaluate_with_state(F, {}, {}, P3, nullptr);
      AssertThrow(P1 == P2 && A1 == A2 && P3 == m->first_piola_stress(F),
                  ExcInternalError());
      for (unsigned int g = 0; g < 2; ++g)
        {
          Vector<double>     ra, rb;
          FullMatrix<double> Ka, Kb;
          const auto         y = deformed(tables.X[g], 0.02);
          assemble_element(tables.tables[g], y, *m, ra, &Ka);
          assemble_element(tables.tables[g], y, *m, rb, &Kb, {}, {});
          rb -= ra;
          Kb.add(-1., Ka);
          AssertThrow(rb.linfty_norm() == 0. && Kb.frobenius_norm() == 0.,
                      ExcInternalError());
        }
      deallog << model << ": stateful evaluation = stateless, exactly"
              << std::endl;
    }

  // A stateful material without state slices is refused.
  try
    {
      Vector<double> r_missing;
      assemble_element(tables.tables[0],
                       deformed(tables.X[0], 0.01),
                       *material,
                       r_missing,
                       nullptr);
      AssertThrow(false, ExcInternalError());
    }
  catch (const ExcMessage &e)
    {
      const std::string text = exception_message(e);
      AssertThrow(text.find("needs state slices of 8 values") !=
                    std::string::npos,
                  ExcInternalError());
      deallog << "no slices: " << text.substr(text.find_first_not_of(' '))
              << std::endl;
    }
}
