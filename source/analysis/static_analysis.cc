#include <pg/analysis/static_analysis.h>
#include <pg/solvers/load_stepper.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <string>

namespace pg
{
  namespace Analysis
  {
    template <int dim>
    StaticAnalysis<dim>::StaticAnalysis(
      const Access<dim>                                 &access,
      const std::function<bool(double, unsigned int &)> &solve_step,
      const std::function<std::string()>                &last_failure)
      : Interface<dim>(access)
      , solve_step(solve_step)
      , last_failure(last_failure)
    {}



    template <int dim>
    void
    StaticAnalysis<dim>::run()
    {
      const auto       &access  = this->access;
      const auto       &prm     = access.parameters;
      MechanicalSystem &system  = access.system;
      RunSummary       &summary = access.summary;
      summary.load_steps        = 0;
      // the state after the last step done (step 0: the initial state)
      unsigned int last_step = 0;
      double       t0        = 0;
      if (!access.restart(last_step, t0, {}))
        access.postprocess(0, 0., 0);

      // The displacement of the last accepted (sub)step (zero at first).
      LinearAlgebra::Vector   converged(system.locally_owned_dofs(),
                                      system.communicator());
      LoadStepper::Operations stepping;
      stepping.solve  = solve_step;
      stepping.commit = [&]() {
        converged = system.displacement();
        access.history.commit();
      };
      stepping.revert = [&]() {
        system.displacement() = converged;
        system.displacement_changed();
        access.history.revert();
      };
      stepping.step_done = [&](const unsigned int step,
                               const double       t,
                               const unsigned int iterations) {
        summary.newton_iterations += iterations;
        summary.load_steps = step;
        summary.converged  = true;
        access.postprocess(step, t, iterations);
        access.checkpoint(step, t, {});
      };
      stepping.give_up = [&](const unsigned int step, const double t) {
        summary.converged = false;
        access.write_files(step, t);
      };
      stepping.last_failure = last_failure;
      // After a NaN or inf on any rank: f_ext at t, one residual assembly
      // at u = 0 (collective; it throws on a NaN or inf on any rank).
      stepping.load_is_finite = [&](const double t) {
        if (!Utilities::MPI::logical_or(last_failure().find("NaN or inf") !=
                                          std::string::npos,
                                        system.communicator()))
          return true;
        system.set_time(t);
        LinearAlgebra::Vector f_ext;
        try
          {
            system.external_force(f_ext);
          }
        catch (const std::exception &)
          {
            return false;
          }
        return std::isfinite(f_ext.l2_norm());
      };
      LoadStepper(prm.loading, prm.output.directory, access.pcout)
        .run(stepping, last_step + 1);
      access.finalize(prm.loading.load_steps, 1.);
    }



    template class StaticAnalysis<2>;
    template class StaticAnalysis<3>;
  } // namespace Analysis
} // namespace pg
