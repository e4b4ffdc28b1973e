#include <pg/base/exceptions.h>
#include <pg/solvers/time_stepper.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace pg
{
  TimeStepper::TimeStepper(const Parameters::Time   &time,
                           const std::string        &output_directory,
                           const ConditionalOStream &out)
    : time(time)
    , output_directory(output_directory)
    , out(out)
  {}



  void
  TimeStepper::State::reinit(const IndexSet &owned, const MPI_Comm comm)
  {
    for (LinearAlgebra::Vector *x : {&a, &f_ext, &f_int, &r_old})
      x->reinit(owned, comm);
  }



  void
  TimeStepper::choose_time_step(MechanicalSystem   &system,
                                const MassMatrices &masses,
                                const bool          explicit_,
                                Result             &result) const
  {
    const double T = time.end_time;
    {
      const std::string failure = system.assemble_residual(true);
      AssertThrow(failure.empty(), ExcMessage(failure));
    }
    if (Utilities::MPI::sum(masses.massless.n_elements(),
                            system.communicator()) > 0)
      {
        // Pressure unknowns without mass: no central-difference limit
        // (Parameters require 'Time step' > 0 and Newmark for them).
        AssertThrow(!explicit_ && time.time_step > 0, ExcInternalError());
        result.stable_time_step = 0;
        out << "  time integrator: " << time.integrator
            << " (the pressure unknowns have no mass: no central-difference "
               "step limit)"
            << std::endl;
      }
    else
      {
        const double omega2 =
          TimeIntegration::largest_eigenvalue(system.tangent(), masses.inverse);
        const double dt_stable  = omega2 > 0 ? 2. / std::sqrt(omega2) : T;
        result.stable_time_step = dt_stable;
        std::ostringstream line;
        line << std::setprecision(4) << "  time integrator: " << time.integrator
             << ", stable leapfrog step 2/omega_max = " << dt_stable
             << " (omega_max = " << std::sqrt(omega2) << ")";
        out << line.str() << std::endl;
      }
    const double dt_stable = result.stable_time_step;
    const auto   text      = [](const double x) {
      std::ostringstream s;
      s << std::setprecision(4) << x;
      return s.str();
    };
    if (explicit_)
      AssertThrow(time.time_step <= dt_stable,
                  ExcBadParameter("Time/Time step",
                                  text(time.time_step),
                                  "it exceeds the stable step of leapfrog, "
                                  "2/omega_max = " +
                                    text(dt_stable) +
                                    " (estimated from the tangent of the "
                                    "initial state): use a smaller step, or "
                                    "0 for the automatic one."));
    const double dt0 =
      time.time_step > 0 ? time.time_step : time.safety_factor * dt_stable;
    result.n_steps   = std::max(1., std::ceil(T / dt0 - 1e-9 * T / dt0));
    result.time_step = T / result.n_steps;
  }



  TimeStepper::Result
  TimeStepper::run(MechanicalSystem          &system,
                   TimeIntegrator            &integrator,
                   const MassMatrices        &masses,
                   LinearAlgebra::Vector     &v,
                   TimeIntegration::Energies &energies,
                   const std::vector<double> &disorder,
                   const Operations          &operations,
                   State                     &state,
                   const bool                 restarted) const
  {
    const bool             explicit_ = integrator.is_explicit();
    const double           T         = time.end_time;
    const MPI_Comm         comm      = system.communicator();
    const IndexSet         owned     = system.locally_owned_dofs();
    Result                &result    = state.result;
    LinearAlgebra::Vector &a = state.a, &f_ext = state.f_ext,
                          &f_int = state.f_int, &r_old = state.r_old;
    double &kinetic_constrained = state.kinetic_constrained;

    // 1 at the constrained DoFs
    LinearAlgebra::Vector constrained(owned, comm);
    for (const auto i : owned)
      if (system.homogeneous_constraints().is_constrained(i))
        constrained(i) = 1.;
    constrained.compress(VectorOperation::insert);

    // a restart keeps the step of the run it continues
    if (!restarted)
      choose_time_step(system, masses, explicit_, result);
    const unsigned int n_steps = result.n_steps;
    const double       dt      = result.time_step;
    {
      std::ostringstream line;
      line << std::setprecision(4) << "  time step " << dt << ", " << n_steps
           << " steps to t = " << T;
      out << line.str() << std::endl;
    }

    LinearAlgebra::Vector Ma(owned, comm), u_old(owned, comm), du(owned, comm),
      r_new(owned, comm);
    // E_kin (and that of the constrained DoFs, whose change the supports
    // pay for with lumped masses) and the reaction including inertia.
    const auto kinetic = [&](double &constrained_part) {
      constrained_part = 0;
      if (!explicit_)
        {
          masses.consistent.vmult(Ma, v);
          return 0.5 * (v * Ma);
        }
      double e = 0, e_constrained = 0;
      for (unsigned int i = 0; i < v.locally_owned_size(); ++i)
        {
          const double ei =
            0.5 * masses.lumped.begin()[i] * v.begin()[i] * v.begin()[i];
          e += ei;
          e_constrained += constrained.begin()[i] * ei;
        }
      constrained_part = Utilities::MPI::sum(e_constrained, comm);
      return Utilities::MPI::sum(e, comm);
    };
    const auto reaction = [&](LinearAlgebra::Vector &r) {
      // (f_int - f_ext + M a) at the constrained DoFs (Newmark), f_int -
      // f_ext there (leapfrog: the inertia enters through E_kin)
      r = system.unbalanced_force();
      if (!explicit_)
        {
          masses.consistent.vmult(Ma, a);
          r += Ma;
        }
      r.scale(constrained);
    };

    const auto progress = [&](const unsigned int step, const double t) {
      std::ostringstream line;
      line << std::setprecision(4) << "  t = " << t << ", step " << step
           << ": E_kin = " << energies.kinetic
           << ", W_int = " << energies.internal_work
           << ", W_ext = " << energies.external_work
           << ", W_supports = " << energies.support_work;
      const double scale = std::max({std::abs(energies.kinetic),
                                     std::abs(energies.internal_work),
                                     std::abs(energies.initial_kinetic),
                                     std::abs(energies.external_work)});
      line << std::scientific << std::setprecision(1) << ", balance/max(E) = "
           << (scale > 0 ? energies.balance() / scale : 0.);
      if (!disorder.empty())
        line << std::defaultfloat << std::setprecision(3)
             << ", disorder = " << disorder.back();
      out << line.str() << std::endl;
    };

    const double interval    = time.output_interval;
    double      &next_output = state.next_output;
    double      &t           = state.t;
    if (!restarted)
      {
        // The state at t = 0: accelerations and energies.
        system.external_force(f_ext);
        {
          const std::string failure = system.assemble_residual(false);
          AssertThrow(failure.empty(), ExcMessage(failure));
        }
        integrator.initial_acceleration(system, a);
        f_int = system.unbalanced_force();
        f_int += f_ext;
        energies                 = TimeIntegration::Energies();
        energies.kinetic         = kinetic(kinetic_constrained);
        energies.initial_kinetic = energies.kinetic;
        reaction(r_old);
        operations.started(result);
        operations.output(0, 0., 0);
        progress(0, 0.);
        next_output = interval;
      }

    for (unsigned int step = state.step + 1; step <= n_steps; ++step)
      {
        const double t_new      = (step == n_steps ? T : step * dt);
        unsigned int iterations = 0;
        u_old                   = system.displacement();
        const double          kinetic_constrained_old = kinetic_constrained;
        LinearAlgebra::Vector f_ext_old(f_ext), f_int_old(f_int);
        // A step that fails (Newton, a NaN in an assembly, a load that
        // cannot be evaluated) ends the run with the files of the steps
        // before it written.
        bool advanced = false;
        try
          {
            advanced =
              integrator.step(system, t_new, dt, v, a, f_ext, iterations);
          }
        catch (const std::exception &exc)
          {
            integrator.last_failure = one_line(user_message(exc));
          }
        if (!advanced)
          {
            system.displacement() = u_old;
            system.displacement_changed();
            operations.give_up(step - 1, t);
            std::string why = integrator.last_failure;
            if (!why.empty() && why.back() != '.')
              why += '.';
            AssertThrow(
              false,
              ExcMessage(
                "The " + time.integrator +
                " step to t = " + std::to_string(t_new) + " failed" +
                (why.empty() ? std::string(". ") : ": " + why + " ") +
                (explicit_ || why.find("NaN or inf") != std::string::npos ?
                   std::string() :
                   "Reduce 'Time step' in subsection 'Time', or increase "
                   "'Maximum iterations' in subsection 'Newton'. ") +
                "The results up to t = " + std::to_string(t) + " are in '" +
                output_directory + "'."));
          }
        t = t_new;
        result.newton_iterations += iterations;
        operations.step_done(step, iterations);

        // energies (trapezoidal rule)
        du = system.displacement();
        du -= u_old;
        f_int = system.unbalanced_force();
        f_int += f_ext;
        reaction(r_new);
        energies.kinetic = kinetic(kinetic_constrained);
        f_int_old += f_int;
        f_ext_old += f_ext;
        r_old += r_new;
        energies.internal_work += 0.5 * (f_int_old * du);
        energies.external_work += 0.5 * (f_ext_old * du);
        energies.support_work +=
          0.5 * (r_old * du) + kinetic_constrained - kinetic_constrained_old;
        r_old = r_new;
        if (!std::isfinite(energies.kinetic))
          {
            system.displacement() = u_old;
            system.displacement_changed();
            operations.give_up(step - 1, t - dt);
            AssertThrow(false,
                        ExcMessage("The motion became unbounded at t = " +
                                   std::to_string(t) +
                                   ": reduce 'Time step' in subsection "
                                   "'Time'. The results up to t = " +
                                   std::to_string(t - dt) + " are in '" +
                                   output_directory + "'."));
          }

        if (step == n_steps || interval == 0. || t >= next_output - 1e-9 * dt)
          {
            while (interval > 0. && next_output <= t + 1e-9 * dt)
              next_output += interval;
            operations.output(step, t, iterations);
            progress(step, t);
          }
        state.step = step;
        if (operations.step_accepted)
          operations.step_accepted(state);
      }
    result.final_time = t;
    return result;
  }
} // namespace pg
