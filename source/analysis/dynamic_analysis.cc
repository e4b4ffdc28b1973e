#include <pg/analysis/dynamic_analysis.h>
#include <pg/assembly/mass_matrix.h>
#include <pg/postprocess/postprocessors.h>
#include <pg/solvers/time_integrator.h>
#include <pg/solvers/time_stepper.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>

#include <iomanip>
#include <memory>

namespace pg
{
  namespace Analysis
  {
    template <int dim>
    double
    DynamicAnalysis<dim>::particle_disorder() const
    {
      const ParticleSet<dim>     &particles = *this->view().particles;
      const Vector<double>        u_full = this->view().gather_displacement();
      std::vector<Tensor<1, dim>> u(particles.n_particles());
      for (unsigned int k = 0; k < u.size(); ++k)
        for (unsigned int c = 0; c < dim; ++c)
          u[k][c] = u_full[particles.dof(k, c)];
      const double deviation =
        TimeIntegration::local_fit_deviation(disorder_positions,
                                             u,
                                             disorder_volumes,
                                             disorder_neighbours);
      const double reference =
        disorder_reference > 0 ?
          disorder_reference :
          TimeIntegration::rms_about_mean(u, disorder_volumes);
      return reference > 0 ? deviation / reference : 0.;
    }



    template <int dim>
    void
    DynamicAnalysis<dim>::add_statistics(const double t)
    {
      auto &d          = this->access.summary.dynamics;
      auto &statistics = this->access.statistics;
      d.time.push_back(t);
      d.kinetic.push_back(energies.kinetic);
      d.internal_work.push_back(energies.internal_work);
      d.external_work.push_back(energies.external_work);
      d.support_work.push_back(energies.support_work);
      d.balance.push_back(energies.balance());
      statistics.add_value("kinetic energy", energies.kinetic);
      statistics.add_value("internal work", energies.internal_work);
      statistics.add_value("external work", energies.external_work);
      statistics.add_value("support work", energies.support_work);
      statistics.add_value("energy balance", energies.balance());
      for (const std::string column : {"kinetic energy",
                                       "internal work",
                                       "external work",
                                       "support work",
                                       "energy balance"})
        {
          statistics.set_scientific(column, true);
          statistics.set_precision(column, 8);
        }
      if (energies.plastic_work)
        {
          d.plastic_work.push_back(*energies.plastic_work);
          statistics.add_value("plastic work", *energies.plastic_work);
          statistics.set_scientific("plastic work", true);
          statistics.set_precision("plastic work", 8);
        }
      if (this->view().particles->n_particles() > 0)
        {
          d.disorder.push_back(particle_disorder());
          statistics.add_value("disorder", d.disorder.back());
          statistics.set_scientific("disorder", true);
          statistics.set_precision("disorder", 6);
        }
    }



    template <int dim>
    void
    DynamicAnalysis<dim>::run()
    {
      const auto             &access    = this->access;
      const auto             &prm       = access.parameters;
      const auto             &view      = this->view();
      const ParticleSet<dim> &particles = *view.particles;
      MechanicalSystem       &system    = access.system;
      RunSummary             &summary   = access.summary;
      const auto             &time      = prm.time;
      const bool              explicit_ = (time.integrator == "leapfrog");
      auto                   &d         = summary.dynamics;
      d.integrator                      = time.integrator;

      // Initial conditions at the vertices; the Dirichlet values of t = 0
      // win, and the constrained DoFs start at rest.
      system.set_time(0.);
      const IndexSet        &owned_dofs = system.locally_owned_dofs();
      LinearAlgebra::Vector &u          = system.displacement();
      LinearAlgebra::Vector  v(owned_dofs, system.communicator());
      for (const auto &cell : view.dof_handler->active_cell_iterators())
        for (const unsigned int vertex : cell->vertex_indices())
          for (unsigned int c = 0; c < dim; ++c)
            {
              const auto dof = cell->vertex_dof_index(vertex, c);
              if (!owned_dofs.is_element(dof))
                continue;
              u(dof) = prm.initial_displacement.value(cell->vertex(vertex), c);
              v(dof) = prm.initial_velocity.value(cell->vertex(vertex), c);
            }
      u.compress(VectorOperation::insert);
      v.compress(VectorOperation::insert);
      system.apply_dirichlet_values();
      system.homogeneous_constraints().distribute(v);
      system.displacement_changed();
      if (particles.n_particles() > 0)
        {
          std::vector<Tensor<1, dim>> u0(particles.n_particles());
          std::vector<double>         V(particles.n_particles());
          const Vector<double>        u_all = view.gather_displacement();
          for (unsigned int k = 0; k < u0.size(); ++k)
            {
              V[k] = particles.volume(k);
              for (unsigned int c = 0; c < dim; ++c)
                u0[k][c] = u_all[particles.dof(k, c)];
            }
          disorder_reference = TimeIntegration::rms_about_mean(u0, V);
          const FamilySet<dim> &families = *view.families;
          disorder_volumes               = V;
          disorder_positions.resize(u0.size());
          disorder_neighbours.assign(u0.size(), {});
          for (unsigned int k = 0; k < u0.size(); ++k)
            {
              disorder_positions[k] = particles.position(k);
              // (the real neighbours: a mirror image moves with its
              // original)
              for (const unsigned int j : families.members(k))
                if (j != k && j < particles.n_particles())
                  disorder_neighbours[k].push_back(j);
            }
        }
      assemble_masses(*view.dof_handler,
                      *view.meshfree,
                      system.homogeneous_constraints(),
                      system.tangent(),
                      prm.material.density,
                      !explicit_,
                      masses);
      std::unique_ptr<TimeIntegrator> integrator;
      if (explicit_)
        integrator = std::make_unique<Leapfrog>(masses);
      else
        integrator =
          std::make_unique<Newmark>(masses, prm.time, prm.newton, access.pcout);

      // the steps taken up to time t, for the summary
      const auto record_steps = [&d](const TimeStepper::Result &r,
                                     const unsigned int         n_steps,
                                     const double               t) {
        d.n_steps            = n_steps;
        d.stable_time_step   = r.stable_time_step;
        d.smallest_time_step = r.smallest_time_step;
        d.largest_time_step  = r.largest_time_step;
        d.step_cuts          = r.step_cuts;
        d.final_time         = t;
      };
      TimeStepper::Operations operations;
      operations.started = [&](const TimeStepper::Result &r) {
        d.stable_time_step = r.stable_time_step;
        d.n_steps          = r.n_steps;
        d.time_step        = r.time_step;
        summary.load_steps = 0;
        summary.converged  = true;
      };
      operations.step_done = [&](const unsigned int step,
                                 const unsigned int iterations) {
        access.history.commit();
        summary.newton_iterations += iterations;
        summary.load_steps                 = step;
        summary.newton_residuals_last_step = integrator->last_residuals;
      };
      // The state of the time loop and the velocity, acceleration, forces
      // and energies it needs to continue (a checkpoint, a restart).
      TimeStepper::State state;
      state.reinit(owned_dofs, system.communicator());
      // the vectors of a checkpoint, named for the message of a mismatch
      const std::vector<std::pair<LinearAlgebra::Vector *, std::string>>
                 checkpoint_vectors = {{&v, "velocity"},
                                       {&state.a, "acceleration"},
                                       {&state.f_ext, "external force"},
                                       {&state.f_int, "internal force"},
                                       {&state.r_old, "reaction"}};
      const auto serialize_energies = [this](auto &archive) {
        for (double *e : {&energies.kinetic,
                          &energies.initial_kinetic,
                          &energies.internal_work,
                          &energies.external_work,
                          &energies.support_work})
          archive &*e;
      };
      // (TimeStepper passes back the state it advances: this one)
      operations.step_accepted = [&](const TimeStepper::State &s) {
        access.checkpoint(s.step,
                          s.t,
                          [&](boost::archive::binary_oarchive &archive) {
                            archive << state;
                            for (const auto &[x, name] : checkpoint_vectors)
                              CheckpointData::save(archive, *x);
                            serialize_energies(archive);
                          });
      };
      unsigned int restart_step = 0;
      double       restart_time = 0;
      const bool   restarted =
        access.restart(restart_step,
                       restart_time,
                       [&](boost::archive::binary_iarchive &archive) {
                         archive >> state;
                         for (const auto &[x, name] : checkpoint_vectors)
                           CheckpointData::load(archive, *x, name);
                         serialize_energies(archive);
                       });
      operations.step_rejected = [&]() { access.history.revert(); };
      operations.output        = access.postprocess;
      operations.give_up = [&](const unsigned int last_step, const double t) {
        record_steps(state.result, state.step, t);
        access.history.revert();
        summary.converged = false;
        access.write_files(last_step, t);
      };
      const TimeStepper::Result result =
        TimeStepper(time, prm.output.directory, access.pcout)
          .run(system,
               *integrator,
               masses,
               v,
               energies,
               summary.dynamics.disorder,
               operations,
               state,
               restarted);
      const unsigned int n_steps = result.n_steps;
      const double       t       = result.final_time;
      record_steps(result, n_steps, t);

      const std::vector<Tensor<2, dim>> F =
        view.particle_deformation_gradients();
      if (particles.n_particles() > 0)
        Postprocess::ParticleFields<dim>::write_table(view, F);
      Postprocess::NodalStresses<dim>::write(view, F, summary);
      if (summary.have_errors)
        access.pcout << "  errors: L2 relative = " << summary.L2_relative
                     << ", H1 relative = " << summary.H1_relative << std::endl;
      if (!explicit_)
        access.pcout << "  total Newton iterations: "
                     << summary.newton_iterations << std::endl;
      access.write_files(n_steps, t);
      // a material with history: the largest committed value of each state
      // output (as "max_<name>" of summary.json, filled by write_files())
      for (const auto &[name, value] : summary.state_output_maxima)
        access.pcout << "  max " << name << ": " << std::setprecision(4)
                     << value << std::setprecision(6) << std::endl;
    }



    template class DynamicAnalysis<2>;
    template class DynamicAnalysis<3>;
  } // namespace Analysis
} // namespace pg
