#include <pg/base/exceptions.h>
#include <pg/base/parameters.h>
#include <pg/constraints/boundary_constraints.h>
#include <pg/constraints/support_check.h>
#include <pg/elements/family_group.h>
#include <pg/elements/nodal_pressure_group.h>
#include <pg/elements/u1_stabilisation.h>
#include <pg/elements/unit_stress_residual.h>
#include <pg/postprocess/problem_view.h>
#include <pg/postprocess/run_summary.h>
#include <pg/shape_functions/shape_functions.h>
#include <pg/solvers/discrete_system.h>
#include <pg/solvers/linear_solver.h>

#include <deal.II/base/timer.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>

namespace pg
{
  template <int dim>
  DiscreteSystem<dim>::DiscreteSystem(
    const Parameters::AllParameters<dim> &parameters,
    const MPI_Comm                        mpi_communicator,
    const ConditionalOStream             &pcout,
    const FormulationCode                &formulation,
    const Materials::Material<dim>       &material,
    Discretization<dim>                  &discretization,
    RunSummary                           &summary)
    : prm(parameters)
    , comm(mpi_communicator)
    , pcout(pcout)
    , formulation(formulation)
    , material(material)
    , discretization(discretization)
    , summary(summary)
    , loads(parameters)
    , particle_loads(parameters,
                     formulation,
                     loads,
                     discretization.particles,
                     discretization.owned_families,
                     discretization.owned_meshfree_neumann_cells,
                     [this](const unsigned int k) {
                       // 'exact stress': the internal force of P(I + grad
                       // u_exact)
                       const auto exact_stress = [this](const Point<dim> &X) {
                         return this->material.first_piola_stress(
                           unit_symmetric_tensor<dim>() +
                           Postprocess::exact_displacement_gradient(
                             prm,
                             this->discretization.mesh_diameter,
                             X));
                       };
                       return particle_stress_force<dim>(
                         this->discretization.particles,
                         this->discretization.families,
                         *this->discretization.family_elements,
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
  bool
  DiscreteSystem<dim>::loaded_by_face_traction(const CellIterator &cell) const
  {
    return !particle_loads.traction_from_test_functions() &&
           !particle_loads.traction_from_exact_stress() &&
           loads.has_neumann_face(cell);
  }



  template <int dim>
  void
  DiscreteSystem<dim>::setup()
  {
    const auto &particles     = discretization.particles;
    const auto &owned_dofs    = discretization.owned_dofs;
    const auto &relevant_dofs = discretization.relevant_dofs;

    // every meshfree cell with a Neumann face, on every rank (the exact
    // resultants and the loads at the edges of loaded regions)
    std::vector<CellIterator> neumann_cells;
    for (const auto &cell : discretization.dof_handler.active_cell_iterators())
      if (discretization.meshfree[cell->active_cell_index()] &&
          loads.has_neumann_face(cell))
        neumann_cells.push_back(cell);
    particle_loads.set_neumann_cells(neumann_cells);
    compute_unit_stress_residual();

    SupportCheck::check_boundary_ids(prm.boundary_conditions,
                                     discretization.triangulation);
    rigid_wall.reset();
    make_constraints(wall_free_constraints, true);
    if (prm.boundary_conditions.rigid_wall.enabled)
      rigid_wall =
        std::make_unique<RigidWall<dim>>(prm.boundary_conditions.rigid_wall,
                                         discretization.dof_handler,
                                         discretization.relevant_dofs,
                                         discretization.owned_dofs,
                                         discretization.mesh_diameter,
                                         comm,
                                         !prm.time.dynamic());
    make_constraints(constraints, false);
    make_constraints(zero_constraints, true);
    // A quasi-static problem needs supports against every rigid motion of
    // every part (dynamics and eigenmodes may float).
    if (prm.analysis.type == "static" && !prm.time.dynamic())
      SupportCheck::check_rigid_body_modes(discretization.dof_handler,
                                           particles,
                                           discretization.families,
                                           zero_constraints,
                                           owned_dofs);

    // The element groups: Q1 cells first, then the families (PG or CPD).
    // The mixed codes (UnlP0, U2P1, FEM Q1P0) condense p and Theta per
    // element with the isochoric/volumetric split of the material; U2P1C
    // and Unl+P1C have them as nodal DoFs of the particles, IUnlP0 its
    // family pressure.
    const Materials::VolumetricSplit<dim> *condensed_pressure = nullptr;
    if (formulation.mixed())
      {
        condensed_pressure =
          dynamic_cast<const Materials::VolumetricSplit<dim> *>(&material);
        // AllParameters::parse_parameters() checked the model
        AssertThrow(condensed_pressure != nullptr, ExcInternalError());
      }
    q1_cells = std::make_unique<Q1CellGroup<dim>>(discretization.owned_fe_cells,
                                                  discretization.cells,
                                                  material,
                                                  loads,
                                                  condensed_pressure);
    // CPD's bonds have their own constitutive law (no material, no state)
    AssertThrow(!discretization.cpd || material.n_state_variables() == 0,
                ExcMessage(
                  "'Discretization/Formulation = " +
                  prm.discretization.formulation +
                  "' (CPD) evaluates its own bond law, not the material of "
                  "subsection 'Material', and cannot carry the history of "
                  "'Material/Model = " +
                  prm.material.model +
                  "'. Choose another formulation code for a material with "
                  "history, or a material without."));
    if (discretization.cpd)
      family_group =
        std::make_unique<CpdGroup<dim>>(discretization.owned_families,
                                        discretization.families,
                                        particles,
                                        *discretization.cpd);
    else if (formulation.incompressible())
      family_group = std::make_unique<IncompressibleFamilyGroup<dim>>(
        discretization.owned_families,
        discretization.families,
        particles,
        discretization.family_tables,
        *condensed_pressure,
        formulation.method != FormulationCode::Method::pbg ?
          discretization.family_elements.get() :
          nullptr);
    else if (formulation.n_nodal_fields() > 0)
      family_group = std::make_unique<NodalPressureFamilyGroup<dim>>(
        discretization.owned_families,
        discretization.families,
        particles,
        discretization.family_tables,
        *condensed_pressure,
        formulation.bubble);
    else
      {
        auto families = std::make_unique<FamilyGroup<dim>>(
          discretization.owned_families,
          discretization.families,
          particles,
          discretization.family_tables,
          material,
          condensed_pressure,
          (condensed_pressure != nullptr &&
           formulation.method != FormulationCode::Method::pbg) ?
            discretization.family_elements.get() :
            nullptr,
          formulation.condensed_pressure_degree());
        // eq. (6.20) with E~ = E, also under plasticity, where the source
        // softens it to |sigma_vM / alpha| (doc/ambiguities.md), and
        // nu~ = min(0.49, nu)
        const double nu = prm.material.poissons_ratio;
        // (a material with history: the pseudo-material is the elastic
        // isochoric-volumetric neo-Hooke of the same constants, which is
        // stateless)
        if (formulation.points == FormulationCode::Points::u1s_unl ||
            formulation.implicit_gradients)
          {
            Parameters::Material pseudo =
              prm.material.with_poissons_ratio(std::min(0.49, nu));
            if (material.n_state_variables() > 0)
              pseudo.model = "isochoric-volumetric neo-Hooke";
            pseudo_material = Materials::create_material<dim>(pseudo);
          }
        if (formulation.points == FormulationCode::Points::u1s_unl)
          {
            U1Stabilisation<dim> stabilisation;
            stabilisation.tables = &discretization.stabilisation_tables;
            stabilisation.pseudo_material = pseudo_material.get();
            stabilisation.master_terms    = (nu > 0.49);
            families->set_stabilisation(stabilisation);
          }
        if (prm.discretization.hourglass_coefficient > 0.)
          families->set_stabilisation(hourglass_stabilisation());
        if (formulation.implicit_gradients)
          families->set_stabilisation(implicit_gradient_stabilisation());
        family_group = std::move(families);
      }
    // Mixed elements: p and Theta as Newton iterates (not for the explicit
    // integrator, which has no Newton updates: the closed form)
    condensed_field_iterates = formulation.mixed() &&
                               !formulation.incompressible() &&
                               prm.newton.linearized_condensed_fields &&
                               prm.time.integrator != "leapfrog";
    if (condensed_field_iterates)
      {
        q1_cells->keep_condensed_field_iterates();
        family_group->keep_condensed_field_iterates();
      }
    assembler = std::make_unique<Assembler<dim>>(
      zero_constraints,
      std::vector<ElementGroup<dim> *>{q1_cells.get(), family_group.get()});

    DynamicSparsityPattern dsp(relevant_dofs);
    assembler->add_sparsity(dsp);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               owned_dofs,
                                               comm,
                                               relevant_dofs);
    amg_cache.clear();
    matrix.reinit(owned_dofs, owned_dofs, dsp, comm);
    setup_amg_operator(condensed_pressure);
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

    // The state at every evaluation point of every group (the tables are
    // final now: the VC correction keeps their points).
    // Per point: the material's n_state_variables() values, then a
    // kernel's own entries (U1SIG: the master's F of the last accepted
    // step, dim^2 values, initially 1; doc/architecture.md, "History").
    const unsigned int n_material = material.n_state_variables();
    const unsigned int n_kernel =
      formulation.implicit_gradients ? dim * dim : 0;
    const auto initial_state =
      [this, n_material, n_kernel](const ArrayView<double> &state) {
        material.initialize_state(
          make_array_view(state.begin(), state.begin() + n_material));
        for (unsigned int i = 0; i < n_kernel; ++i)
          state[n_material + i] = (i / dim == i % dim ? 1. : 0.);
      };
    history.reinit(assembler->evaluation_points(),
                   n_material + n_kernel,
                   initial_state);
    if (n_material + n_kernel > 0)
      initial_history.reinit(assembler->evaluation_points(),
                             n_material + n_kernel,
                             initial_state);
    assembler->set_history(&history);
  }



  template <int dim>
  U1Stabilisation<dim>
  DiscreteSystem<dim>::hourglass_stabilisation() const
  {
    // Peridigm's constant with the 3-D bulk modulus and the horizon of
    // each family
    const double K = prm.material.lambda() + 2. / 3. * prm.material.mu();
    U1Stabilisation<dim> stabilisation;
    for (const unsigned int k : discretization.owned_families)
      stabilisation.hourglass_constants.push_back(
        hourglass_constant(prm.discretization.hourglass_coefficient,
                           K,
                           discretization.families.horizon(k)));
    return stabilisation;
  }



  template <int dim>
  U1Stabilisation<dim>
  DiscreteSystem<dim>::implicit_gradient_stabilisation() const
  {
    const auto          &particles = discretization.particles;
    U1Stabilisation<dim> stabilisation;
    stabilisation.pseudo_material = pseudo_material.get();
    const double distance         = prm.discretization.self_weight_distance;
    for (const unsigned int k : discretization.owned_families)
      {
        const ShapeFunctions::FamilyGeometry<dim> family =
          discretization.family_elements->geometry(k);
        double shortest = std::numeric_limits<double>::max();
        for (unsigned int i = 1; i < family.bonds.size(); ++i)
          shortest = std::min(shortest, family.bonds[i].norm());
        const double self_weight =
          std::pow(distance * shortest, -2. * family.weight_exponent);
        std::vector<Tensor<2, dim>> h;
        const double                condition =
          ShapeFunctions::mls1_second_derivatives(family, self_weight, h);
        if (!(condition <= FamilyElements<dim>::maximum_condition_number))
          {
            std::ostringstream where, detail;
            where << "(" << particles.position(k) << ")";
            detail << " for the MLS1 second derivatives of U1SIG "
                      "(condition number "
                   << condition << " > "
                   << FamilyElements<dim>::maximum_condition_number << ")";
            AssertThrow(false,
                        ExcSingularFamily(k,
                                          where.str(),
                                          family.bonds.size() - 1,
                                          detail.str()));
          }
        stabilisation.implicit_gradients.push_back(std::move(h));
        // of the particle's volume in the mirrored body, times the
        // family's share of the model (ParticleSet::family_share())
        stabilisation.second_moments.push_back(
          particles.family_share(k) *
          particle_second_moment<dim>(particles.member_volume(k)));
      }
    return stabilisation;
  }



  template <int dim>
  void
  DiscreteSystem<dim>::make_constraints(AffineConstraints<double> &c,
                                        const bool homogeneous) const
  {
    BoundaryConstraints<dim>(discretization.dof_handler,
                             prm.boundary_conditions,
                             prm.prescribed_displacement,
                             discretization.mesh_diameter,
                             discretization.node_sets)
      .make(discretization.relevant_dofs,
            homogeneous,
            c,
            rigid_wall ? rigid_wall->values(homogeneous) :
                         std::map<types::global_dof_index, double>());
  }



  template <int dim>
  std::pair<unsigned int, unsigned int>
  DiscreteSystem<dim>::update_rigid_wall(const LinearAlgebra::Vector &reaction,
                                         const bool                   release)
  {
    const std::pair<unsigned int, unsigned int> changes =
      rigid_wall->update(solution, reaction, wall_free_constraints, release);
    if (changes.first + changes.second > 0)
      {
        make_constraints(constraints, false);
        make_constraints(zero_constraints, true);
      }
    return changes;
  }



  template <int dim>
  int
  DiscreteSystem<dim>::update_active_set(const LinearAlgebra::Vector &reaction,
                                         const unsigned int           round,
                                         std::string                 &failure)
  {
    if (!rigid_wall)
      return 0;
    const auto [added, released] = update_rigid_wall(reaction, true);
    if (added + released == 0)
      return 0;
    pcout << "    rigid wall: " << added << " nodes in contact, " << released
          << " released (" << rigid_wall->n_active()
          << " held); solving the step again" << std::endl;
    if (round + 1 >= prm.boundary_conditions.rigid_wall.maximum_set_changes)
      {
        failure = "the active set of the rigid wall still changed after " +
                  std::to_string(round + 1) +
                  " solves ('Boundary conditions/Rigid wall/Maximum active "
                  "set changes')";
        pcout << "    " << failure << std::endl;
        return -1;
      }
    constraints.distribute(solution_owned);
    return 1;
  }



  template <int dim>
  void
  DiscreteSystem<dim>::set_contact_state(const std::vector<bool> &state)
  {
    if (!rigid_wall)
      return;
    // (on every rank, also where the set stayed: the constraints are
    // rebuilt collectively)
    rigid_wall->set_active_set(state);
    make_constraints(constraints, false);
    make_constraints(zero_constraints, true);
  }



  template <int dim>
  std::optional<double>
  DiscreteSystem<dim>::plastic_work() const
  {
    if (!material.is_dissipative())
      return {};
    const double local = assembler->integrate_committed_state(
      [this](const ArrayView<const double> &state) {
        return material.plastic_work_density(state);
      },
      material.n_state_variables());
    return Utilities::MPI::sum(local, comm);
  }



  template <int dim>
  int
  DiscreteSystem<dim>::update_contact(const LinearAlgebra::Vector &reaction,
                                      const unsigned int           round)
  {
    std::string failure;
    const int   changed = update_active_set(reaction, round, failure);
    if (changed == 1)
      displacement_changed();
    return changed;
  }



  template <int dim>
  void
  DiscreteSystem<dim>::compute_unit_stress_residual()
  {
    // U1SUnl: the loads of the Unl tables (the U1 tables share their
    // surface area vectors after VC; without VC the families equal Unl
    // for nu <= 0.49)
    particle_loads.compute_unit_stress_residual(
      discretization.families,
      discretization.stabilisation_tables.empty() ?
        discretization.family_tables :
        discretization.stabilisation_tables,
      comm);
    summary.max_interior_unit_stress_residual =
      particle_loads.max_interior_unit_stress_residual();
  }



  template <int dim>
  void
  DiscreteSystem<dim>::correct_variational_consistency()
  {
    if (!correction_system)
      correction_system = std::make_unique<CorrectionSystem<dim>>(
        formulation.underintegrated_part(),
        comm,
        prm.linear_solver.vc_solver);
    if (discretization.stabilisation_elements)
      {
        // U1SUnl (section 12.3.2: "VC must be performed twice"): first the
        // Unl tables of the stabilisation, with the code's boundary
        // option; then the U1 tables with the surface area vectors of the
        // corrected Unl tables as targets, so that a homogeneous stress
        // gives both the same nodal forces and the loads balance the
        // family (eq. 6.18) whatever the pseudo-material.
        if (!stabilisation_correction_system)
          stabilisation_correction_system =
            std::make_unique<CorrectionSystem<dim>>(
              formulation.stabilisation_part(),
              comm,
              prm.linear_solver.vc_solver);
        correct_family_tables(*stabilisation_correction_system,
                              discretization.particles,
                              discretization.families,
                              *discretization.stabilisation_elements,
                              discretization.owned_families,
                              discretization.owned_dofs,
                              particle_loads.unit_stress(),
                              discretization.stabilisation_tables);
        correction_system->set_prescribed_targets(
          unit_stress_residual(discretization.families,
                               discretization.owned_families,
                               discretization.stabilisation_tables,
                               discretization.particles,
                               comm));
      }
    const std::vector<Tensor<1, dim>> u1_unit_stress =
      discretization.stabilisation_elements ?
        unit_stress_residual(discretization.families,
                             discretization.owned_families,
                             discretization.family_tables,
                             discretization.particles,
                             comm) :
        std::vector<Tensor<1, dim>>();
    const CorrectionFactors<dim> factors =
      correct_family_tables(*correction_system,
                            discretization.particles,
                            discretization.families,
                            *discretization.family_elements,
                            discretization.owned_families,
                            discretization.owned_dofs,
                            discretization.stabilisation_elements ?
                              u1_unit_stress :
                              particle_loads.unit_stress(),
                            discretization.family_tables);
    if (formulation.second_order_consistency)
      summary.max_interior_second_order_residual =
        factors.max_second_order_residual;
    // The size of the correction, relative to the gradients (~1/h): large
    // values mean strongly modified test functions.
    summary.max_correction_factor =
      factors.max_scaled_factor(discretization.particles);
    if (!formulation.second_order_consistency)
      {
        summary.vc_solver     = factors.solver;
        summary.vc_iterations = factors.solver_iterations;
      }
    compute_unit_stress_residual();
    // a solve that "succeeded" on a singular system leaves d^k != 0
    AssertThrow(summary.max_interior_unit_stress_residual < 1e-8,
                ExcMessage("The VC correction failed: after it the interior "
                           "unit-stress residual is max |d^k| / h^(dim-1) = " +
                           Utilities::to_string(
                             summary.max_interior_unit_stress_residual) +
                           " (round-off expected). " +
                           CorrectionSystem<dim>::failure_advice(formulation)));
  }



  template <int dim>
  void
  DiscreteSystem<dim>::update_ghost_values()
  {
    solution = solution_owned;
  }



  template <int dim>
  void
  DiscreteSystem<dim>::assemble(const bool with_matrix)
  {
    Timer timer;
    failure    = assembler->assemble(solution,
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
  std::string
  DiscreteSystem<dim>::reduced_failure() const
  {
    if (Utilities::MPI::max(failure.empty() ? 0 : 1, comm) == 0)
      return "";
    return failure.empty() ? "the assembly failed on another rank" : failure;
  }



  template <int dim>
  NewtonSolver::Operations
  DiscreteSystem<dim>::newton_operations()
  {
    NewtonSolver::Operations operations;
    operations.assemble = [this]() -> std::string {
      assemble(true);
      return reduced_failure();
    };
    operations.assemble_residual = [this]() -> std::string {
      assemble(false);
      return reduced_failure();
    };
    operations.residual_norm    = [this]() { return rhs.l2_norm(); };
    operations.solve_and_update = [this](double &energy) {
      return apply_newton_update(energy);
    };
    return operations;
  }



  template <int dim>
  bool
  DiscreteSystem<dim>::solve_step(const double t, unsigned int &iterations)
  {
    set_load_factor(t);
    make_constraints(constraints, false);
    last_failure.clear();
    if (prm.loading.linearized_predictor)
      apply_linearized_predictor();
    constraints.distribute(solution_owned);
    update_ghost_values();

    iterations = 0;
    // The rigid wall's active set: after each converged Newton solve,
    // nodes behind the wall are put on it and nodes with a tensile
    // reaction released, and the step is solved again until the set
    // stays (at most 'Maximum active set changes' times).
    for (unsigned int round = 0;; ++round)
      {
        const NewtonSolver::Result result =
          NewtonSolver(prm.newton).solve(newton_operations());
        summary.newton_residuals_last_step = result.residuals;
        iterations += result.updates;
        last_failure = result.failure;
        NewtonSolver::report(result, pcout);
        if (!result.converged())
          return false;
        summary.newton_residuals.push_back(result.residuals);
        const int changed = update_active_set(force, round, last_failure);
        if (changed <= 0)
          return changed == 0;
        update_ghost_values();
      }
  }



  template <int dim>
  void
  DiscreteSystem<dim>::apply_linearized_predictor()
  {
    // The Dirichlet increment c(t) - u on every DoF with a prescribed value
    // becomes the inhomogeneity of the update's constraints for one solve
    // with the tangent of the last converged state.
    bool moved = false;
    for (const auto &line : constraints.get_lines())
      if (line.entries.empty() &&
          discretization.relevant_dofs.is_element(line.index) &&
          zero_constraints.is_constrained(line.index))
        {
          const double increment = line.inhomogeneity - solution[line.index];
          zero_constraints.set_inhomogeneity(line.index, increment);
          moved = moved || (increment != 0.);
        }
    if (Utilities::MPI::max(moved ? 1 : 0, comm) == 1)
      {
        assemble(true);
        double energy = 0;
        if (reduced_failure().empty() && apply_newton_update(energy))
          pcout << "    predictor: linearized step to the new boundary values"
                << std::endl;
        else
          pcout << "    predictor failed; the step starts from the new "
                   "boundary values"
                << std::endl;
      }
    for (const auto &line : constraints.get_lines())
      if (line.entries.empty() &&
          discretization.relevant_dofs.is_element(line.index) &&
          zero_constraints.is_constrained(line.index))
        zero_constraints.set_inhomogeneity(line.index, 0.);
  }



  template <int dim>
  bool
  DiscreteSystem<dim>::apply_newton_update(double &energy)
  {
    Timer timer;
    update = 0;
    // Newmark adds c0 M, condensed for the constraints of the start, to
    // the tangent: the rows of the DoFs held on a rigid wall since then
    // would couple them (an inexact Newton direction, 9 instead of 1
    // iterations per step on a linear block). Their rows become those of
    // a constraint again (diagonal kept, right-hand side 0: du = 0 there).
    if (rigid_wall && tangent_mass != nullptr)
      for (const auto &[dof, value] : rigid_wall->values(true))
        if (discretization.owned_dofs.is_element(dof))
          matrix.clear_row(dof, matrix.diag_element(dof));
    try
      {
        std::function<const LinearAlgebra::SparseMatrix *()> amg_operator;
        if (amg_assembler != nullptr)
          amg_operator = [this]() { return assemble_amg_operator(); };
        summary.assembly_cost.linear_iterations +=
          solve_linear_system(prm.linear_solver,
                              discretization.dof_handler,
                              matrix,
                              update,
                              rhs,
                              &amg_cache,
                              amg_operator);
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
    summary.assembly_cost.amg_builds            = amg_cache.n_builds;
    summary.assembly_cost.amg_operator_rejected = amg_cache.operator_rejected;
    zero_constraints.distribute(update);
    energy = update * rhs;
    solution_owned += update;
    update_ghost_values();
    if (condensed_field_iterates)
      {
        LinearAlgebra::Vector ghosted_update(discretization.owned_dofs,
                                             discretization.relevant_dofs,
                                             comm);
        ghosted_update = update;
        assembler->recover_local_fields(ghosted_update);
      }
    return true;
  }



  template <int dim>
  void
  DiscreteSystem<dim>::setup_amg_operator(
    const Materials::VolumetricSplit<dim> *condensed_pressure)
  {
    amg_assembler.reset();
    amg_cells.reset();
    owned_cells.clear();
    summary.amg_operator_nonzeros = 0;
    // 'automatic': the PG displacement codes from 10,000 DoFs on
    // (doc/benchmarks/amg_operator.md). Not FE everywhere (the Q1 tangent
    // is the tangent); not below 10,000 DoFs, where ML's hierarchy of the
    // tangent ends in a direct coarse solve after a level or two and needs
    // a fifth of the iterations; not the mixed codes, whose Q1P0 / H1P0
    // hierarchy needs 2 to 4 times the iterations at nu = 0.49; not the
    // classical correspondence (U1, with hourglass force: GMRES 1.7 times
    // slower on Peridigm's tensile bar) nor CPD (not measured).
    const std::string &choice = prm.linear_solver.amg_operator;
    const bool         weak_u1_modes =
      formulation.points == FormulationCode::Points::u1 &&
      !formulation.implicit_gradients;
    // (on triangles and tetrahedra 'Q1 cells' are P1 cells, whose hierarchy
    // needed 4 to 8 times the tangent's iterations: 'automatic' takes the
    // tangent there)
    const bool simplex = discretization.cells.is_simplex();
    const bool suits_automatic =
      discretization.dof_handler.n_dofs() >= 10000 &&
      condensed_pressure == nullptr && !weak_u1_modes &&
      formulation.method != FormulationCode::Method::cpd && !simplex;
    if (choice == "tangent" || prm.linear_solver.type == "direct" ||
        discretization.particles.n_particles() == 0 ||
        (choice == "automatic" && !suits_automatic))
      return;
    for (const auto &cell : discretization.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        owned_cells.push_back(cell);
    amg_cells = std::make_unique<Q1CellGroup<dim>>(owned_cells,
                                                   discretization.cells,
                                                   material,
                                                   loads,
                                                   condensed_pressure);
    amg_assembler =
      std::make_unique<Assembler<dim>>(zero_constraints,
                                       std::vector<ElementGroup<dim> *>{
                                         amg_cells.get()});
    if (material.n_state_variables() > 0)
      {
        amg_history.reinit(amg_assembler->evaluation_points(),
                           material.n_state_variables(),
                           [this](const ArrayView<double> &state) {
                             material.initialize_state(state);
                           });
        amg_assembler->set_history(&amg_history);
      }
    DynamicSparsityPattern dsp(discretization.relevant_dofs);
    amg_assembler->add_sparsity(dsp);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               discretization.owned_dofs,
                                               comm,
                                               discretization.relevant_dofs);
    amg_matrix.reinit(discretization.owned_dofs,
                      discretization.owned_dofs,
                      dsp,
                      comm);
    summary.amg_operator_nonzeros = amg_matrix.n_nonzero_elements();
  }



  template <int dim>
  const LinearAlgebra::SparseMatrix *
  DiscreteSystem<dim>::assemble_amg_operator()
  {
    Timer                 timer;
    LinearAlgebra::Vector residual(discretization.owned_dofs, comm),
      unbalanced(discretization.owned_dofs, comm);
    // e.g. an inverted Q1 cell where the families are fine: the tangent
    const bool failed = Utilities::MPI::logical_or(
      !amg_assembler->assemble(solution, &amg_matrix, residual, unbalanced)
         .empty(),
      comm);
    // Newmark's c0 M: its nonzeros (Q1 cells' consistent mass, the
    // particles' lumped one) lie in the Q1 pattern; it is stored in the
    // pattern of the tangent, whose other entries are zero, and Trilinos'
    // add() skips those
    if (!failed && tangent_mass != nullptr)
      amg_matrix.add(tangent_mass_factor, *tangent_mass);
    time_amg_operator += timer.wall_time();
    return failed ? nullptr : &amg_matrix;
  }



  template <int dim>
  void
  DiscreteSystem<dim>::solve(const LinearAlgebra::SparseMatrix &A,
                             LinearAlgebra::Vector             &x,
                             const LinearAlgebra::Vector       &b)
  {
    solve_linear_system(prm.linear_solver, discretization.dof_handler, A, x, b);
  }



  template <int dim>
  void
  DiscreteSystem<dim>::compute_external_force(LinearAlgebra::Vector &f_ext)
  {
    f_ext.reinit(discretization.owned_dofs, comm);
    if (!loads.any())
      return;
    const LinearAlgebra::Vector u_saved = solution;
    solution                            = 0;
    assembler->use_condensed_field_iterates(false);
    // at u = 0 the initial state has no stress (the committed one may)
    if (initial_history.n_variables() > 0)
      assembler->set_history(&initial_history);
    assemble(false);
    assembler->set_history(&history);
    assembler->use_condensed_field_iterates(true);
    solution = u_saved;
    // every rank stops alike (a load can fail on one rank's cells only)
    const std::string reduced = reduced_failure();
    AssertThrow(reduced.empty(), ExcMessage(reduced));
    f_ext = force;
    f_ext *= -1.;
  }



  template <int dim>
  void
  DiscreteSystem<dim>::add_condensed(const LinearAlgebra::Vector &y,
                                     const double                 factor,
                                     LinearAlgebra::Vector       &target) const
  {
    const auto           &owned_dofs = discretization.owned_dofs;
    LinearAlgebra::Vector ghosted(owned_dofs,
                                  discretization.relevant_dofs,
                                  comm);
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



  template class DiscreteSystem<2>;
  template class DiscreteSystem<3>;
} // namespace pg
