// The point history through a step cut, in a whole run: a history-carrying
// test material (registered here, as doc/adding-a-material.md says) whose
// stress depends on the deformation gradient F_c of the last accepted step,
//   P = sigma(eps(F)) + eta (F - F_c),
// and whose update fails (throws, like a return mapping that does not
// converge) when |F - F_c| exceeds a limit. With one load step the first
// attempt fails, the step is cut to t = 0.5 and grown again to t = 1: the
// result must equal the run with two load steps (same accepted path) to
// round-off, and differ from the single-step run without the limit (the
// history matters). For FEM (Q1 Gauss points) and VCBCPBG V5sn Unl (family
// evaluation points).

#include <pg/materials/material_registry.h>

#include "../tests.h"
#include "problem_fixture.h"

namespace pg
{
  namespace Materials
  {
    template <int dim>
    class IncrementLimitedViscous : public Material<dim>
    {
    public:
      IncrementLimitedViscous(const Parameters::Material &parameters)
        : lambda(parameters.lambda())
        , mu(parameters.mu())
        , eta(parameters.model_double("Eta"))
        , limit(parameters.model_double("Increment limit"))
      {}

      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Eta", "0.5", Patterns::Double(0.), "eta");
        prm.declare_entry("Increment limit",
                          "1",
                          Patterns::Double(0.),
                          "largest |F - F_c| of an update");
      }

      static void
      parse_parameters(ParameterHandler &prm, Parameters::Material &parameters)
      {
        parameters.model_entries["Eta"] = prm.get("Eta");
        parameters.model_entries["Increment limit"] =
          prm.get("Increment limit");
      }

      unsigned int
      n_state_variables() const override
      {
        return dim * dim;
      }

      void
      initialize_state(const ArrayView<double> &state) const override
      {
        for (unsigned int i = 0; i < dim * dim; ++i)
          state[i] = (i % (dim + 1) == 0 ? 1. : 0.);
      }

      void
      evaluate_with_state(const Tensor<2, dim>          &F,
                          const ArrayView<const double> &committed,
                          const ArrayView<double>       &trial,
                          Tensor<2, dim>                &P,
                          Tensor<4, dim>                *A) const override
      {
        Tensor<2, dim> F_c;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            F_c[i][j] = committed[i * dim + j];
        AssertThrow((F - F_c).norm() <= limit,
                    ExcMessage("the update of the test material failed"));
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            trial[i * dim + j] = F[i][j];
        P = elastic_stress(F) + eta * (F - F_c);
        if (A != nullptr)
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              for (unsigned int c = 0; c < dim; ++c)
                for (unsigned int k = 0; k < dim; ++k)
                  (*A)[a][b][c][k] = (a == b && c == k ? lambda : 0.) +
                                     (a == c && b == k ? mu + eta : 0.) +
                                     (a == k && b == c ? mu : 0.);
      }

      // The stateless functions: the initial state F_c = 1, no limit.
      void
      evaluate(const Tensor<2, dim> &F,
               Tensor<2, dim>       &P,
               Tensor<4, dim>       &A) const override
      {
        P = first_piola_stress(F);
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            for (unsigned int c = 0; c < dim; ++c)
              for (unsigned int k = 0; k < dim; ++k)
                A[a][b][c][k] = (a == b && c == k ? lambda : 0.) +
                                (a == c && b == k ? mu + eta : 0.) +
                                (a == k && b == c ? mu : 0.);
      }

      Tensor<2, dim>
      first_piola_stress(const Tensor<2, dim> &F) const override
      {
        return elastic_stress(F) +
               eta * (F - Tensor<2, dim>(unit_symmetric_tensor<dim>()));
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
        const Tensor<2, dim> I   = unit_symmetric_tensor<dim>();
        const Tensor<2, dim> eps = 0.5 * (F + transpose(F)) - I;
        return 0.5 * scalar_product(elastic_stress(F), eps);
      }

    private:
      Tensor<2, dim>
      elastic_stress(const Tensor<2, dim> &F) const
      {
        const Tensor<2, dim> I   = unit_symmetric_tensor<dim>();
        const Tensor<2, dim> eps = 0.5 * (F + transpose(F)) - I;
        return lambda * trace(eps) * I + 2. * mu * eps;
      }

      const double lambda, mu, eta, limit;
    };

    PG_REGISTER_MATERIAL(IncrementLimitedViscous,
                         "increment limited viscous",
                         "test only: P = sigma + eta (F - F_c), fails for "
                         "large increments")
  } // namespace Materials
} // namespace pg

namespace
{
  std::string
  settings(const std::string &formulation,
           const unsigned int load_steps,
           const double       limit)
  {
    return "set Dimension = 2\n"
           "subsection Geometry\n  set Mesh = hyper rectangle\n"
           "  set Subdivisions = 6, 6\n  set Distortion = 0.2\nend\n"
           "subsection Discretization\n  set Formulation = " +
           formulation +
           "\nend\n"
           "subsection Material\n  set Model = increment limited viscous\n"
           "  set Young's modulus = 1\n  set Poisson's ratio = 0.3\n"
           "  subsection increment limited viscous\n    set Eta = 0.5\n"
           "    set Increment limit = " +
           std::to_string(limit) +
           "\n  end\nend\n"
           "subsection Boundary conditions\n  set Dirichlet = 0: xy\n"
           "  set Neumann = 1\n  subsection Traction\n"
           "    set Function expression = 0.02*t; 0.01*t\n  end\nend\n"
           "subsection Loading\n  set Load steps = " +
           std::to_string(load_steps) +
           "\nend\n"
           "subsection Output\n  set VTU = false\n"
           "  set Points = corner: 1, 1\nend\n";
  }

  double
  distance(const std::vector<double> &a, const std::vector<double> &b)
  {
    double d = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      d += (a[i] - b[i]) * (a[i] - b[i]);
    return std::sqrt(d);
  }

  double
  norm(const std::vector<double> &a)
  {
    return distance(a, std::vector<double>(a.size(), 0.));
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  for (const std::string formulation : {"FEM", "VCBCPBG V5sn Unl"})
    {
      std::ostringstream   cut_screen, screen;
      const pg::RunSummary cut =
        run_problem<2>(settings(formulation, 1, 0.026), cut_screen);
      const pg::RunSummary two =
        run_problem<2>(settings(formulation, 2, 1.), screen);
      const pg::RunSummary one =
        run_problem<2>(settings(formulation, 1, 1.), screen);
      const auto &u_cut = cut.points[0].second, &u_two = two.points[0].second,
                 &u_one      = one.points[0].second;
      const std::string text = cut_screen.str();
      deallog << formulation << ": one load step with the limit: cut "
              << (text.find("cutting the step to dt = 0.5") !=
                      std::string::npos ?
                    "yes" :
                    "NO")
              << ", grown again "
              << (text.find("growing the step to dt = 1") != std::string::npos ?
                    "yes" :
                    "NO")
              << ", failure named "
              << (text.find("the update of the test material failed") !=
                      std::string::npos ?
                    "yes" :
                    "NO")
              << std::endl;
      print_bound("  |u(cut) - u(two steps)| / |u|",
                  distance(u_cut, u_two) / norm(u_two),
                  1e-10);
      const double path = distance(u_one, u_two) / norm(u_two);
      deallog << "  |u(one step) - u(two steps)| / |u| > 1e-3 (the history "
                 "matters): "
              << (path > 1e-3 ? "yes" : "NO") << std::endl;
      AssertThrow(distance(u_cut, u_two) <= 1e-10 * norm(u_two) &&
                    path > 1e-3 &&
                    text.find("cutting the step") != std::string::npos,
                  ExcInternalError());
    }
}
