#include <pg/base/exceptions.h>
#include <pg/solvers/load_stepper.h>
#include <pg/solvers/newton_solver.h>

#include <algorithm>
#include <sstream>

namespace pg
{
  LoadStepper::LoadStepper(const Parameters::Loading &parameters,
                           const std::string         &output_directory,
                           const ConditionalOStream  &out)
    : parameters(parameters)
    , output_directory(output_directory)
    , out(out)
  {}



  void
  LoadStepper::run(const Operations  &operations,
                   const unsigned int first_step) const
  {
    const unsigned int n_steps = parameters.load_steps;
    // the same expression as a step's target below: bit for bit
    double t = static_cast<double>(first_step - 1) / n_steps;
    operations.commit();
    for (unsigned int step = first_step; step <= n_steps; ++step)
      {
        const double       target = static_cast<double>(step) / n_steps;
        double             dt     = target - t;
        const double       full   = dt;
        unsigned int       cuts   = 0;
        std::ostringstream header;
        header << "  load step " << step << ", t = " << target;
        out << header.str() << std::endl;
        unsigned int step_iterations = 0;
        bool         stalled_before  = false;
        while (t < target - 1e-14)
          {
            const double t_new      = std::min(target, t + dt);
            unsigned int iterations = 0;
            if (operations.solve(t_new, iterations))
              {
                operations.commit();
                t = t_new;
                step_iterations += iterations;
                stalled_before = false;
                if (cuts > 0 && iterations <= parameters.easy_iterations &&
                    dt < full && t < target - 1e-14)
                  {
                    dt = std::min(2 * dt, full);
                    out << "    growing the step to dt = " << dt << std::endl;
                  }
                continue;
              }
            operations.revert();
            const std::string last_failure = operations.last_failure();
            // A residual that stalls on its round-off floor before and
            // after a cut stalls after every further cut: the floor is
            // absolute, and a smaller step only lowers |R_0|.
            const bool stalled = NewtonSolver::stalled(last_failure);
            if (stalled && stalled_before)
              {
                operations.give_up(step, t);
                AssertThrow(
                  false,
                  ExcMessage(
                    "Load step " + std::to_string(step) + " stopped after " +
                    std::to_string(cuts) +
                    (cuts == 1 ? " step cut" : " step cuts") +
                    " (last load factor reached: " + std::to_string(t) +
                    "): Newton's residual stalled before and after a cut, "
                    "and smaller steps do not lower its round-off floor. " +
                    last_failure +
                    " The results of the converged steps are in '" +
                    output_directory + "'."));
              }
            stalled_before = stalled;
            // A load that is NaN or inf at t_new stays so after any cut
            // (issue 45, item 2); an element inverted by a too large step
            // gives a NaN, too, but a finite residual at u = 0.
            if (operations.load_is_finite && !operations.load_is_finite(t_new))
              {
                operations.give_up(step, t);
                std::ostringstream load_factor;
                load_factor << t_new;
                AssertThrow(
                  false,
                  ExcMessage(
                    "Load step " + std::to_string(step) +
                    " did not converge after " + std::to_string(cuts) +
                    (cuts == 1 ? " step cut" : " step cuts") +
                    " (last load factor reached: " + std::to_string(t) +
                    "): the residual is NaN or inf at load factor " +
                    load_factor.str() +
                    " already in the undeformed state (u = 0), so it comes "
                    "from the loads (or the undeformed model itself), not "
                    "from the size of the step, and a step cut cannot "
                    "remove it. The last attempt ended "
                    "with: " +
                    last_failure +
                    " The results of the converged steps are in '" +
                    output_directory + "'."));
              }
            if (++cuts > parameters.maximum_step_cuts)
              {
                operations.give_up(step, t);
                AssertThrow(
                  false,
                  ExcMessage(
                    "Load step " + std::to_string(step) +
                    " did not converge after " +
                    std::to_string(parameters.maximum_step_cuts) +
                    " step cuts (last load factor reached: " +
                    std::to_string(t) + "). " +
                    (last_failure.empty() ?
                       std::string() :
                       "The last attempt ended with: " + last_failure + " ") +
                    // smaller steps do not cure a NaN in the input
                    (last_failure.find("NaN or inf") != std::string::npos ?
                       std::string() :
                       "Increase 'Load steps' or 'Maximum step "
                       "cuts' in subsection 'Loading', or "
                       "'Maximum iterations' in subsection "
                       "'Newton'. ") +
                    "The results of the converged steps are in '" +
                    output_directory + "'."));
              }
            dt /= 2;
            out << "    cutting the step to dt = " << dt << std::endl;
          }
        operations.step_done(step, t, step_iterations);
      }
  }
} // namespace pg
