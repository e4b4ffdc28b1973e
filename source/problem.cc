#include <pg/analysis/analysis.h>
#include <pg/analysis/dynamic_analysis.h>
#include <pg/analysis/eigenmode_analysis.h>
#include <pg/analysis/inf_sup_analysis.h>
#include <pg/analysis/static_analysis.h>
#include <pg/assembly/assembler.h>
#include <pg/assembly/loads.h>
#include <pg/assembly/mass_matrix.h>
#include <pg/assembly/particle_loads.h>
#include <pg/base/exceptions.h>
#include <pg/base/formulation_code.h>
#include <pg/base/linear_algebra.h>
#include <pg/constraints/boundary_constraints.h>
#include <pg/dofs/discretization.h>
#include <pg/elements/correction_system.h>
#include <pg/elements/cpd_interactions.h>
#include <pg/elements/element_group.h>
#include <pg/elements/family_elements.h>
#include <pg/elements/family_group.h>
#include <pg/elements/kernel_cost.h>
#include <pg/elements/q1_cell.h>
#include <pg/elements/q1_cell_group.h>
#include <pg/elements/quadrature_table.h>
#include <pg/elements/unit_stress_residual.h>
#include <pg/families/family_set.h>
#include <pg/materials/material.h>
#include <pg/mesh/mesh_generator.h>
#include <pg/mesh/particle_set.h>
#include <pg/postprocess/output.h>
#include <pg/postprocess/postprocessor.h>
#include <pg/postprocess/postprocessors.h>
#include <pg/postprocess/problem_view.h>
#include <pg/postprocess/sample_locations.h>
#include <pg/postprocess/setup_report.h>
#include <pg/problem.h>
#include <pg/solvers/linear_solver.h>
#include <pg/solvers/load_stepper.h>
#include <pg/solvers/newton_solver.h>
#include <pg/solvers/time_integration.h>
#include <pg/solvers/time_integrator.h>
#include <pg/solvers/time_stepper.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/table_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/work_stream.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/numerics/data_out.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <mutex>
#include <optional>
#include <sstream>

namespace pg
{
  template <int dim>
  class Problem<dim>::Implementation : public MechanicalSystem
  {
  public:
    Implementation(const Parameters::AllParameters<dim> &parameters,
                   const MPI_Comm                        mpi_communicator,
                   std::ostream                         &out);

    void
    run();

    void
    setup();

    /**
     * Dirichlet and symmetry constraints; the Dirichlet values are those
     * of the current load factor (set_load_factor), or zero if
     * @p homogeneous.
     */
    void
    make_constraints(AffineConstraints<double> &c,
                     const bool                 homogeneous) const;

    void
    assemble(const bool with_matrix);

    /** One load (sub)step to load factor @p t; returns success. */
    bool
    solve_step(const double t, unsigned int &iterations);
    /**
     * Solve matrix * update = rhs and add the update (with the homogeneous
     * constraints) to the solution, with @p energy = update . rhs; false,
     * with a message, if the linear solver does not converge.
     */
    bool
    apply_newton_update(double &energy);

    /**
     * Newton's operations on the static residual: assemble (failures
     * reduced over the ranks), |R|, solve and update.
     */
    NewtonSolver::Operations
    newton_operations() override;

    /** @name The MechanicalSystem of the time integrators */
    /** @{ */
    MPI_Comm
    communicator() const override
    {
      return comm;
    }

    const IndexSet &
    locally_owned_dofs() const override
    {
      return owned_dofs;
    }

    LinearAlgebra::Vector &
    displacement() override
    {
      return solution_owned;
    }

    void
    displacement_changed() override
    {
      update_full_solution();
    }

    void
    set_time(const double t) override
    {
      set_load_factor(t);
      if (prm.boundary_conditions.prescribes_values())
        make_constraints(constraints, false);
    }

    void
    apply_dirichlet_values() override
    {
      constraints.distribute(solution_owned);
    }

    const AffineConstraints<double> &
    homogeneous_constraints() const override
    {
      return zero_constraints;
    }

    std::string
    assemble_residual(const bool with_matrix) override
    {
      assemble(with_matrix);
      return failure;
    }

    LinearAlgebra::Vector &
    residual() override
    {
      return rhs;
    }

    const LinearAlgebra::Vector &
    unbalanced_force() const override
    {
      return force;
    }

    LinearAlgebra::SparseMatrix &
    tangent() override
    {
      return matrix;
    }

    void
    external_force(LinearAlgebra::Vector &f_ext) override
    {
      compute_external_force(f_ext);
    }

    void
    solve(const LinearAlgebra::SparseMatrix &A,
          LinearAlgebra::Vector             &x,
          const LinearAlgebra::Vector       &b) override
    {
      solve_linear_system(prm.linear_solver, dof_handler, A, x, b);
    }
    /** @} */

    void
    update_full_solution();

    /**
     * d^k of every particle from the current family tables (summed over
     * all ranks), the largest interior value for the summary and the
     * boundary-area weights of the Neumann loads (ParticleLoads).
     */
    void
    compute_unit_stress_residual();

    /**
     * Build and solve the VC (or VC2) system (pg-methods.md sections
     * 11.4-11.7) in correction_system, hand the factors to the family
     * elements (PBG: test = trial corrected), record max |alpha^k| h,
     * rebuild the family tables and d^k (correct_family_tables()).
     */
    void
    correct_variational_consistency();

    /** Set the time of every parsed function to the load factor @p t. */
    void
    set_load_factor(const double t) const
    {
      prm.set_load_factor(t);
    }

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
                const unsigned int newton_iterations);

    /** Entries and flops of the local tangents (summary.assembly_cost). */
    void
    compute_assembly_cost();

    /** statistics.txt, summary.json, timing.txt and the VTU/PVD files. */
    void
    write_files(const unsigned int step, const double t);

    /**
     * What the analyses see of the problem (the view is set once view()
     * has been called, after setup()).
     */
    Analysis::Access<dim>
    analysis_access();

    /** F^k of particle @p k (ProblemView::particle_deformation_gradient). */
    Tensor<2, dim>
    particle_deformation_gradient(const unsigned int k);

    /**
     * The nodal stresses from the particle deformation gradients
     * @p particle_F (Postprocess::NodalStresses::write()).
     */
    void
    write_nodal_stresses(const std::vector<Tensor<2, dim>> &particle_F);

    /** Is @p id in 'Neumann' or in 'Neumann stress'? */
    bool
    is_neumann(const types::boundary_id id) const
    {
      return loads.is_neumann(id);
    }

    bool
    has_neumann_face(
      const typename DoFHandler<dim>::active_cell_iterator &cell) const
    {
      return loads.has_neumann_face(cell);
    }

    /**
     * f_ext at the time of the parsed functions: the loads are dead, so
     * f_ext = -(f_int - f_ext)(u = 0), one residual assembly (none without
     * body force and Neumann boundaries). Overwrites rhs and force.
     */
    void
    compute_external_force(LinearAlgebra::Vector &f_ext);

    /** @p target += @p factor C^T y with C of zero_constraints. */
    void
    add_condensed(const LinearAlgebra::Vector &y,
                  const double                 factor,
                  LinearAlgebra::Vector       &target) const override;


    const Parameters::AllParameters<dim>     &prm;
    const MPI_Comm                            comm;
    const bool                                root;
    ConditionalOStream                        pcout;
    const FormulationCode                     formulation;
    std::unique_ptr<Materials::Material<dim>> material;

    /** Mesh, DoFs, particles, families and tables (set up in setup()). */
    Discretization<dim> discretization;
    /** @name Short names of the members of discretization */
    /** @{ */
    Parameters::Geometry                 &geometry = discretization.geometry;
    parallel::shared::Triangulation<dim> &triangulation =
      discretization.triangulation;
    const FESystem<dim> &fe            = discretization.fe;
    const FE_Q<dim>     &fe_scalar     = discretization.fe_scalar;
    DoFHandler<dim>     &dof_handler   = discretization.dof_handler;
    std::vector<bool>   &meshfree      = discretization.meshfree;
    IndexSet            &owned_dofs    = discretization.owned_dofs;
    IndexSet            &relevant_dofs = discretization.relevant_dofs;
    ParticleSet<dim>    &particles     = discretization.particles;
    FamilySet<dim>      &families      = discretization.families;
    std::unique_ptr<FamilyElements<dim>> &family_elements =
      discretization.family_elements;
    std::unique_ptr<CpdInteractions<dim>> &cpd = discretization.cpd;
    std::vector<unsigned int> &owned_families  = discretization.owned_families;
    std::vector<QuadratureTable<dim>> &family_tables =
      discretization.family_tables;
    std::vector<typename DoFHandler<dim>::active_cell_iterator>
      &owned_fe_cells = discretization.owned_fe_cells;
    std::vector<typename DoFHandler<dim>::active_cell_iterator>
      &owned_meshfree_neumann_cells =
        discretization.owned_meshfree_neumann_cells;
    double      &mesh_diameter = discretization.mesh_diameter;
    std::string &mesh_notes    = discretization.mesh_notes;
    double      &time_mesh     = discretization.time_mesh;
    double      &time_setup    = discretization.time_setup;
    double      &time_shape    = discretization.time_shape;
    /** @} */

    /** The cell and reference coordinates of every 'Output/Points' entry. */
    std::vector<
      std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>>>
      point_locations;
    /** The samples of 'Output/Lines'. */
    std::vector<Postprocess::LineSampleLocation<dim>> line_locations;

    AffineConstraints<double>   constraints, zero_constraints;
    LinearAlgebra::SparseMatrix matrix;
    LinearAlgebra::Vector       solution, solution_owned;
    LinearAlgebra::Vector       update, rhs, force;
    Vector<double>              u_full;

    /** The VC system, with its own matrix (VC codes only). */
    std::unique_ptr<CorrectionSystem<dim>> correction_system;

    /** The dead loads of 'Boundary conditions' and the body force. */
    const Loads<dim> loads;
    /**
     * The loads on the particles and meshfree faces (the load term of the
     * Assembler) and the unit-stress residual d^k they use.
     */
    ParticleLoads<dim> particle_loads;
    /** Views of particle_loads for setup() and view(). */
    const bool traction_from_test_functions =
      particle_loads.traction_from_test_functions();
    const bool traction_from_exact_stress =
      particle_loads.traction_from_exact_stress();
    const std::vector<Tensor<1, dim>> &unit_stress =
      particle_loads.unit_stress();
    const std::vector<std::map<types::boundary_id, double>>
      &boundary_area_weights = particle_loads.boundary_area_weights();
    /** The element groups and the assembler over them (set up in setup()). */
    std::unique_ptr<Q1CellGroup<dim>>  q1_cells;
    std::unique_ptr<ElementGroup<dim>> family_group;
    std::unique_ptr<Assembler<dim>>    assembler;
    /**
     * The material state at the groups' evaluation points: committed after
     * every accepted (sub)step, reverted after a cut.
     */
    QuadraturePointHistory history;

    /** The first failure of the last assembly on this rank (or empty). */
    std::string failure;
    /** Why the last failed (sub)step failed, for the final message. */
    std::string last_failure;

    RunSummary   summary;
    TableHandler statistics;
    Timer        total_timer;
    /** Wall times (s) of the phases, reported in summary.json. */
    double time_vc = 0, time_assembly = 0, time_solve = 0;
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
    std::ostream                         &out)
    : prm(parameters)
    , comm(mpi_communicator)
    , root(Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
    , pcout(out, root)
    , formulation(parse_formulation_code(parameters.discretization.formulation))
    , material(Materials::create_material<dim>(parameters.material))
    , discretization(mpi_communicator, parameters.geometry)
    , loads(parameters)
    , particle_loads(
        parameters,
        formulation,
        loads,
        particles,
        owned_families,
        owned_meshfree_neumann_cells,
        [this](const unsigned int k) {
          // 'exact stress': the internal force of P(I + grad u_exact)
          const auto exact_stress = [this](const Point<dim> &X) {
            return material->first_piola_stress(
              unit_symmetric_tensor<dim>() +
              Postprocess::exact_displacement_gradient(prm, mesh_diameter, X));
          };
          return particle_stress_force<dim>(families,
                                            *family_elements,
                                            k,
                                            exact_stress);
        })
  {
    AssertThrow(!(parameters.linear_solver.type == "cg" &&
                  (formulation.method == FormulationCode::Method::ppg1 ||
                   formulation.method == FormulationCode::Method::ppg2)),
                ExcBadParameter("Linear solver/Type",
                                "cg",
                                "PPG tangents are not symmetric, so CG cannot "
                                "solve them; use 'gmres' or 'direct'."));
  }



  template <int dim>
  void
  Problem<dim>::Implementation::setup()
  {
    discretization.reinit(
      formulation,
      prm.discretization,
      prm.cpd,
      [this](const typename DoFHandler<dim>::active_cell_iterator &cell) {
        return !traction_from_test_functions && !traction_from_exact_stress &&
               loads.has_neumann_face(cell);
      });
    Timer timer;
    summary.dimension   = dim;
    summary.formulation = formulation.text;
    summary.n_dofs      = dof_handler.n_dofs();
    for (const bool m : meshfree)
      (m ? summary.n_meshfree_cells : summary.n_fe_cells) += 1;
    summary.n_particles = particles.n_particles();
    if (particles.n_particles() > 0)
      summary.n_families = families.n_families();

    compute_unit_stress_residual();

    // Locate the reference points once (every rank knows all cells).
    point_locations =
      Postprocess::locate_points(dof_handler, prm.output.points);
    line_locations = Postprocess::locate_line_samples(dof_handler,
                                                      prm.output.lines,
                                                      prm.output.line_samples);

    make_constraints(constraints, false);
    make_constraints(zero_constraints, true);

    // The element groups: Q1 cells first, then the families (PG or CPD).
    q1_cells =
      std::make_unique<Q1CellGroup<dim>>(owned_fe_cells, *material, loads);
    if (cpd)
      family_group = std::make_unique<CpdGroup<dim>>(owned_families,
                                                     families,
                                                     particles,
                                                     *cpd);
    else
      family_group = std::make_unique<FamilyGroup<dim>>(owned_families,
                                                        families,
                                                        particles,
                                                        family_tables,
                                                        *material);
    assembler = std::make_unique<Assembler<dim>>(
      zero_constraints,
      std::vector<ElementGroup<dim> *>{q1_cells.get(), family_group.get()});

    DynamicSparsityPattern dsp(relevant_dofs);
    assembler->add_sparsity(dsp);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               owned_dofs,
                                               comm,
                                               relevant_dofs);
    matrix.reinit(owned_dofs, owned_dofs, dsp, comm);
    summary.matrix_nonzeros = matrix.n_nonzero_elements();
    rhs.reinit(owned_dofs, comm);
    update.reinit(owned_dofs, comm);
    if (formulation.variational_consistency && particles.n_particles() > 0)
      {
        Timer vc_timer;
        correct_variational_consistency();
        time_vc += vc_timer.wall_time();
      }

    solution.reinit(owned_dofs, relevant_dofs, comm);
    solution_owned.reinit(owned_dofs, comm);
    force.reinit(owned_dofs, comm);
    u_full.reinit(dof_handler.n_dofs());
    time_setup += timer.wall_time() - time_vc;
    compute_assembly_cost();

    // The echo of what was understood (no wall times: tests compare it).
    Postprocess::print_setup_report(
      pcout,
      prm,
      formulation,
      discretization,
      summary,
      traction_from_exact_stress   ? "exact stress" :
      traction_from_test_functions ? "test functions" :
                                     "geometry",
      [this](const types::boundary_id id) { return loads.is_neumann(id); },
      boundary_area_weights);

    // The state at every evaluation point of every group (the tables are
    // final now: the VC correction keeps their points).
    history.reinit(assembler->evaluation_points(),
                   material->n_state_variables(),
                   [this](const ArrayView<double> &state) {
                     material->initialize_state(state);
                   });
    assembler->set_history(&history);
  }



  template <int dim>
  void
  Problem<dim>::Implementation::make_constraints(AffineConstraints<double> &c,
                                                 const bool homogeneous) const
  {
    BoundaryConstraints<dim>(dof_handler,
                             prm.boundary_conditions,
                             prm.prescribed_displacement,
                             mesh_diameter)
      .make(relevant_dofs, homogeneous, c);
  }



  template <int dim>
  void
  Problem<dim>::Implementation::compute_unit_stress_residual()
  {
    particle_loads.compute_unit_stress_residual(families, family_tables, comm);
    summary.max_interior_unit_stress_residual =
      particle_loads.max_interior_unit_stress_residual();
  }



  template <int dim>
  void
  Problem<dim>::Implementation::correct_variational_consistency()
  {
    if (!correction_system)
      correction_system =
        std::make_unique<CorrectionSystem<dim>>(formulation, comm);
    const CorrectionFactors<dim> factors =
      correct_family_tables(*correction_system,
                            particles,
                            families,
                            *family_elements,
                            owned_families,
                            owned_dofs,
                            unit_stress,
                            family_tables);
    if (formulation.second_order_consistency)
      summary.max_interior_second_order_residual =
        factors.max_second_order_residual;
    // The size of the correction, relative to the gradients (~1/h): large
    // values mean strongly modified test functions.
    summary.max_correction_factor = factors.max_scaled_factor(particles);
    compute_unit_stress_residual();
  }



  template <int dim>
  void
  Problem<dim>::Implementation::update_full_solution()
  {
    solution = solution_owned;
    for (types::global_dof_index i = 0; i < u_full.size(); ++i)
      u_full[i] = solution[i];
  }



  template <int dim>
  void
  Problem<dim>::Implementation::assemble(const bool with_matrix)
  {
    Timer timer;
    failure    = assembler->assemble(u_full,
                                  with_matrix ? &matrix : nullptr,
                                  rhs,
                                  force,
                                  particle_loads.load_term());
    auto &cost = summary.assembly_cost;
    if (with_matrix)
      {
        ++cost.n_assemblies;
        cost.fe_seconds     = assembler->tangent_seconds()[0];
        cost.family_seconds = assembler->tangent_seconds()[1];
      }
    time_assembly += timer.wall_time();
  }



  template <int dim>
  NewtonSolver::Operations
  Problem<dim>::Implementation::newton_operations()
  {
    NewtonSolver::Operations operations;
    operations.assemble = [this]() -> std::string {
      assemble(true);
      if (Utilities::MPI::max(failure.empty() ? 0 : 1, comm) == 0)
        return "";
      return failure.empty() ? "the assembly failed on another rank" : failure;
    };
    operations.residual_norm    = [this]() { return rhs.l2_norm(); };
    operations.solve_and_update = [this](double &energy) {
      return apply_newton_update(energy);
    };
    return operations;
  }



  template <int dim>
  bool
  Problem<dim>::Implementation::solve_step(const double  t,
                                           unsigned int &iterations)
  {
    set_load_factor(t);
    make_constraints(constraints, false);
    constraints.distribute(solution_owned);
    update_full_solution();
    last_failure.clear();

    const NewtonSolver::Result result =
      NewtonSolver(prm.newton).solve(newton_operations());
    summary.newton_residuals_last_step = result.residuals;
    iterations                         = result.updates;
    last_failure                       = result.failure;
    NewtonSolver::report(result, pcout);
    if (result.converged())
      summary.newton_residuals.push_back(result.residuals);
    return result.converged();
  }



  template <int dim>
  bool
  Problem<dim>::Implementation::apply_newton_update(double &energy)
  {
    Timer timer;
    update = 0;
    try
      {
        solve_linear_system(prm.linear_solver,
                            dof_handler,
                            matrix,
                            update,
                            rhs);
      }
    catch (const SolverControl::NoConvergence &e)
      {
        time_solve += timer.wall_time();
        pcout << "    linear solver did not converge in " << e.last_step
              << " iterations" << std::endl;
        return false;
      }
    time_solve += timer.wall_time();
    ++summary.assembly_cost.n_solves;
    zero_constraints.distribute(update);
    energy = update * rhs;
    solution_owned += update;
    update_full_solution();
    return true;
  }



  template <int dim>
  const Postprocess::ProblemView<dim> &
  Problem<dim>::Implementation::view()
  {
    if (problem_view)
      return *problem_view;
    // filled once, after setup: the objects keep their addresses
    auto &v                  = problem_view.emplace();
    v.parameters             = &prm;
    v.mpi_communicator       = comm;
    v.root                   = root;
    v.pcout                  = &pcout;
    v.formulation            = &formulation;
    v.material               = material.get();
    v.triangulation          = &triangulation;
    v.dof_handler            = &dof_handler;
    v.fe                     = &fe;
    v.fe_scalar              = &fe_scalar;
    v.meshfree               = &meshfree;
    v.particles              = &particles;
    v.families               = &families;
    v.family_elements        = family_elements.get();
    v.cpd                    = cpd.get();
    v.owned_families         = &owned_families;
    v.family_tables          = &family_tables;
    v.owned_fe_cells         = &owned_fe_cells;
    v.owned_dofs             = &owned_dofs;
    v.u_full                 = &u_full;
    v.force                  = &force;
    v.constraints            = &constraints;
    v.unit_stress            = &unit_stress;
    v.point_locations        = &point_locations;
    v.line_locations         = &line_locations;
    v.mesh_diameter          = &mesh_diameter;
    v.time_mesh              = &time_mesh;
    v.time_setup             = &time_setup;
    v.time_shape             = &time_shape;
    v.time_vc                = &time_vc;
    v.time_assembly          = &time_assembly;
    v.time_solve             = &time_solve;
    v.total_timer            = &total_timer;
    v.postprocess_timer      = &postprocess_timer;
    v.set_load_factor        = [this](const double t) { set_load_factor(t); };
    v.add_dynamic_statistics = {}; // set by run() for a DynamicAnalysis
    return *problem_view;
  }



  template <int dim>
  Tensor<2, dim>
  Problem<dim>::Implementation::particle_deformation_gradient(
    const unsigned int k)
  {
    return view().particle_deformation_gradient(k);
  }



  template <int dim>
  void
  Problem<dim>::Implementation::write_nodal_stresses(
    const std::vector<Tensor<2, dim>> &particle_F)
  {
    Postprocess::NodalStresses<dim>::write(view(), particle_F, summary);
  }



  template <int dim>
  void
  Problem<dim>::Implementation::compute_assembly_cost()
  {
    Postprocess::compute_assembly_cost(view(), summary);
  }



  template <int dim>
  void
  Problem<dim>::Implementation::postprocess(
    const unsigned int step,
    const double       t,
    const unsigned int newton_iterations)
  {
    postprocessors.execute(view(),
                           {step, t, newton_iterations},
                           statistics,
                           summary);
  }



  template <int dim>
  void
  Problem<dim>::Implementation::write_files(const unsigned int step,
                                            const double       t)
  {
    postprocessors.output().write(view(), step, t, statistics, summary);
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
      *this,
      problem_view ? &*problem_view : nullptr,
      summary,
      statistics,
      history,
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
      }};
  }



  template <int dim>
  void
  Problem<dim>::Implementation::run()
  {
    total_timer.restart();
    postprocess_timer.reset();
    if (root)
      std::filesystem::create_directories(prm.output.directory);
    MPI_Barrier(comm);

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
            level.geometry = mesh;
            level.setup();
            level.view();
            work(level.analysis_access());
          };
        analysis =
          std::make_unique<Analysis::InfSupAnalysis<dim>>(analysis_access(),
                                                          set_up);
        analysis->run();
        return;
      }
    setup();
    update_full_solution();
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
          return solve_step(t, iterations);
        },
        [this]() { return last_failure; });
    analysis->run();
  }



  template <int dim>
  void
  Problem<dim>::Implementation::compute_external_force(
    LinearAlgebra::Vector &f_ext)
  {
    f_ext.reinit(owned_dofs, comm);
    const auto &bc = prm.boundary_conditions;
    if (prm.zero_body_force && bc.neumann.empty() && bc.neumann_stress.empty())
      return;
    const Vector<double> u_saved = u_full;
    u_full                       = 0;
    assemble(false);
    u_full = u_saved;
    AssertThrow(failure.empty(), ExcMessage(failure));
    f_ext = force;
    f_ext *= -1.;
  }



  template <int dim>
  void
  Problem<dim>::Implementation::add_condensed(
    const LinearAlgebra::Vector &y,
    const double                 factor,
    LinearAlgebra::Vector       &target) const
  {
    LinearAlgebra::Vector ghosted(owned_dofs, relevant_dofs, comm);
    ghosted = y;
    LinearAlgebra::Vector z(owned_dofs, comm);
    for (const auto j : owned_dofs)
      if (!zero_constraints.is_constrained(j))
        z(j) = ghosted(j);
    for (const auto &line : zero_constraints.get_lines())
      for (const auto &[j, c] : line.entries)
        if (owned_dofs.is_element(j))
          z(j) += c * ghosted(line.index);
    z.compress(VectorOperation::insert);
    target.add(factor, z);
  }



  template <int dim>
  Problem<dim>::Problem(const Parameters::AllParameters<dim> &parameters,
                        const MPI_Comm                        mpi_communicator,
                        std::ostream                         &out)
    : implementation(
        std::make_unique<Implementation>(parameters, mpi_communicator, out))
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
  void
  declare_all_parameters(ParameterHandler &prm)
  {
    Parameters::AllParameters<dim>::declare_parameters(prm);
  }



  namespace
  {
    template <int dim>
    RunSummary
    run_dim(const std::string &filename, const MPI_Comm comm, std::ostream &out)
    {
      ParameterHandler prm;
      declare_all_parameters<dim>(prm);
      prm.parse_input(filename);
      Parameters::AllParameters<dim> parameters;
      parameters.parse_parameters(prm);
      Problem<dim> problem(parameters, comm, out);
      problem.run();
      return problem.summary();
    }
  } // namespace



  RunSummary
  run_parameter_file(const std::string &filename,
                     const MPI_Comm     comm,
                     std::ostream      &out)
  {
    const unsigned int dim = Parameters::read_dimension(filename);
    return (dim == 2) ? run_dim<2>(filename, comm, out) :
                        run_dim<3>(filename, comm, out);
  }



  template class Problem<2>;
  template class Problem<3>;
  template void
  declare_all_parameters<2>(ParameterHandler &);
  template void
  declare_all_parameters<3>(ParameterHandler &);
} // namespace pg
