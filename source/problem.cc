#include <pg/analysis/analysis.h>
#include <pg/analysis/checkpoint.h>
#include <pg/analysis/dynamic_analysis.h>
#include <pg/analysis/eigenmode_analysis.h>
#include <pg/analysis/inf_sup_analysis.h>
#include <pg/analysis/static_analysis.h>
#include <pg/base/exceptions.h>
#include <pg/base/formulation_code.h>
#include <pg/base/interruption.h>
#include <pg/base/parameter_file.h>
#include <pg/base/shared_libraries.h>
#include <pg/dofs/discretization.h>
#include <pg/materials/material.h>
#include <pg/postprocess/output.h>
#include <pg/postprocess/postprocessor.h>
#include <pg/postprocess/postprocessors.h>
#include <pg/postprocess/problem_view.h>
#include <pg/postprocess/sample_locations.h>
#include <pg/postprocess/setup_report.h>
#include <pg/problem.h>
#include <pg/solvers/discrete_system.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/table_handler.h>
#include <deal.II/base/timer.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/map.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <filesystem>
#include <optional>

namespace pg
{
  /**
   * The wiring of a run: the parameters, the material, the Discretization
   * and the DiscreteSystem on it, the sample locations, the summary, the
   * statistics and the timers, the ProblemView of the postprocessors and
   * the analysis of 'Analysis/Type' and 'Time/Integrator'.
   */
  template <int dim>
  class Problem<dim>::Implementation
  {
  public:
    Implementation(const Parameters::AllParameters<dim> &parameters,
                   const MPI_Comm                        mpi_communicator,
                   std::ostream                         &out,
                   const bool                            restart = false);

    /**
     * run_analysis(); an exception that ends it is recorded in summary.json
     * ("status": "failed" and its message; the files of the steps before it
     * stay as they were written) and passed on.
     */
    void
    run();

    /** Set up, then run the analysis of 'Analysis/Type'. */
    void
    run_analysis();

    /**
     * The discretization, the sample locations, the system, the assembly
     * cost and the set-up report.
     */
    void
    setup();

    /**
     * The read-only view of the problem for the postprocessors, filled on
     * the first call (after setup).
     */
    const Postprocess::ProblemView<dim> &
    view();

    /**
     * Point values, reactions, errors, statistics, files of a step: the
     * postprocessors' execute().
     */
    void
    postprocess(const unsigned int step,
                const double       t,
                const unsigned int newton_iterations)
    {
      postprocessors.execute(view(),
                             {step, t, newton_iterations},
                             statistics,
                             summary);
    }

    /** Entries and flops of the local tangents (summary.assembly_cost). */
    void
    compute_assembly_cost()
    {
      Postprocess::compute_assembly_cost(view(), summary);
    }

    /** statistics.txt, summary.json, timing.txt and the VTU/PVD files. */
    void
    write_files(const unsigned int step, const double t)
    {
      postprocessors.output().write(view(), step, t, statistics, summary);
    }

    /**
     * What the analyses see of the problem (the view is set once view()
     * has been called, after setup()).
     */
    Analysis::Access<dim>
    analysis_access();

    /** What a checkpoint must match to be read by this run. */
    Checkpoint::Signature
    checkpoint_signature() const;

    /**
     * The problem's part of a checkpoint (Archive: a boost binary o- or
     * iarchive): the progress in the summary, the statistics table, the
     * PVD records, the displacement and the committed material history.
     */
    template <class Archive>
    void
    serialize_state(Archive &archive);

    /** Access::checkpoint. */
    void
    checkpoint(const unsigned int        step,
               const double              t,
               const Checkpoint::Writer &analysis_state);

    /** "load step 4 (load factor 0.8)" or "time step 50 (t = 1.5)". */
    std::string
    step_text(const unsigned int step, const double t) const;

    /** Access::restart. */
    bool
    restart_from_checkpoint(unsigned int             &step,
                            double                   &t,
                            const Checkpoint::Reader &analysis_state);

    const Parameters::AllParameters<dim> &prm;
    const MPI_Comm                        comm;
    /** `pg_solve --restart`: continue from the checkpoint. */
    const bool                                restart;
    const bool                                root;
    ConditionalOStream                        pcout;
    const FormulationCode                     formulation;
    std::unique_ptr<Materials::Material<dim>> material;

    /** Mesh, DoFs, particles, families and tables (set up in setup()). */
    Discretization<dim> discretization;
    /** Sizes, Newton residuals, errors, timing: summary.json. */
    RunSummary summary;
    /** Constraints, tangent, vectors, loads, groups, history, VC. */
    DiscreteSystem<dim> system;

    /** The cell and reference coordinates of every 'Output/Points' entry. */
    std::vector<
      std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>>>
      point_locations;
    /** The samples of 'Output/Lines'. */
    std::vector<Postprocess::LineSampleLocation<dim>> line_locations;

    TableHandler statistics;
    Timer        total_timer;
    /** Errors, statistics, output (started and stopped around them). */
    Timer postprocess_timer;

    std::optional<Postprocess::ProblemView<dim>> problem_view;
    /** Points, lines, reactions, errors, statistics, files, in order. */
    Postprocess::Manager<dim> postprocessors;
    /** The analysis of 'Analysis/Type' and 'Time/Integrator' (run()). */
    std::unique_ptr<Analysis::Interface<dim>> analysis;
  };



  template <int dim>
  Problem<dim>::Implementation::Implementation(
    const Parameters::AllParameters<dim> &parameters,
    const MPI_Comm                        mpi_communicator,
    std::ostream                         &out,
    const bool                            restart)
    : prm(parameters)
    , comm(mpi_communicator)
    , restart(restart)
    , root(Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
    , pcout(out, root)
    , formulation(parse_formulation_code(parameters.discretization.formulation))
    // IUnlP0 constrains the volume by its pressure: the material's
    // isochoric part alone (its K is infinite)
    , material(Materials::create_material<dim>(
        formulation.incompressible() ?
          parameters.material.without_volumetric_energy() :
          parameters.material))
    , discretization(mpi_communicator, parameters.geometry)
    , system(parameters,
             mpi_communicator,
             pcout,
             formulation,
             *material,
             discretization,
             summary)
  {}



  template <int dim>
  void
  Problem<dim>::Implementation::setup()
  {
    discretization.reinit(
      formulation,
      prm.discretization,
      prm.cpd,
      [this](const typename DoFHandler<dim>::active_cell_iterator &cell) {
        return system.loaded_by_face_traction(cell);
      },
      prm.boundary_conditions.mirror_symmetry ?
        prm.boundary_conditions.symmetry :
        std::vector<types::boundary_id>());
    Timer timer;
    summary.dimension   = dim;
    summary.formulation = formulation.text;
    summary.n_dofs      = discretization.dof_handler.n_dofs();
    for (const bool m : discretization.meshfree)
      (m ? summary.n_meshfree_cells : summary.n_fe_cells) += 1;
    const auto &particles = discretization.particles;
    summary.n_particles   = particles.n_particles();
    if (particles.n_particles() > 0)
      summary.n_families = discretization.families.n_families();

    // Locate the reference points once (every rank knows all cells).
    const auto &dof_handler = discretization.dof_handler;
    point_locations =
      Postprocess::locate_points(dof_handler, prm.output.points);
    line_locations = Postprocess::locate_line_samples(dof_handler,
                                                      prm.output.lines,
                                                      prm.output.line_samples);

    system.setup();
    discretization.time_setup += timer.wall_time() - system.time_vc;
    compute_assembly_cost();

    // The resultant and moment of every Neumann id on the particles at the
    // full load (load factor 1), beside the exact ones.
    const auto  &particle_loads = system.particle_loads;
    const double load_factor    = system.loads.load_factor();
    prm.set_load_factor(1.);
    summary.neumann_resultants.clear();
    for (const auto &r : particle_loads.neumann_resultants())
      {
        RunSummary::NeumannResultant n;
        n.id              = r.id;
        n.area            = r.area;
        n.moment          = r.moment;
        n.exact_moment    = r.exact_moment;
        n.n_partly_loaded = r.n_partly_loaded;
        for (unsigned int c = 0; c < dim; ++c)
          {
            n.centre.push_back(r.centre[c]);
            n.force.push_back(r.force[c]);
            n.exact_force.push_back(r.exact_force[c]);
            if (particle_loads.traction_from_test_functions())
              n.point_force.push_back(r.point_force[c]);
          }
        summary.neumann_resultants.push_back(n);
      }
    prm.set_load_factor(load_factor);

    // The echo of what was understood (no wall times: tests compare it).
    Postprocess::print_setup_report(
      pcout,
      prm,
      formulation,
      discretization,
      summary,
      particle_loads.traction_from_exact_stress()   ? "exact stress" :
      particle_loads.traction_from_test_functions() ? "test functions" :
                                                      "geometry",
      [this](const types::boundary_id id) {
        return system.loads.is_neumann(id);
      },
      particle_loads.boundary_area_weights());
  }



  template <int dim>
  const Postprocess::ProblemView<dim> &
  Problem<dim>::Implementation::view()
  {
    if (problem_view)
      return *problem_view;
    // filled once, after setup: the objects keep their addresses
    auto &v            = problem_view.emplace();
    v.parameters       = &prm;
    v.mpi_communicator = comm;
    v.root             = root;
    v.pcout            = &pcout;
    v.formulation      = &formulation;
    v.material         = material.get();
    v.triangulation    = &discretization.triangulation;
    v.dof_handler      = &discretization.dof_handler;
    // the element of the FE cells (with extra nodal fields, the hp
    // collection's FE-cell element: u and FE_Nothing)
    v.fe                     = discretization.field_layout ?
                                 &discretization.field_layout
                ->fe_collection()[FieldLayout<dim>::fe_cell_index] :
                                 discretization.fe.get();
    v.fe_scalar              = &discretization.cells.scalar_element();
    v.cells                  = &discretization.cells;
    v.field_layout           = discretization.field_layout.get();
    v.meshfree               = &discretization.meshfree;
    v.particles              = &discretization.particles;
    v.families               = &discretization.families;
    v.family_elements        = discretization.family_elements.get();
    v.cpd                    = discretization.cpd.get();
    v.owned_families         = &discretization.owned_families;
    v.family_tables          = &discretization.family_tables;
    v.owned_fe_cells         = &discretization.owned_fe_cells;
    v.owned_dofs             = &discretization.owned_dofs;
    v.u                      = &system.solution;
    v.force                  = &system.force;
    v.constraints            = &system.constraints;
    v.unit_stress            = &system.particle_loads.unit_stress();
    v.history                = &system.history;
    v.point_locations        = &point_locations;
    v.line_locations         = &line_locations;
    v.mesh_diameter          = &discretization.mesh_diameter;
    v.node_sets              = &discretization.node_sets;
    v.rigid_wall             = system.rigid_wall.get();
    v.time_mesh              = &discretization.time_mesh;
    v.time_setup             = &discretization.time_setup;
    v.time_shape             = &discretization.time_shape;
    v.time_vc                = &system.time_vc;
    v.time_assembly          = &system.time_assembly;
    v.time_solve             = &system.time_solve;
    v.time_amg_operator      = &system.time_amg_operator;
    v.total_timer            = &total_timer;
    v.postprocess_timer      = &postprocess_timer;
    v.add_dynamic_statistics = {}; // set by run() for a DynamicAnalysis
    v.set_load_factor = [this](const double t) { system.set_load_factor(t); };
    return *problem_view;
  }



  template <int dim>
  Analysis::Access<dim>
  Problem<dim>::Implementation::analysis_access()
  {
    return {
      prm,
      formulation,
      pcout,
      root,
      total_timer,
      system,
      problem_view ? &*problem_view : nullptr,
      summary,
      statistics,
      system.history,
      [this](const unsigned int step,
             const double       t,
             const unsigned int iterations) {
        postprocess_timer.start();
        postprocess(step, t, iterations);
        postprocess_timer.stop();
      },
      [this](const unsigned int step, const double t) { write_files(step, t); },
      [this](const unsigned int step, const double t) {
        postprocess_timer.start();
        postprocessors.finalize(view(), {step, t, 0}, statistics, summary);
      },
      [this](const unsigned int        step,
             const double              t,
             const Checkpoint::Writer &analysis_state) {
        checkpoint(step, t, analysis_state);
      },
      [this](unsigned int &step, double &t, const Checkpoint::Reader &state) {
        return restart_from_checkpoint(step, t, state);
      }};
  }



  template <int dim>
  Checkpoint::Signature
  Problem<dim>::Implementation::checkpoint_signature() const
  {
    Checkpoint::Signature signature = {
      {"dimension", std::to_string(dim)},
      {"MPI ranks", std::to_string(Utilities::MPI::n_mpi_processes(comm))},
      {"DoFs", std::to_string(discretization.dof_handler.n_dofs())},
      {"families", std::to_string(summary.n_families)},
      {"formulation", formulation.text},
      {"analysis", prm.time.dynamic() ? prm.time.integrator : "static"}};
    const auto text = [](const double x) {
      std::ostringstream s;
      s << std::setprecision(17) << x;
      return s.str();
    };
    if (prm.time.dynamic())
      {
        signature["End time"]  = text(prm.time.end_time);
        signature["Time step"] = text(prm.time.time_step);
      }
    else
      signature["Load steps"] = std::to_string(prm.loading.load_steps);
    return signature;
  }



  template <int dim>
  template <class Archive>
  void
  Problem<dim>::Implementation::serialize_state(Archive &archive)
  {
    // one member per statement: a chain 'archive & a & b' is read by
    // clang-format as declarations
    auto &s = summary;
    for (unsigned int *n : {&s.load_steps,
                            &s.newton_iterations,
                            &s.assembly_cost.n_assemblies,
                            &s.assembly_cost.n_solves,
                            &s.assembly_cost.linear_iterations})
      archive &*n;
    archive &s.converged;
    archive &s.newton_residuals;
    archive &s.newton_residuals_last_step;
    auto    &d = s.dynamics;
    archive &d.integrator;
    archive &d.time_step;
    archive &d.stable_time_step;
    archive &d.n_steps;
    for (std::vector<double> *series : {&d.time,
                                        &d.kinetic,
                                        &d.internal_work,
                                        &d.external_work,
                                        &d.support_work,
                                        &d.balance,
                                        &d.plastic_work,
                                        &d.disorder})
      archive &*series;
    archive &statistics;
    archive &postprocessors.output();
  }



  template <int dim>
  void
  Problem<dim>::Implementation::checkpoint(
    const unsigned int        step,
    const double              t,
    const Checkpoint::Writer &analysis_state)
  {
    const int          signal   = Interruption::received(comm);
    const unsigned int interval = prm.output.checkpoint_interval;
    if (signal == 0 && (interval == 0 || step % interval != 0))
      return;
    const Checkpoint checkpoint(prm.output.directory, comm);
    checkpoint.write(checkpoint_signature(),
                     step,
                     t,
                     [&](boost::archive::binary_oarchive &archive) {
                       serialize_state(archive);
                       CheckpointData::save(archive, system.displacement());
                       archive << system.history;
                       // the rigid wall's active set (empty without)
                       const std::vector<bool> contact = system.contact_state();
                       archive << contact;
                       if (analysis_state)
                         analysis_state(archive);
                     });
    const std::string at = step_text(step, t);
    pcout << "  checkpoint after " << at << " in '" << checkpoint.directory()
          << "'" << std::endl;
    if (signal != 0)
      throw RunInterrupted(
        signal,
        "Stopped by " + Interruption::signal_name(signal) + " after " + at +
          ". The checkpoint is in '" + checkpoint.directory() +
          "', the results written so far in '" + prm.output.directory +
          "'. Continue with: pg_solve --restart <this parameter file>.");
  }



  template <int dim>
  bool
  Problem<dim>::Implementation::restart_from_checkpoint(
    unsigned int             &step,
    double                   &t,
    const Checkpoint::Reader &analysis_state)
  {
    if (!restart)
      return false;
    const Checkpoint checkpoint(prm.output.directory, comm);
    const auto       group_offsets = system.history.group_offsets();
    const auto       point_offsets = system.history.point_offsets();
    step                           = checkpoint.read(
      checkpoint_signature(),
      t,
      [&](boost::archive::binary_iarchive &archive) {
        serialize_state(archive);
        CheckpointData::load(archive, system.displacement(), "displacement");
        archive >> system.history;
        AssertThrow(system.history.group_offsets() == group_offsets &&
                      system.history.point_offsets() == point_offsets,
                    ExcMessage("The material history of the checkpoint has "
                                                         "other evaluation points than this run. "
                                                         "Restart with the parameter file that wrote "
                                                         "it."));
        std::vector<bool> contact;
        archive >> contact;
        AssertThrow(contact.size() == system.contact_state().size(),
                    ExcMessage("The rigid wall of the checkpoint has other "
                                                         "nodes than this run. Restart with the "
                                                         "parameter file that wrote it."));
        if (!contact.empty())
          system.set_contact_state(contact);
        if (analysis_state)
          analysis_state(archive);
      });
    system.displacement_changed();
    pcout << "  restart after " << step_text(step, t) << " from '"
          << checkpoint.directory() << "'" << std::endl;
    return true;
  }



  template <int dim>
  std::string
  Problem<dim>::Implementation::step_text(const unsigned int step,
                                          const double       t) const
  {
    std::ostringstream text;
    if (prm.time.dynamic())
      text << "time step " << step << " (t = " << t << ")";
    else
      text << "load step " << step << " (load factor " << t << ")";
    return text.str();
  }



  template <int dim>
  void
  Problem<dim>::Implementation::run()
  {
    try
      {
        run_analysis();
        summary.finished = true;
        if (root)
          write_summary_json(summary, prm.output.directory + "/summary.json");
      }
    catch (const std::exception &exc)
      {
        summary.converged    = false;
        summary.interrupted  = dynamic_cast<const RunInterrupted *>(&exc);
        summary.stop_message = one_line(user_message(exc));
        if (root)
          try
            {
              write_summary_json(summary,
                                 prm.output.directory + "/summary.json");
            }
          catch (const std::exception &)
            {
              // the directory cannot be written: the message on the
              // screen is all there is
            }
        throw;
      }
  }



  template <int dim>
  void
  Problem<dim>::Implementation::run_analysis()
  {
    total_timer.restart();
    postprocess_timer.reset();
    {
      // made by rank 0; every rank learns whether that worked
      std::string error;
      if (root)
        try
          {
            std::filesystem::create_directories(prm.output.directory);
          }
        catch (const std::filesystem::filesystem_error &exc)
          {
            error = exc.code().message();
          }
      error = Utilities::MPI::broadcast(comm, error, 0);
      AssertThrow(error.empty(),
                  ExcBadParameter("Output/Directory",
                                  prm.output.directory,
                                  "it cannot be created (" + error +
                                    "). Choose a directory that you can "
                                    "write to."));
    }

    AssertThrow(!prm.time.dynamic() || prm.analysis.type == "static",
                ExcBadParameter("Time/Integrator",
                                prm.time.integrator,
                                "a time integrator needs 'Type = static' in "
                                "subsection 'Analysis'."));
    if (prm.analysis.type == "inf-sup")
      {
        // One problem of these parameters per mesh of the series.
        const auto set_up =
          [this](
            const Parameters::Geometry                               &mesh,
            std::ostream                                             &out,
            const std::function<void(const Analysis::Access<dim> &)> &work) {
            Implementation level(prm, comm, out);
            level.discretization.geometry = mesh;
            level.setup();
            level.view();
            work(level.analysis_access());
          };
        analysis =
          std::make_unique<Analysis::InfSupAnalysis<dim>>(analysis_access(),
                                                          set_up);
        AssertThrow(!restart,
                    ExcMessage("pg_solve --restart continues static and "
                               "dynamic runs; an inf-sup analysis has no "
                               "checkpoint. Run it without --restart."));
        analysis->run();
        return;
      }
    AssertThrow(!restart || prm.analysis.type == "static",
                ExcMessage("pg_solve --restart continues static and dynamic "
                           "runs; an eigenmode analysis has no checkpoint. "
                           "Run it without --restart."));
    setup();
    system.update_ghost_values();
    view();
    if (prm.analysis.type == "eigenmodes")
      analysis =
        std::make_unique<Analysis::EigenmodeAnalysis<dim>>(analysis_access());
    else if (prm.time.dynamic())
      {
        auto dynamics =
          std::make_unique<Analysis::DynamicAnalysis<dim>>(analysis_access());
        problem_view->add_dynamic_statistics =
          [d = dynamics.get()](const double t) { d->add_statistics(t); };
        analysis = std::move(dynamics);
      }
    else
      analysis = std::make_unique<Analysis::StaticAnalysis<dim>>(
        analysis_access(),
        [this](const double t, unsigned int &iterations) {
          return system.solve_step(t, iterations);
        },
        [this]() { return system.last_failure; });
    analysis->run();
  }



  template <int dim>
  Problem<dim>::Problem(const Parameters::AllParameters<dim> &parameters,
                        const MPI_Comm                        mpi_communicator,
                        std::ostream                         &out,
                        const bool                            restart)
    : implementation(std::make_unique<Implementation>(parameters,
                                                      mpi_communicator,
                                                      out,
                                                      restart))
  {}



  template <int dim>
  Problem<dim>::~Problem() = default;



  template <int dim>
  void
  Problem<dim>::run()
  {
    implementation->run();
  }



  template <int dim>
  const RunSummary &
  Problem<dim>::summary() const
  {
    return implementation->summary;
  }



  template <int dim>
  const QuadraturePointHistory &
  Problem<dim>::history() const
  {
    return implementation->system.history;
  }



  template <int dim>
  void
  declare_all_parameters(ParameterHandler &prm)
  {
    Parameters::AllParameters<dim>::declare_parameters(prm);
  }



  namespace
  {
    template <int dim>
    RunSummary
    run_dim(const std::string &filename,
            const MPI_Comm     comm,
            std::ostream      &out,
            const bool         restart)
    {
      ParameterHandler prm;
      declare_all_parameters<dim>(prm);
      Parameters::parse_parameter_file(prm, filename);
      Parameters::AllParameters<dim> parameters;
      parameters.parse_parameters(prm);
      Problem<dim> problem(parameters, comm, out, restart);
      problem.run();
      return problem.summary();
    }
  } // namespace



  RunSummary
  run_parameter_file(const std::string &filename,
                     const MPI_Comm     comm,
                     std::ostream      &out,
                     const bool         restart)
  {
    const unsigned int dim = Parameters::read_dimension(filename);
    Parameters::load_additional_shared_libraries(filename);
    return (dim == 2) ? run_dim<2>(filename, comm, out, restart) :
                        run_dim<3>(filename, comm, out, restart);
  }



  template class Problem<2>;
  template class Problem<3>;
  template void
  declare_all_parameters<2>(ParameterHandler &);
  template void
  declare_all_parameters<3>(ParameterHandler &);
} // namespace pg
