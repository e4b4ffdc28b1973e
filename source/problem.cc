#include <pg/analysis/eigenmodes.h>
#include <pg/analysis/inf_sup.h>
#include <pg/assembly/assembler.h>
#include <pg/assembly/loads.h>
#include <pg/assembly/mass_matrix.h>
#include <pg/base/exceptions.h>
#include <pg/base/formulation_code.h>
#include <pg/base/linear_algebra.h>
#include <pg/constraints/boundary_constraints.h>
#include <pg/dofs/relevant_dofs.h>
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
     * boundary-area weights of the Neumann loads.
     */
    void
    compute_unit_stress_residual();

    /**
     * Build and solve the VC (or VC2) system (pg-methods.md sections
     * 11.4-11.7) in correction_system, hand the factors to the family
     * elements (PBG: test = trial corrected), record max |alpha^k| h,
     * rebuild the family tables and d^k.
     */
    void
    correct_variational_consistency();

    /** Set the time of every parsed function to the load factor @p t. */
    void
    set_load_factor(const double t) const;

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
     * 'Analysis/Type = eigenmodes': the eigenvalues of the tangent in the
     * undeformed state (dissertation section 7.2.1).
     */
    void
    compute_eigenmodes();

    /**
     * 'Analysis/Type = inf-sup': the numerical inf-sup test (section
     * 7.2.5) on the refinement series 'Inf-sup subdivisions' of the unit
     * square, one Implementation per mesh.
     */
    void
    compute_inf_sup();

    /**
     * T_h (pressure projection, eq. 7.13) and S_h (H1 form, eq. 7.12) of
     * the set-up mesh with the element kernels of the real problem, the
     * constrained rows condensed by zero_constraints.
     */
    void
    assemble_inf_sup_forms(LinearAlgebra::SparseMatrix &T,
                           LinearAlgebra::SparseMatrix &S);

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
    is_neumann(const types::boundary_id id) const;

    /**
     * The prescribed traction on boundary @p id at @p point with the
     * outward unit normal @p normal: the 'Traction' function, or
     * sigma . n from 'Boundary stress' for the 'Neumann stress' ids.
     */
    Tensor<1, dim>
    prescribed_traction(const types::boundary_id id,
                        const Point<dim>        &point,
                        const Tensor<1, dim>    &normal) const;

    bool
    has_neumann_face(
      const typename DoFHandler<dim>::active_cell_iterator &cell) const;

    /**
     * The particle loads (the body force V^k rho_0 b and the tractions
     * through the test functions) and the FE-consistent traction on
     * meshfree Neumann faces: the load term of the Assembler.
     */
    void
    add_particle_loads(Assembler<dim> &assembler) const;

    /**
     * 'Time/Integrator' leapfrog or newmark: initial conditions, masses,
     * the stable step estimate and the time loop (instead of the load
     * steps of run()).
     */
    void
    run_dynamics();

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

    /**
     * particles.txt: position, displacement, deformation gradient @p F
     * and volume of every particle (for plots).
     */
    void
    write_particle_table(const std::vector<Tensor<2, dim>> &F);

    /** The disorder indicator of the particles at the current state. */
    double
    particle_disorder() const;

    /** The energy columns of statistics.txt and summary.dynamics. */
    void
    add_energy_statistics(const double t);

    /** The masses of the time integrators (run_dynamics). */
    MassMatrices              masses;
    TimeIntegration::Energies energies;
    /** RMS of the initial particle displacement about its mean. */
    double disorder_reference = 0;
    /**
     * GridTools::diameter() of the final mesh (O(boundary vertices^2), so
     * computed once in setup()): the scale of the geometric tolerances of
     * make_constraints(), which dynamics calls every step.
     */
    double mesh_diameter = 0;
    /** What create_mesh() did to a mesh file, for the banner. */
    std::string mesh_notes;

    const Parameters::AllParameters<dim> &prm;
    /** prm.geometry, replaced per mesh by the inf-sup analysis. */
    Parameters::Geometry                      geometry;
    const MPI_Comm                            comm;
    const bool                                root;
    ConditionalOStream                        pcout;
    const FormulationCode                     formulation;
    std::unique_ptr<Materials::Material<dim>> material;

    parallel::shared::Triangulation<dim> triangulation;
    const FESystem<dim>                  fe;
    const FE_Q<dim>                      fe_scalar;
    DoFHandler<dim>                      dof_handler;
    std::vector<bool>                    meshfree;

    ParticleSet<dim>                     particles;
    FamilySet<dim>                       families;
    std::unique_ptr<FamilyElements<dim>> family_elements;
    /**
     * Formulation = CPD: the interactions, assembled in place of the
     * family tables (family_elements then serves the particle deformation
     * gradients of the output only, as PBG U1).
     */
    std::unique_ptr<CpdInteractions<dim>>                       cpd;
    std::vector<unsigned int>                                   owned_families;
    std::vector<QuadratureTable<dim>>                           family_tables;
    std::vector<typename DoFHandler<dim>::active_cell_iterator> owned_fe_cells;
    /** Meshfree cells loaded by FE-consistent face tractions ('geometry'). */
    std::vector<typename DoFHandler<dim>::active_cell_iterator>
      owned_meshfree_neumann_cells;
    /** The cell and reference coordinates of every 'Output/Points' entry. */
    std::vector<
      std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>>>
      point_locations;
    /** The samples of 'Output/Lines'. */
    std::vector<Postprocess::LineSampleLocation<dim>> line_locations;
    /** Unit-stress residual d^k of every particle (section 8.2). */
    std::vector<Tensor<1, dim>> unit_stress;

    IndexSet                    owned_dofs, relevant_dofs;
    AffineConstraints<double>   constraints, zero_constraints;
    LinearAlgebra::SparseMatrix matrix;
    /**
     * solution is ghosted over relevant_dofs (what the assembly and the
     * postprocessors read); solution_owned holds the owned DoFs that the
     * Newton updates change.
     */
    LinearAlgebra::Vector solution, solution_owned, converged_solution;
    LinearAlgebra::Vector update, rhs, force;

    /**
     * Tractions on meshfree faces load particles through d^k ('Particle
     * traction area' = test functions, or automatic with VC); otherwise by
     * FE-consistent face quadrature.
     */
    const bool traction_from_test_functions;
    /** 'Particle traction area = exact stress'. */
    const bool traction_from_exact_stress;

    /** grad u of the exact solution (Gradient expression if given). */
    Tensor<2, dim>
    exact_displacement_gradient(const Point<dim> &p) const;

    /**
     * The internal force at particle @p k of the exact stress,
     * sum over the families e containing k of sum_q w_q P(X_q) T^{qk}.
     */
    Tensor<1, dim>
    exact_stress_force(const unsigned int k) const;
    /**
     * The area of each boundary part b at particle k seen by the test
     * functions: d^k = sum_b c_b n_b on the unit normals n_b of the parts
     * at k (section 8.2). With one part c = n . d^k; at a corner the
     * decomposition keeps the other part's area out of the load.
     */
    std::vector<std::map<types::boundary_id, double>> boundary_area_weights;

    /** The VC system, with its own matrix (VC codes only). */
    std::unique_ptr<CorrectionSystem<dim>> correction_system;

    /** The dead loads of 'Boundary conditions' and the body force. */
    const Loads<dim> loads;
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
    double time_mesh = 0, time_setup = 0, time_shape = 0, time_vc = 0,
           time_assembly = 0, time_solve = 0;
    /** Errors, statistics, output (started and stopped around them). */
    Timer postprocess_timer;

    std::optional<Postprocess::ProblemView<dim>> problem_view;
    /** Points, lines, reactions, errors, statistics, files, in order. */
    Postprocess::Manager<dim> postprocessors;
  };



  template <int dim>
  Problem<dim>::Implementation::Implementation(
    const Parameters::AllParameters<dim> &parameters,
    const MPI_Comm                        mpi_communicator,
    std::ostream                         &out)
    : prm(parameters)
    , geometry(parameters.geometry)
    , comm(mpi_communicator)
    , root(Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
    , pcout(out, root)
    , formulation(parse_formulation_code(parameters.discretization.formulation))
    , material(Materials::create_material<dim>(parameters.material))
    , triangulation(mpi_communicator,
                    Triangulation<dim>::none,
                    false,
                    parallel::shared::Triangulation<dim>::partition_metis)
    , fe(FE_Q<dim>(1), dim)
    , fe_scalar(1)
    , traction_from_test_functions(
        parameters.boundary_conditions.particle_traction_area ==
          "test functions" ||
        (parameters.boundary_conditions.particle_traction_area == "automatic" &&
         formulation.variational_consistency))
    , traction_from_exact_stress(
        parameters.boundary_conditions.particle_traction_area == "exact stress")
    , loads(parameters)
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
    Timer timer;
    Mesh::create_mesh(geometry, triangulation, &mesh_notes);
    time_mesh += timer.wall_time();
    timer.restart();
    const bool fem = (formulation.method == FormulationCode::Method::fem);
    meshfree = fem ? std::vector<bool>(triangulation.n_active_cells(), false) :
                     Mesh::mark_meshfree_cells(geometry, triangulation);

    dof_handler.reinit(triangulation);
    dof_handler.distribute_dofs(fe);
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      Assert(fe.system_to_component_index(i).first == i % dim &&
               fe.system_to_component_index(i).second == i / dim,
             ExcInternalError());
    owned_dofs = dof_handler.locally_owned_dofs();

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          if (!meshfree[cell->active_cell_index()])
            owned_fe_cells.push_back(cell);
          else if (!traction_from_test_functions &&
                   !traction_from_exact_stress && has_neumann_face(cell))
            owned_meshfree_neumann_cells.push_back(cell);
        }

    summary.dimension   = dim;
    summary.formulation = formulation.text;
    summary.n_dofs      = dof_handler.n_dofs();
    for (const bool m : meshfree)
      (m ? summary.n_meshfree_cells : summary.n_fe_cells) += 1;

    // Particles, families, and the quadrature table of every family owned
    // by this rank (owned = its master's DoFs are owned here).
    particles.reinit(dof_handler, meshfree);
    summary.n_particles = particles.n_particles();
    time_setup += timer.wall_time();
    timer.restart();
    if (particles.n_particles() > 0)
      {
        const bool is_cpd =
          (formulation.method == FormulationCode::Method::cpd);
        // CPD with partial volumes: bonds reach delta + h/2
        families.reinit(particles,
                        prm.discretization.horizon_factor +
                          (is_cpd && prm.cpd.partial_volumes ? 0.5 : 0.),
                        prm.discretization.nearest_neighbours,
                        prm.discretization.horizon);
        summary.n_families = families.n_families();
        if (is_cpd)
          cpd = std::make_unique<CpdInteractions<dim>>(
            particles,
            families,
            CpdConstants{prm.cpd.C1,
                         prm.cpd.C2,
                         prm.cpd.C3,
                         prm.cpd.partial_volumes},
            prm.discretization.horizon_factor,
            prm.discretization.horizon);
        family_elements = std::make_unique<FamilyElements<dim>>(
          particles,
          families,
          is_cpd ? parse_formulation_code("PBG U1") : formulation,
          ShapeFunctions::parse_base(prm.discretization.shape_functions),
          prm.discretization.weight_exponent);
        family_elements->initialize();
        for (unsigned int k = 0; k < particles.n_particles(); ++k)
          if (owned_dofs.is_element(particles.dof(k, 0)))
            owned_families.push_back(k);
        family_tables.resize(owned_families.size());
        for (unsigned int f = 0; f < owned_families.size(); ++f)
          family_elements->build(owned_families[f], family_tables[f]);
      }
    relevant_dofs =
      compute_relevant_dofs(dof_handler, particles, families, owned_families);
    time_shape += timer.wall_time();
    timer.restart();

    compute_unit_stress_residual();

    // Locate the reference points once (every rank knows all cells).
    const MappingQ1<dim> mapping;
    for (const auto &[name, coordinates] : prm.output.points)
      {
        Point<dim> p;
        for (unsigned int d = 0; d < dim; ++d)
          p[d] = coordinates[d];
        std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>>
             found;
        bool inside = true;
        try
          {
            found =
              GridTools::find_active_cell_around_point(mapping, dof_handler, p);
            inside = (found.first.state() == IteratorState::valid);
          }
        catch (...)
          {
            inside = false;
          }
        AssertThrow(inside,
                    ExcBadParameter("Output/Points",
                                    name,
                                    "this point lies outside the mesh."));
        point_locations.push_back(found);
      }
    // The samples of 'Output/Lines'; those outside the mesh (in a hole) are
    // left out.
    line_locations.clear();
    for (unsigned int l = 0; l < prm.output.lines.size(); ++l)
      {
        Point<dim> start, end;
        for (unsigned int d = 0; d < dim; ++d)
          {
            start[d] = prm.output.lines[l].start[d];
            end[d]   = prm.output.lines[l].end[d];
          }
        const unsigned int n = prm.output.line_samples;
        for (unsigned int i = 0; i < n; ++i)
          {
            const Point<dim> p = start + (end - start) * (1. * i / (n - 1));
            try
              {
                const auto found =
                  GridTools::find_active_cell_around_point(mapping,
                                                           dof_handler,
                                                           p);
                if (found.first.state() == IteratorState::valid)
                  line_locations.push_back(
                    {l, p.distance(start), p, found.first, found.second});
              }
            catch (...)
              {
                // outside the mesh: no sample
              }
          }
      }

    mesh_diameter = GridTools::diameter(triangulation);
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
    converged_solution.reinit(owned_dofs, comm);
    force.reinit(owned_dofs, comm);
    time_setup += timer.wall_time() - time_vc;
    compute_assembly_cost();

    // The echo of what was understood (no wall times: tests compare it).
    unsigned int min_family = 0, max_family = 0;
    double       mean_family = 0;
    if (families.n_families() > 0)
      {
        min_family = max_family = families.members(0).size();
        for (unsigned int k = 0; k < families.n_families(); ++k)
          {
            const unsigned int s = families.members(k).size();
            min_family           = std::min(min_family, s);
            max_family           = std::max(max_family, s);
            mean_family += s;
          }
        mean_family /= families.n_families();
      }
    pcout << "pg_solve: " << dim << "-D, formulation '" << formulation.text
          << "'";
    if (formulation.method != FormulationCode::Method::fem && !cpd)
      pcout << " (" << formulation.method_name() << ", "
            << (formulation.points == FormulationCode::Points::unl ? "Unl" :
                formulation.points == FormulationCode::Points::u1  ? "U1" :
                                                                     "U2")
            << ", "
            << (formulation.points == FormulationCode::Points::u2 ?
                  std::string("WTE2") :
                  prm.discretization.shape_functions)
            << ", bond correction "
            << (formulation.bond_correction ? "on" : "off") << ")";
    if (!formulation.notice().empty())
      pcout << "\n  " << formulation.notice();
    if (cpd)
      {
        const auto n = cpd->n_interactions();
        pcout << "\n  CPD:             C1 = " << prm.cpd.C1
              << ", C2 = " << prm.cpd.C2 << ", C3 = " << prm.cpd.C3
              << (prm.cpd.partial_volumes ? ", partial volumes" : "")
              << "\n  interactions:    " << n[0] << " bonds, " << n[1]
              << " triangles, " << n[2] << " tetrahedra";
      }
    if (!cpd || summary.n_fe_cells > 0)
      pcout << "\n  material:        " << prm.material.model
            << ", E = " << prm.material.youngs_modulus
            << ", nu = " << prm.material.poissons_ratio;
    pcout << "\n"
          << "  cells:           " << triangulation.n_active_cells() << " ("
          << summary.n_fe_cells << " finite elements, "
          << summary.n_meshfree_cells << " meshfree)\n"
          << mesh_notes << "  particles:       " << particles.n_particles()
          << "\n";
    if (families.n_families() > 0 && prm.discretization.horizon > 0)
      pcout << "  horizon:         " << prm.discretization.horizon
            << " (absolute)\n";
    if (families.n_families() > 0)
      {
        std::ostringstream mean;
        mean << std::fixed << std::setprecision(1) << mean_family;
        pcout << "  family size:     min " << min_family << ", mean "
              << mean.str() << ", max " << max_family << " (master included)"
              << "\n";
      }
    if (!prm.boundary_conditions.neumann.empty() && particles.n_particles())
      {
        // How much of the geometric Neumann area the test functions see:
        // sum of n . d^k over the particles of Neumann faces divided by the
        // sum of |a^k| (1 for a variationally consistent method).
        double seen = 0, geometric = 0;
        for (unsigned int k = 0; k < particles.n_particles(); ++k)
          for (const auto &[id, area] : particles.boundary_area_vectors(k))
            if (is_neumann(id))
              {
                seen += boundary_area_weights[k].at(id);
                geometric += area.norm();
              }
        if (geometric > 0)
          {
            std::ostringstream percent;
            percent << std::fixed << std::setprecision(1)
                    << 100. * seen / geometric;
            pcout << "  particle traction area: "
                  << (traction_from_exact_stress   ? "exact stress" :
                      traction_from_test_functions ? "test functions" :
                                                     "geometry")
                  << " (the test functions see " << percent.str()
                  << " % of the Neumann area)\n";
          }
      }
    if (formulation.variational_consistency)
      {
        std::ostringstream vc;
        vc << std::scientific << std::setprecision(1)
           << summary.max_interior_unit_stress_residual
           << ", max |alpha| h = " << std::fixed << std::setprecision(2)
           << summary.max_correction_factor;
        pcout << "  VC correction:   interior |d^k|/h^(dim-1) <= " << vc.str()
              << "\n";
        unsigned int n_v1 = 0;
        for (unsigned int k = 0; k < particles.n_particles(); ++k)
          n_v1 += (family_elements->family_correction_function(k) ==
                     FormulationCode::CorrectionFunction::v1 &&
                   formulation.correction_function !=
                     FormulationCode::CorrectionFunction::v1);
        if (n_v1 > 0)
          pcout << "  VC on the FE/meshfree interface: V1 in the " << n_v1
                << " families of interface particles (doc/ambiguities.md, "
                   "item 17)\n";
        if (formulation.second_order_consistency)
          {
            std::ostringstream vc2;
            vc2 << std::scientific << std::setprecision(1)
                << summary.max_interior_second_order_residual;
            pcout << "  VC2 correction:  interior |D^k|/h^dim <= " << vc2.str()
                  << "\n";
          }
      }
    pcout << "  DoFs:            " << dof_handler.n_dofs() << "\n"
          << "  matrix nonzeros: " << summary.matrix_nonzeros << std::endl;

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
    unit_stress = unit_stress_residual(families,
                                       owned_families,
                                       family_tables,
                                       particles.n_particles(),
                                       comm);
    summary.max_interior_unit_stress_residual =
      max_interior_unit_stress_residual(particles, unit_stress);
    boundary_area_weights = pg::boundary_area_weights(particles, unit_stress);
  }



  template <int dim>
  void
  Problem<dim>::Implementation::correct_variational_consistency()
  {
    if (!correction_system)
      correction_system =
        std::make_unique<CorrectionSystem<dim>>(formulation, comm);
    correction_system->reinit(particles,
                              families,
                              *family_elements,
                              owned_families,
                              owned_dofs);
    const CorrectionFactors<dim> factors =
      correction_system->solve(unit_stress);
    if (formulation.second_order_consistency)
      summary.max_interior_second_order_residual =
        factors.max_second_order_residual;
    // The size of the correction, relative to the gradients (~1/h): large
    // values mean strongly modified test functions.
    summary.max_correction_factor = factors.max_scaled_factor(particles);
    family_elements->set_correction_factors(factors.alpha,
                                            factors.second_order_alpha);
    for (unsigned int f = 0; f < owned_families.size(); ++f)
      family_elements->build(owned_families[f], family_tables[f]);
    compute_unit_stress_residual();
  }



  template <int dim>
  void
  Problem<dim>::Implementation::set_load_factor(const double t) const
  {
    // ParsedFunction::set_time() is the only thing that changes the
    // parameters during a run, so it is done here, in one place.
    for (const Functions::ParsedFunction<dim> *function :
         {&prm.prescribed_displacement,
          &prm.traction,
          &prm.boundary_stress,
          &prm.body_force,
          &prm.exact_solution})
      const_cast<Functions::ParsedFunction<dim> *>(function)->set_time(t);
    if (prm.exact_gradient)
      prm.exact_gradient->set_time(t);
  }



  template <int dim>
  void
  Problem<dim>::Implementation::update_full_solution()
  {
    // the ghost entries from their owners: no full-vector copy
    solution = solution_owned;
  }



  template <int dim>
  bool
  Problem<dim>::Implementation::is_neumann(const types::boundary_id id) const
  {
    return loads.is_neumann(id);
  }



  template <int dim>
  Tensor<1, dim>
  Problem<dim>::Implementation::prescribed_traction(
    const types::boundary_id id,
    const Point<dim>        &point,
    const Tensor<1, dim>    &normal) const
  {
    return loads.prescribed_traction(id, point, normal);
  }



  template <int dim>
  bool
  Problem<dim>::Implementation::has_neumann_face(
    const typename DoFHandler<dim>::active_cell_iterator &cell) const
  {
    return loads.has_neumann_face(cell);
  }



  template <int dim>
  void
  Problem<dim>::Implementation::assemble(const bool with_matrix)
  {
    Timer timer;
    failure =
      assembler->assemble(solution,
                          with_matrix ? &matrix : nullptr,
                          rhs,
                          force,
                          [this](Assembler<dim> &a) { add_particle_loads(a); });
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
  void
  Problem<dim>::Implementation::add_particle_loads(
    Assembler<dim> &assembler) const
  {
    // Particle loads: the body force V^k rho_0 b and, with tractions through
    // the test functions, T_b c_b with c_b the area of boundary part b in
    // the unit-stress residual d^k (section 8.2, eqs. 4.32-4.35).
    Vector<double>                       f(dim), local(dim);
    std::vector<types::global_dof_index> dofs(dim);
    for (const unsigned int k : owned_families)
      {
        local = 0;
        if (traction_from_exact_stress && !particles.on_interface(k) &&
            std::any_of(particles.boundary_area_vectors(k).begin(),
                        particles.boundary_area_vectors(k).end(),
                        [&](const auto &area) {
                          return is_neumann(area.first);
                        }))
          {
            // the surface load plus the body force: the whole internal
            // force of the exact stress
            const Tensor<1, dim> force = exact_stress_force(k);
            for (unsigned int c = 0; c < dim; ++c)
              local(c) = force[c];
          }
        else
          {
            loads.body_force(particles.position(k), f);
            for (unsigned int c = 0; c < dim; ++c)
              local(c) += particles.volume(k) * f(c);
          }
        if (traction_from_test_functions)
          for (const auto &[id, area] : particles.boundary_area_vectors(k))
            if (is_neumann(id))
              {
                const Tensor<1, dim> t =
                  prescribed_traction(id,
                                      particles.position(k),
                                      area / area.norm());
                // On the FE/meshfree interface the VC targets d^k are the
                // geometric area vectors (interface plus surface part), so
                // the consistent load there is the geometric one.
                const double a = particles.on_interface(k) ?
                                   area.norm() :
                                   boundary_area_weights[k].at(id);
                for (unsigned int c = 0; c < dim; ++c)
                  local(c) += a * t[c];
              }
        if (!all_finite(local))
          assembler.record_failure(Assembler<dim>::non_finite_message(
            "the load of particle " + std::to_string(k),
            particles.position(k),
            "Check the 'Traction' and 'Body force' functions."));
        for (unsigned int c = 0; c < dim; ++c)
          dofs[c] = particles.dof(k, c);
        assembler.add_load(local, dofs);
      }
    // 'geometry': the FE-consistent load on the meshfree boundary faces.
    if (owned_meshfree_neumann_cells.empty())
      return;
    FEFaceValues<dim> fe_face_values(fe_scalar,
                                     QGauss<dim - 1>(2),
                                     update_values | update_quadrature_points |
                                       update_normal_vectors |
                                       update_JxW_values);
    LocalSystem       local_system;
    local_system.with_matrix = false;
    for (const auto &cell : owned_meshfree_neumann_cells)
      {
        local_system.dofs.resize(fe.n_dofs_per_cell());
        cell->get_dof_indices(local_system.dofs);
        local_system.residual.reinit(local_system.dofs.size());
        loads.add_face_tractions(cell, fe_face_values, local_system.residual);
        if (!all_finite(local_system.residual))
          assembler.record_failure(Assembler<dim>::non_finite_message(
            "the traction on meshfree cell " +
              std::to_string(cell->active_cell_index()),
            cell->center(),
            "Check the 'Traction' function."));
        assembler.distribute(local_system);
      }
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
    v.u                      = &solution;
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
    v.add_dynamic_statistics = [this](const double t) {
      add_energy_statistics(t);
    };
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
  Tensor<2, dim>
  Problem<dim>::Implementation::exact_displacement_gradient(
    const Point<dim> &p) const
  {
    return Postprocess::exact_displacement_gradient(prm, mesh_diameter, p);
  }



  template <int dim>
  Tensor<1, dim>
  Problem<dim>::Implementation::exact_stress_force(const unsigned int k) const
  {
    // Families are pairwise: the families containing k are those of the
    // members of family k.
    Tensor<1, dim>       force;
    QuadratureTable<dim> table;
    for (const unsigned int e : families.members(k))
      {
        family_elements->build(e, table);
        const auto members = families.members(e);
        const auto found   = std::find(members.begin(), members.end(), k);
        Assert(found != members.end(), ExcInternalError());
        std::vector<Tensor<1, dim>> local(members.size());
        add_stress_residual<dim>(
          table,
          [&](const unsigned int q) {
            return material->first_piola_stress(
              unit_symmetric_tensor<dim>() +
              exact_displacement_gradient(table.points[q]));
          },
          local);
        force += local[found - members.begin()];
      }
    return force;
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
  void
  Problem<dim>::Implementation::compute_eigenmodes()
  {
    assemble(true);
    AssertThrow(failure.empty(), ExcMessage(failure));
    const std::vector<double> values = Analysis::dense_eigenvalues(matrix);
    summary.max_eigenvalue           = values.back();
    summary.n_zero_eigenvalues       = 0;
    for (const double v : values)
      if (std::abs(v) < 1e-10 * summary.max_eigenvalue)
        ++summary.n_zero_eigenvalues;
    summary.eigenvalues.assign(
      values.begin(),
      values.begin() +
        std::min<std::size_t>(values.size(), prm.analysis.n_eigenvalues));
    summary.converged = true;

    std::ostringstream line;
    line << std::setprecision(4) << "  eigenvalues: max " << values.back()
         << ", below 1e-10 max: " << summary.n_zero_eigenvalues
         << "\n  smallest non-zero:";
    for (unsigned int i = summary.n_zero_eigenvalues;
         i <
         std::min<std::size_t>(values.size(), summary.n_zero_eigenvalues + 6);
         ++i)
      line << " " << values[i];
    pcout << line.str() << std::endl;

    write_files(0, 0.);
    if (root)
      {
        std::ofstream table(prm.output.directory + "/eigenvalues.txt");
        table << "# index  eigenvalue (real part, ascending)\n"
              << std::setprecision(12);
        for (unsigned int i = 0; i < summary.eigenvalues.size(); ++i)
          table << i + 1 << " " << summary.eigenvalues[i] << "\n";
      }
  }



  template <int dim>
  void
  Problem<dim>::Implementation::assemble_inf_sup_forms(
    LinearAlgebra::SparseMatrix &T,
    LinearAlgebra::SparseMatrix &S)
  {
    const Analysis::InfSup::PressureProjectionMaterial<dim> t_material;
    const Analysis::InfSup::H1Material<dim>                 s_material;
    const bool p0 = (prm.analysis.pressure_space == "P0");
    T.copy_from(matrix);
    T = 0;
    S.copy_from(matrix);
    S = 0;
    FullMatrix<double> t_local, s_local;
    Vector<double>     residual;
    // The undeformed state: y^b = X^b - X^0 (u = 0; both forms are linear).
    const auto add = [&](const QuadratureTable<dim>                 &table,
                         const std::vector<Tensor<1, dim>>          &y,
                         const std::vector<types::global_dof_index> &dofs) {
      if (p0)
        Analysis::InfSup::p0_pressure_projection(table, t_local);
      else
        assemble_element(table, y, t_material, residual, &t_local);
      assemble_element(table, y, s_material, residual, &s_local);
      zero_constraints.distribute_local_to_global(t_local, dofs, T);
      zero_constraints.distribute_local_to_global(s_local, dofs, S);
    };
    FEValues<dim>                        fe_values(fe_scalar,
                            QGauss<dim>(2),
                            update_gradients | update_JxW_values);
    QuadratureTable<dim>                 table;
    std::vector<Tensor<1, dim>>          y;
    std::vector<types::global_dof_index> dofs;
    for (const auto &cell : owned_fe_cells)
      {
        fe_values.reinit(
          typename Triangulation<dim>::active_cell_iterator(cell));
        fill_q1_table(fe_values, table);
        dofs.resize(fe.n_dofs_per_cell());
        cell->get_dof_indices(dofs);
        y.resize(cell->n_vertices());
        for (unsigned int b = 0; b < y.size(); ++b)
          y[b] = cell->vertex(b) - cell->vertex(0);
        add(table, y, dofs);
      }
    for (unsigned int f = 0; f < owned_families.size(); ++f)
      {
        const unsigned int k       = owned_families[f];
        const auto         members = families.members(k);
        dofs.resize(members.size() * dim);
        y.resize(members.size());
        for (unsigned int b = 0; b < members.size(); ++b)
          {
            y[b] = particles.position(members[b]) - particles.position(k);
            for (unsigned int c = 0; c < dim; ++c)
              dofs[b * dim + c] = particles.dof(members[b], c);
          }
        add(family_tables[f], y, dofs);
      }
    T.compress(VectorOperation::add);
    S.compress(VectorOperation::add);
  }



  template <int dim>
  void
  Problem<dim>::Implementation::compute_inf_sup()
  {
    using Method = FormulationCode::Method;
    AssertThrow(formulation.method == Method::fem ||
                  formulation.method == Method::pbg,
                ExcBadParameter(
                  "Discretization/Formulation",
                  formulation.text,
                  "the inf-sup test ('Analysis/Type = inf-sup') solves a "
                  "symmetric generalised eigenproblem, and PPG tangents are "
                  "not symmetric: use a PBG formulation (or FEM)."));
    const std::vector<unsigned int> &series = prm.analysis.inf_sup_subdivisions;
    const double       tolerance = prm.analysis.inf_sup_zero_tolerance;
    const unsigned int max_size  = 6000;
    // Refuse too big problems before computing anything: a clamped square
    // has dim (N - 1)^dim free unknowns, fewer constraints give more.
    for (const unsigned int N : series)
      AssertThrow(dim * std::pow(N - 1., dim) <= max_size,
                  ExcBadParameter("Analysis/Inf-sup subdivisions",
                                  std::to_string(N),
                                  "the dense generalised eigensolver handles "
                                  "at most " +
                                    std::to_string(max_size) +
                                    " free unknowns, and this mesh has at "
                                    "least " +
                                    std::to_string(static_cast<unsigned int>(
                                      dim * std::pow(N - 1., dim))) +
                                    ": use fewer subdivisions."));

    RunSummary::InfSup result;
    result.pressure_space = prm.analysis.pressure_space;
    result.zero_tolerance = tolerance;
    const double nan      = std::numeric_limits<double>::quiet_NaN();
    const bool   p0       = (prm.analysis.pressure_space == "P0");
    RunSummary   last;
    for (unsigned int i = 0; i < series.size(); ++i)
      {
        const unsigned int N = series[i];
        // The first mesh echoes its set-up, the others stay quiet.
        std::ostringstream quiet;
        Implementation level(prm, comm, i == 0 ? pcout.get_stream() : quiet);
        level.geometry.mesh              = "hyper rectangle";
        level.geometry.lower_corner      = std::vector<double>(dim, 0.);
        level.geometry.upper_corner      = std::vector<double>(dim, 1.);
        level.geometry.subdivisions      = {N};
        level.geometry.global_refinement = 0;
        level.setup();
        LinearAlgebra::SparseMatrix T, S;
        level.assemble_inf_sup_forms(T, S);
        const Analysis::InfSup::Value value =
          Analysis::InfSup::compute_value(T,
                                          S,
                                          level.zero_constraints,
                                          tolerance,
                                          max_size);
        // n_p: one pressure per element (Q1 cell or family) for P0.
        const double n_p =
          p0 ? level.owned_fe_cells.size() + level.owned_families.size() : nan;
        result.N.push_back(N);
        result.n_dofs.push_back(level.summary.n_dofs);
        result.n_free.push_back(value.n_free);
        result.n_pressure.push_back(n_p);
        result.n_zero.push_back(value.n_zero);
        // (7.15) with k = n_zero + 1
        result.k_pm.push_back(
          p0 ? value.n_zero + 1. - (value.n_free - n_p + 1.) : nan);
        result.beta.push_back(value.beta);
        result.slope.push_back(
          i == 0 ? nan :
                   Analysis::InfSup::loglog_slope(series[i - 1],
                                                  result.beta[i - 1],
                                                  N,
                                                  value.beta));
        result.lambda_max.push_back(value.lambda_max);
        result.largest_zero.push_back(value.largest_zero / value.lambda_max);

        std::ostringstream line;
        line << "  inf-sup N = " << N << ": " << value.n_free << " free DoFs";
        if (p0)
          line << ", " << n_p << " pressures";
        line << ", zero eigenvalues " << value.n_zero << std::setprecision(3)
             << ", beta = " << value.beta;
        if (i > 0)
          line << std::fixed << std::setprecision(2)
               << ", slope = " << result.slope[i];
        pcout << line.str() << std::endl;
        last = level.summary;
      }

    // The table, also as inf_sup.txt.
    std::ostringstream table;
    table << "# inf-sup test (Chapelle & Bathe 1993; dissertation 7.2.5), '"
          << formulation.text << "', pressure space " << result.pressure_space
          << ", distortion " << geometry.distortion << "\n"
          << "# zero eigenvalues: lambda < " << tolerance
          << " lambda_max; beta = sqrt(first non-zero lambda) (7.14); "
          << "slope = -dlog(beta)/dlog(N); k_pm (7.15) for P0 only\n"
          << "# N n_dofs n_u n_p zero k_pm beta slope lambda_max "
          << "largest_zero/lambda_max\n";
    for (unsigned int i = 0; i < result.N.size(); ++i)
      {
        const auto number = [](const double x) {
          std::ostringstream s;
          if (std::isnan(x))
            s << "-";
          else
            s << std::setprecision(6) << x;
          return s.str();
        };
        table << result.N[i] << " " << result.n_dofs[i] << " "
              << result.n_free[i] << " " << number(result.n_pressure[i]) << " "
              << result.n_zero[i] << " " << number(result.k_pm[i]) << " "
              << number(result.beta[i]) << " " << number(result.slope[i]) << " "
              << number(result.lambda_max[i]) << " "
              << number(result.largest_zero[i]) << "\n";
      }
    summary                 = last;
    summary.inf_sup         = result;
    summary.converged       = true;
    summary.timing["total"] = total_timer.wall_time();
    if (root)
      {
        std::ofstream file(prm.output.directory + "/inf_sup.txt");
        file << table.str();
        write_summary_json(summary, prm.output.directory + "/summary.json");
      }
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
        compute_inf_sup();
        return;
      }
    setup();
    update_full_solution();
    if (prm.analysis.type == "eigenmodes")
      {
        compute_eigenmodes();
        return;
      }
    if (prm.time.dynamic())
      {
        run_dynamics();
        return;
      }
    summary.load_steps = 0;
    postprocess_timer.start();
    postprocess(0, 0., 0);
    postprocess_timer.stop();

    LoadStepper::Operations stepping;
    stepping.solve = [this](const double t, unsigned int &iterations) {
      return solve_step(t, iterations);
    };
    stepping.commit = [this]() {
      converged_solution = solution_owned;
      history.commit();
    };
    stepping.revert = [this]() {
      solution_owned = converged_solution;
      update_full_solution();
      history.revert();
    };
    stepping.step_done = [this](const unsigned int step,
                                const double       t,
                                const unsigned int iterations) {
      summary.newton_iterations += iterations;
      summary.load_steps = step;
      summary.converged  = true;
      postprocess_timer.start();
      postprocess(step, t, iterations);
      postprocess_timer.stop();
    };
    stepping.give_up = [this](const unsigned int step, const double t) {
      summary.converged = false;
      write_files(step, t);
    };
    stepping.last_failure = [this]() { return last_failure; };
    LoadStepper(prm.loading, prm.output.directory, pcout).run(stepping);
    const unsigned int n_steps = prm.loading.load_steps;
    postprocess_timer.start();
    // the particle fields, nodal stresses, the final report and the files
    postprocessors.finalize(view(), {n_steps, 1., 0}, statistics, summary);
  }



  template <int dim>
  void
  Problem<dim>::Implementation::write_particle_table(
    const std::vector<Tensor<2, dim>> &F)
  {
    Postprocess::ParticleFields<dim>::write_table(view(), F);
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
    const LinearAlgebra::Vector u_saved = solution;
    solution                            = 0;
    assemble(false);
    solution = u_saved;
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
  double
  Problem<dim>::Implementation::particle_disorder() const
  {
    const unsigned int          n = particles.n_particles();
    std::vector<Point<dim>>     X(n);
    std::vector<Tensor<1, dim>> u(n);
    std::vector<double>         V(n);
    const Vector<double>        u_all = gather_to_all(solution);
    for (unsigned int k = 0; k < n; ++k)
      {
        X[k] = particles.position(k);
        V[k] = particles.volume(k);
        for (unsigned int c = 0; c < dim; ++c)
          u[k][c] = u_all[particles.dof(k, c)];
      }
    std::vector<std::vector<unsigned int>> neighbours(n);
    for (unsigned int k = 0; k < n; ++k)
      for (const unsigned int j : families.members(k))
        if (j != k)
          neighbours[k].push_back(j);
    const double deviation =
      TimeIntegration::local_fit_deviation(X, u, V, neighbours);
    const double reference = disorder_reference > 0 ?
                               disorder_reference :
                               TimeIntegration::rms_about_mean(u, V);
    return reference > 0 ? deviation / reference : 0.;
  }



  template <int dim>
  void
  Problem<dim>::Implementation::add_energy_statistics(const double t)
  {
    auto &d = summary.dynamics;
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
    if (particles.n_particles() > 0)
      {
        d.disorder.push_back(particle_disorder());
        statistics.add_value("disorder", d.disorder.back());
        statistics.set_scientific("disorder", true);
        statistics.set_precision("disorder", 6);
      }
  }



  template <int dim>
  void
  Problem<dim>::Implementation::run_dynamics()
  {
    const auto &time      = prm.time;
    const bool  explicit_ = (time.integrator == "leapfrog");
    auto       &d         = summary.dynamics;
    d.integrator          = time.integrator;

    // Initial conditions at the vertices; the Dirichlet values of t = 0
    // win, and the constrained DoFs start at rest.
    set_load_factor(0.);
    LinearAlgebra::Vector v(owned_dofs, comm);
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int vertex : cell->vertex_indices())
        for (unsigned int c = 0; c < dim; ++c)
          {
            const auto dof = cell->vertex_dof_index(vertex, c);
            if (!owned_dofs.is_element(dof))
              continue;
            solution_owned(dof) =
              prm.initial_displacement.value(cell->vertex(vertex), c);
            v(dof) = prm.initial_velocity.value(cell->vertex(vertex), c);
          }
    solution_owned.compress(VectorOperation::insert);
    v.compress(VectorOperation::insert);
    make_constraints(constraints, false);
    constraints.distribute(solution_owned);
    zero_constraints.distribute(v);
    update_full_solution();
    if (particles.n_particles() > 0)
      {
        std::vector<Tensor<1, dim>> u0(particles.n_particles());
        std::vector<double>         V(particles.n_particles());
        const Vector<double>        u_all = gather_to_all(solution);
        for (unsigned int k = 0; k < u0.size(); ++k)
          {
            V[k] = particles.volume(k);
            for (unsigned int c = 0; c < dim; ++c)
              u0[k][c] = u_all[particles.dof(k, c)];
          }
        disorder_reference = TimeIntegration::rms_about_mean(u0, V);
      }
    assemble_masses(dof_handler,
                    meshfree,
                    zero_constraints,
                    matrix,
                    prm.material.density,
                    !explicit_,
                    masses);
    std::unique_ptr<TimeIntegrator> integrator;
    if (explicit_)
      integrator = std::make_unique<Leapfrog>(masses);
    else
      integrator =
        std::make_unique<Newmark>(masses, prm.time, prm.newton, pcout);

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
      history.commit();
      summary.newton_iterations += iterations;
      summary.load_steps                 = step;
      summary.newton_residuals_last_step = integrator->last_residuals;
    };
    operations.output = [&](const unsigned int step,
                            const double       t,
                            const unsigned int iterations) {
      postprocess_timer.start();
      postprocess(step, t, iterations);
      postprocess_timer.stop();
    };
    operations.give_up = [&](const unsigned int last_step, const double t) {
      history.revert();
      summary.converged = false;
      write_files(last_step, t);
    };
    const TimeStepper::Result result =
      TimeStepper(time, prm.output.directory, pcout)
        .run(*this,
             *integrator,
             masses,
             v,
             energies,
             summary.dynamics.disorder,
             operations);
    const unsigned int n_steps = result.n_steps;
    const double       t       = result.final_time;

    const std::vector<Tensor<2, dim>> F =
      view().particle_deformation_gradients();
    if (particles.n_particles() > 0)
      write_particle_table(F);
    write_nodal_stresses(F);
    if (summary.have_errors)
      pcout << "  errors: L2 relative = " << summary.L2_relative
            << ", H1 relative = " << summary.H1_relative << std::endl;
    if (!explicit_)
      pcout << "  total Newton iterations: " << summary.newton_iterations
            << std::endl;
    write_files(n_steps, t);
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
