// NewtonSolver on scalar equations where the answer is known: quadratic
// convergence by the residual test; a residual with an artificial round-off
// floor (1e-9 |R_0|, below 'Stagnation tolerance' but above 'Relative
// tolerance') accepted by the stagnation test; a floor above the stagnation
// tolerance (refused, and the failure says that Newton stalled, between
// which levels), a contracting but not converging iteration (wrong
// tangent; refused without that diagnosis), a NaN residual and a failed
// assembly all refused.

#include <pg/solvers/newton_solver.h>

#include <deal.II/base/conditional_ostream.h>

#include "../tests.h"

using namespace pg;

namespace
{
  const char *
  name(const NewtonSolver::Outcome outcome)
  {
    switch (outcome)
      {
        case NewtonSolver::Outcome::converged:
          return "converged";
        case NewtonSolver::Outcome::converged_at_round_off:
          return "converged at round-off";
        case NewtonSolver::Outcome::assembly_failed:
          return "assembly failed";
        case NewtonSolver::Outcome::linear_solver_failed:
          return "linear solver failed";
        case NewtonSolver::Outcome::not_finite:
          return "not finite";
        case NewtonSolver::Outcome::too_many_iterations:
          return "too many iterations";
      }
    return "";
  }

  /**
   * Newton on f(u) = u^3 + u - 10 (root u = 2) from u = 0, with the residual
   * f(u) + floor * (-1)^n * (1 + n/7 mod 1) and the tangent
   * tangent_factor * f'(u).
   */
  NewtonSolver::Result
  run(const double floor,
      const double tangent_factor,
      double      &u,
      const bool   nan_residual = false,
      const bool   failing      = false)
  {
    Parameters::Newton parameters;
    parameters.maximum_iterations     = 20;
    parameters.relative_tolerance     = 1e-12;
    parameters.absolute_tolerance     = 0;
    parameters.stagnation_tolerance   = 1e-6;
    u                                 = 0;
    double                   residual = 0;
    unsigned int             n        = 0;
    NewtonSolver::Operations operations;
    operations.assemble = [&]() -> std::string {
      if (failing)
        return "the element broke";
      residual = u * u * u + u - 10 +
                 floor * ((n % 2) ? -1. : 1.) * (1. + (n % 7) / 7.) * 10;
      ++n;
      if (nan_residual && n == 3)
        residual = std::nan("");
      return "";
    };
    operations.residual_norm    = [&]() { return std::abs(residual); };
    operations.solve_and_update = [&](double &energy) {
      const double du = -residual / (tangent_factor * (3 * u * u + 1));
      energy          = -du * residual;
      u += du;
      return true;
    };
    return NewtonSolver(parameters).solve(operations);
  }
} // namespace

int
main()
{
  initlog();
  struct Case
  {
    std::string name;
    double      floor, tangent_factor;
    bool        nan, failing;
  };
  for (const Case &c : {Case{"exact", 0., 1., false, false},
                        Case{"floor 1e-9", 1e-9, 1., false, false},
                        Case{"floor 1e-4", 1e-4, 1., false, false},
                        Case{"tangent x 10", 0., 10., false, false},
                        Case{"NaN", 0., 1., true, false},
                        Case{"assembly fails", 0., 1., false, true}})
    {
      double                     u = 0;
      const NewtonSolver::Result r =
        run(c.floor, c.tangent_factor, u, c.nan, c.failing);
      deallog << c.name << ": " << name(r.outcome) << ", " << r.updates
              << " updates";
      if (r.converged())
        {
          deallog << ", |u - 2| < 1e-8: "
                  << (std::abs(u - 2) < 1e-8 ? "yes" : "NO");
          AssertThrow(std::abs(u - 2) < 1e-8, ExcInternalError());
        }
      if (!r.failure.empty())
        deallog << ", failure: " << r.failure.substr(0, 40);
      deallog << std::endl;
      std::ostringstream       text;
      const ConditionalOStream out(text, true);
      NewtonSolver::report(r, out);
      deallog << "  report starts with: " << text.str().substr(0, 28)
              << std::endl;
    }
}
