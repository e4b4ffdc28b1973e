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



  double
  TimeStepper::stable_step(MechanicalSystem   &system,
                           const MassMatrices &masses) const
  {
    const double omega2 =
      TimeIntegration::largest_eigenvalue(system.tangent(), masses.inverse);
    return omega2 > 0 ? 2. / std::sqrt(omega2) : time.end_time;
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
        const double dt_stable  = stable_step(system, masses);
        result.stable_time_step = dt_stable;
        std::ostringstream line;
        line << std::setprecision(4) << "  time integrator: " << time.integrator
             << ", stable leapfrog step 2/omega_max = " << dt_stable
             << " (omega_max = " << 2. / dt_stable << ")";
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



  void
  TimeStepper::update_stable_step(MechanicalSystem   &system,
                                  const MassMatrices &masses,
                                  State              &state,
                                  const double        dt_min,
                                  const Operations   &operations) const
  {
    const double t    = state.t;
    const auto   text = [](const double x) {
      std::ostringstream s;
      s << std::setprecision(4) << x;
      return s.str();
    };
    // the tangent of the accepted state (a plastic point evaluated at its
    // committed state is elastic: no flow under the same F)
    {
      const std::string failure = system.assemble_residual(true);
      AssertThrow(failure.empty(), ExcMessage(failure));
    }
    const double stable           = stable_step(system, masses);
    state.result.stable_time_step = stable;
    const std::string kept = " The results up to t = " + text(t) + " are in '" +
                             output_directory + "'.";
    if (time.time_step > 0)
      {
        if (time.time_step > stable)
          {
            operations.give_up(state.step, t);
            AssertThrow(false,
                        ExcBadParameter("Time/Time step",
                                        text(time.time_step),
                                        "it exceeds the stable step of "
                                        "leapfrog at t = " +
                                          text(t) +
                                          ", 2/omega_max = " + text(stable) +
                                          ": use a smaller step, or 0 for "
                                          "the automatic one." +
                                          kept));
          }
        return;
      }
    const double dt_new = time.safety_factor * stable;
    if (dt_new < dt_min)
      {
        operations.give_up(state.step, t);
        AssertThrow(false,
                    ExcMessage("The stable step of leapfrog collapsed at t = " +
                               text(t) +
                               ": 'Safety factor' times 2/omega_max "
                               "= " +
                               text(dt_new) +
                               " is below 'Minimum time step' in subsection "
                               "'Time' (" +
                               text(dt_min) +
                               "). A cell or family is nearly inverted, or "
                               "nodes nearly touch: look at the last "
                               "output, or lower 'Minimum time step'." +
                               kept));
      }
    if (std::abs(dt_new - state.dt) > 0.01 * state.dt)
      {
        out << "  t = " << text(t)
            << ": stable step 2/omega_max = " << text(stable) << ", time step "
            << text(state.dt) << " -> " << text(dt_new) << std::endl;
        state.dt      = dt_new;
        state.uniform = false;
      }
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

    // 1 at the constrained DoFs (the nodes held on a rigid wall change)
    LinearAlgebra::Vector constrained(owned, comm);
    const auto            mark_constrained = [&]() {
      constrained = 0;
      for (const auto i : owned)
        if (system.homogeneous_constraints().is_constrained(i))
          constrained(i) = 1.;
      constrained.compress(VectorOperation::insert);
    };
    mark_constrained();
    const bool contact = !system.contact_state().empty();

    // a restart keeps the step of the run it continues
    if (!restarted)
      {
        choose_time_step(system, masses, explicit_, result);
        state.dt = result.time_step;
      }
    const unsigned int n_steps  = result.n_steps; // of the uniform steps
    const double       dt0      = result.time_step;
    const bool         adaptive = time.step_control == "adaptive";
    const double       dt_min =
      time.minimum_time_step > 0 ? time.minimum_time_step : 1e-3 * dt0;
    const double dt_max =
      time.maximum_time_step > 0 ? time.maximum_time_step : dt0;
    double &dt = state.dt;
    {
      std::ostringstream line;
      line << std::setprecision(4) << "  time step " << dt0 << ", ";
      if (adaptive)
        line << "adaptive from " << dt_min << " to " << dt_max;
      else
        line << n_steps << " steps";
      line << " to t = " << T;
      out << line.str() << std::endl;
    }
    const auto text = [](const double x) {
      std::ostringstream s;
      s << std::setprecision(6) << x;
      return s.str();
    };

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
      if (energies.plastic_work)
        line << ", W_plastic = " << *energies.plastic_work;
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
        energies.plastic_work = system.plastic_work();
        operations.started(result);
        operations.output(0, 0., 0);
        progress(0, 0.);
        next_output = interval;
      }

    for (unsigned int step = state.step + 1;; ++step)
      {
        if (state.uniform ? step > n_steps : t >= T)
          break;
        // the step h to t_new: while every step has had the first one's
        // size, t = step * dt0 as always; afterwards shortened to end at
        // the next output time ('adaptive') and at T
        double h = dt0, t_new = (step == n_steps ? T : step * dt0);
        if (!state.uniform)
          {
            h = std::min(dt, T - t);
            if (adaptive && interval > 0 && next_output - t > 1e-9 * h)
              h = std::min(h, next_output - t);
            t_new = (T - (t + h) <= 1e-9 * h) ? T : t + h;
          }
        unsigned int iterations                       = 0;
        u_old                                         = system.displacement();
        double                kinetic_constrained_old = kinetic_constrained;
        LinearAlgebra::Vector f_ext_old(f_ext), f_int_old(f_int);
        // what an adaptive step restores when it is redone (and the
        // velocity that a rigid wall stops)
        LinearAlgebra::Vector v_old, a_old;
        std::vector<bool>     contact_old;
        if (adaptive || (explicit_ && contact))
          v_old = v;
        if (adaptive)
          {
            a_old       = a;
            contact_old = system.contact_state();
          }
        // A step that fails (Newton, a NaN in an assembly, a load that
        // cannot be evaluated) is redone with half the step ('adaptive')
        // or ends the run with the files of the steps before it written.
        bool advanced = false;
        try
          {
            advanced =
              integrator.step(system, t_new, h, v, a, f_ext, iterations);
          }
        catch (const std::exception &exc)
          {
            integrator.last_failure = one_line(user_message(exc));
          }
        std::string why = integrator.last_failure;
        if (!why.empty() && why.back() == '.')
          why.pop_back();
        if (!advanced && adaptive && 0.5 * h >= dt_min * (1. - 1e-12))
          {
            system.displacement() = u_old;
            v                     = v_old;
            a                     = a_old;
            f_ext                 = f_ext_old;
            system.set_contact_state(contact_old);
            system.displacement_changed();
            if (operations.step_rejected)
              operations.step_rejected();
            ++result.step_cuts;
            dt               = 0.5 * h;
            state.easy_steps = 0;
            state.uniform    = false;
            out << "  the step to t = " << text(t_new) << " failed"
                << (why.empty() ? std::string() : " (" + why + ")")
                << ": redone with dt = " << text(dt) << std::endl;
            --step;
            continue;
          }
        if (!advanced)
          {
            system.displacement() = u_old;
            system.displacement_changed();
            operations.give_up(step - 1, t);
            AssertThrow(
              false,
              ExcMessage(
                "The " + time.integrator + " step to t = " + text(t_new) +
                " failed" +
                (adaptive ? " with the smallest step, dt = " + text(h) +
                              " ('Time/Minimum time step')" :
                            std::string()) +
                (why.empty() ? std::string(". ") : ": " + why + ". ") +
                (explicit_ || why.find("NaN or inf") != std::string::npos ?
                   std::string() :
                 adaptive ?
                   "A smaller 'Minimum time step' in subsection 'Time', or a "
                   "larger 'Maximum iterations' in subsection 'Newton', may "
                   "get further. " :
                   "Reduce 'Time step' in subsection 'Time', or increase "
                   "'Maximum iterations' in subsection 'Newton' (or set "
                   "'Time step control = adaptive'). ") +
                "The results up to t = " + text(t) + " are in '" +
                output_directory + "'."));
          }
        result.smallest_time_step = result.smallest_time_step == 0 ?
                                      h :
                                      std::min(result.smallest_time_step, h);
        result.largest_time_step  = std::max(result.largest_time_step, h);
        if (adaptive)
          {
            // grow after two consecutive easy steps
            if (iterations > time.easy_step_iterations)
              state.easy_steps = 0;
            else if (++state.easy_steps >= 2)
              {
                state.easy_steps = 0;
                const double grown =
                  std::min(dt_max, time.step_growth_factor * dt);
                if (grown > dt * (1. + 1e-12))
                  {
                    dt            = grown;
                    state.uniform = false;
                  }
              }
          }
        t = t_new;
        result.newton_iterations += iterations;
        operations.step_done(step, iterations);

        // A node that the wall held in this step lost its kinetic energy
        // to the wall (leapfrog: it stops; the source's inelastic contact):
        // the support work of the constrained DoFs' kinetic energy counts
        // the held set after the step at the velocities before it.
        if (explicit_ && contact)
          {
            mark_constrained();
            double e_constrained = 0;
            for (unsigned int i = 0; i < v_old.locally_owned_size(); ++i)
              e_constrained += constrained.begin()[i] * 0.5 *
                               masses.lumped.begin()[i] * v_old.begin()[i] *
                               v_old.begin()[i];
            kinetic_constrained_old = Utilities::MPI::sum(e_constrained, comm);
          }
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
            operations.give_up(step - 1, t - h);
            AssertThrow(false,
                        ExcMessage(
                          "The motion became unbounded at t = " + text(t) +
                          ": reduce 'Time step' in subsection "
                          "'Time'. The results up to t = " +
                          text(t - h) + " are in '" + output_directory + "'."));
          }

        if (t >= T || interval == 0. || t >= next_output - 1e-9 * h)
          {
            while (interval > 0. && next_output <= t + 1e-9 * h)
              next_output += interval;
            energies.plastic_work = system.plastic_work();
            operations.output(step, t, iterations);
            progress(step, t);
          }
        state.step = step;
        if (explicit_ && time.stable_step_update_interval > 0 &&
            step % time.stable_step_update_interval == 0 && t < T)
          update_stable_step(system, masses, state, dt_min, operations);
        if (operations.step_accepted)
          operations.step_accepted(state);
      }
    result.n_steps    = state.step;
    result.final_time = t;
    return result;
  }
} // namespace pg
