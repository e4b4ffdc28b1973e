#include <pg/solvers/newton_solver.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace pg
{
  namespace
  {
    // how stall_diagnosis() begins, and what stalled() looks for
    const std::string stall_message = "Newton stalled between ";
  } // namespace



  NewtonSolver::NewtonSolver(const Parameters::Newton &parameters)
    : parameters(parameters)
  {}



  NewtonSolver::Result
  NewtonSolver::solve(const Operations &operations) const
  {
    Result             result;
    std::ostringstream line;
    line << std::scientific << std::setprecision(2);
    double reference = 0, first_energy = 0, last_energy = 0;
    // run an assembly; on failure record it as the outcome
    const auto assembly_failed =
      [&](const std::function<std::string()> &assemble) {
        result.failure = assemble();
        if (result.failure.empty())
          return false;
        result.outcome = Outcome::assembly_failed;
        result.history = line.str();
        return true;
      };
    for (unsigned int it = 0; it <= parameters.maximum_iterations; ++it)
      {
        if (assembly_failed(operations.assemble_residual ?
                              operations.assemble_residual :
                              operations.assemble))
          return result;
        const double residual = operations.residual_norm();
        result.residuals.push_back(residual);
        if (it == 0)
          reference =
            operations.reference ? operations.reference(residual) : residual;
        if (!std::isfinite(residual))
          {
            // never print a NaN residual as a ratio 0
            line << " " << residual;
            result.outcome = Outcome::not_finite;
            result.failure = "the Newton residual is not finite (|R| = " +
                             std::to_string(residual) + ")";
            result.history = line.str();
            return result;
          }
        line << " " << (reference > 0 ? residual / reference : 0.);
        if (residual <= parameters.absolute_tolerance ||
            residual <= parameters.relative_tolerance * reference)
          {
            result.outcome = Outcome::converged;
            result.history = line.str();
            return result;
          }
        const double stagnation = parameters.stagnation_tolerance;
        if (it >= 2 && residual <= stagnation * reference &&
            residual > 0.5 * result.residuals[it - 1] &&
            std::abs(last_energy) <=
              stagnation * stagnation * std::abs(first_energy))
          {
            result.outcome = Outcome::converged_at_round_off;
            result.history = line.str();
            return result;
          }
        if (it == parameters.maximum_iterations)
          break;

        if (operations.assemble_residual &&
            assembly_failed(operations.assemble))
          return result;
        double energy = 0;
        if (!operations.solve_and_update(energy))
          {
            result.outcome = Outcome::linear_solver_failed;
            result.failure = "the linear solver did not converge";
            result.history = line.str();
            return result;
          }
        if (it == 0)
          first_energy = energy;
        last_energy = energy;
        ++result.updates;
        if (operations.after_update)
          operations.after_update();
      }
    result.outcome = Outcome::too_many_iterations;
    result.history = line.str();
    result.failure = stall_diagnosis(result.residuals, reference);
    return result;
  }



  std::string
  NewtonSolver::stall_diagnosis(const std::vector<double> &residuals,
                                const double               reference) const
  {
    // The last four residuals small and within a factor 10 of each other:
    // Newton has stalled, typically on the round-off floor of a stiff
    // material (K/mu = 5e6 at nu = 0.4999999 puts it near 1e-5 |R_0|).
    const unsigned int n = residuals.size();
    if (n < 5 || !(reference > 0))
      return "";
    double low = residuals[n - 1], high = residuals[n - 1];
    for (unsigned int i = n - 4; i < n; ++i)
      {
        low  = std::min(low, residuals[i]);
        high = std::max(high, residuals[i]);
      }
    if (!(high <= 1e-2 * reference && high <= 10. * low))
      return "";
    std::ostringstream message;
    message << std::setprecision(1) << std::scientific << stall_message
            << low / reference << " and " << high / reference
            << " |R_0| in its last 4 iterations. If "
            << "that is the round-off floor of a stiff material (e.g. nu "
            << "close to 0.5), set 'Stagnation tolerance' in subsection "
            << "'Newton' above " << high / reference << " (it is "
            << parameters.stagnation_tolerance << ").";
    return message.str();
  }



  bool
  NewtonSolver::stalled(const std::string &failure)
  {
    return failure.compare(0, stall_message.size(), stall_message) == 0;
  }



  void
  NewtonSolver::report(const Result &result, const ConditionalOStream &out)
  {
    switch (result.outcome)
      {
        case Outcome::converged:
          out << "    Newton " << result.updates
              << ": |R|/|R_0| =" << result.history << std::endl;
          break;
        case Outcome::converged_at_round_off:
          out << "    Newton " << result.updates
              << ": |R|/|R_0| =" << result.history
              << " (stagnated at round-off)" << std::endl;
          break;
        case Outcome::assembly_failed:
          out << "    assembly failed: " << result.failure.substr(0, 400)
              << std::endl;
          break;
        case Outcome::linear_solver_failed:
          break;
        case Outcome::not_finite:
        case Outcome::too_many_iterations:
          out << "    Newton did not converge: |R|/|R_0| =" << result.history
              << std::endl;
          break;
      }
  }
} // namespace pg
