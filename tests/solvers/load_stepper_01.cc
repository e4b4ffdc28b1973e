// LoadStepper with a fake problem whose sub-steps converge (in 3 Newton
// updates) only if they advance the load factor by at most 0.3: the sub-steps
// tried, cut and grown again, the commits and reverts, and the message when
// 'Maximum step cuts' is too small (with give_up called first); and a
// problem whose failures are stalls on the round-off floor, which stops
// after the second stall instead of cutting on; and a failure with a NaN or
// inf that the load gives (load_is_finite), which stops without a cut.

#include <pg/solvers/load_stepper.h>

#include <deal.II/base/conditional_ostream.h>

#include "../tests.h"

using namespace pg;

namespace
{
  void
  run(const unsigned int load_steps,
      const unsigned int maximum_cuts,
      const unsigned int easy_iterations,
      const std::string &failure        = "too hard",
      const double       nan_load_above = 2.)
  {
    Parameters::Loading parameters;
    parameters.load_steps        = load_steps;
    parameters.maximum_step_cuts = maximum_cuts;
    parameters.easy_iterations   = easy_iterations;
    std::ostringstream       text;
    const ConditionalOStream out(text, true);
    double                   committed = 0, state = 0;
    unsigned int             commits = 0, reverts = 0;
    LoadStepper::Operations  operations;
    operations.solve = [&](const double t, unsigned int &iterations) {
      iterations = 3;
      deallog << " " << t;
      state = t;
      return t - committed <= 0.3 + 1e-12;
    };
    operations.commit = [&]() {
      committed = state;
      ++commits;
    };
    operations.revert = [&]() {
      state = committed;
      ++reverts;
      deallog << "x";
    };
    operations.step_done =
      [&](const unsigned int step, const double t, const unsigned int its) {
        deallog << " [step " << step << " at " << t << ", " << its << " its]";
      };
    bool gave_up       = false;
    operations.give_up = [&](const unsigned int, const double) {
      gave_up = true;
    };
    operations.last_failure = [&]() { return failure; };
    if (nan_load_above < 2.)
      operations.load_is_finite = [&](const double t) {
        deallog << "?";
        return failure.find("NaN or inf") == std::string::npos ||
               t <= nan_load_above;
      };
    deallog << load_steps << " steps, " << maximum_cuts << " cuts, easy "
            << easy_iterations << ":";
    try
      {
        LoadStepper(parameters, "results", out).run(operations);
        deallog << std::endl;
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream message;
        e.print_info(message);
        deallog << std::endl
                << "  failed" << (gave_up ? " (give_up called)" : "") << ": "
                << message.str().substr(0, 90) << std::endl;
      }
    deallog << "  committed t = " << committed << ", commits " << commits
            << ", reverts " << reverts << std::endl;
    std::istringstream lines(text.str());
    for (std::string line; std::getline(lines, line);)
      deallog << "  |" << line << std::endl;
  }
} // namespace

int
main()
{
  initlog();
  run(1, 5, 4); // cut twice, grown, ...
  run(1, 5, 0); // a cut step stays small
  run(2, 5, 4);
  run(1, 1, 4); // too few cuts
  // stalled before and after the first cut: no second cut
  run(
    1,
    5,
    4,
    "Newton stalled between 7.7e-06 and 7.8e-06 |R_0| in its last 4 iterations.");
  // a NaN that the load gives above t = 0.9 (issue 45, item 2): step 1
  // cuts (its failure is the step size's, the load is finite), step 2
  // stops at once, without a cut ('?': load_is_finite asked)
  run(2, 5, 4, "NaN or inf in the residual or tangent of Q1 cell 3.", 0.9);
  // a NaN at a finite load (an element inverted by a too large step): cuts
  run(1, 5, 4, "NaN or inf in the residual or tangent of Q1 cell 3.", 1.);
}
