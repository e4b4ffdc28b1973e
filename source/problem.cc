#include <pg/analysis/eigenmodes.h>
#include <pg/analysis/inf_sup.h>
#include <pg/base/exceptions.h>
#include <pg/base/formulation_code.h>
#include <pg/base/linear_algebra.h>
#include <pg/elements/cpd_interactions.h>
#include <pg/elements/family_elements.h>
#include <pg/elements/kernel_cost.h>
#include <pg/elements/q1_cell.h>
#include <pg/elements/quadrature_table.h>
#include <pg/elements/second_order_correction.h>
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
#include <pg/solvers/time_integration.h>

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
  class Problem<dim>::Implementation
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
     * constraints) to the solution; false, with a message, if the linear
     * solver does not converge.
     */
    bool
    apply_newton_update();

    void
    update_full_solution();

    /**
     * d^k of every particle from the current family tables (summed over
     * all ranks), and the largest interior value for the summary.
     */
    void
    compute_unit_stress_residual();

    /**
     * Solve the VC system once (pg-methods.md section 11.4-11.7), correct
     * the test (PBG: and trial) functions and rebuild the family tables.
     */
    void
    correct_variational_consistency();

    /**
     * VC2 (section 11.6): the first- and second-order correction of PPG2
     * with option s, then rebuild the family tables.
     */
    void
    correct_second_order_consistency();

    /**
     * Hand the VC factors (and the VC2 factors, if any) to the family
     * elements, record max |alpha^k| h, rebuild the family tables and d^k.
     */
    void
    apply_correction_factors(
      const std::vector<Tensor<1, dim>> &alpha,
      const std::vector<Tensor<2, dim>> &second_order_alpha = {});

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
     * Subtract the FE-consistent dead traction load of the Neumann faces of
     * @p cell from the element residual @p residual (node-major).
     */
    void
    add_face_tractions(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      FEFaceValues<dim>                                    &fe_face_values,
      Vector<double>                                       &residual) const;

    /**
     * 'Time/Integrator' leapfrog or newmark: initial conditions, masses,
     * the stable step estimate and the time loop (instead of the load
     * steps of run()).
     */
    void
    run_dynamics();

    /**
     * The lumped mass rho_0 int N_k of every DoF over all cells
     * (lumped_mass) and its diagonal condensed with zero_constraints
     * (inverse_mass: 1/m at free DoFs, 0 at constrained ones); for
     * @p consistent also the Newmark mass matrices: consistent Q1 mass on
     * the finite element cells, rho_0 V^k on the particles, unconstrained
     * (mass_matrix) and condensed (condensed_mass).
     */
    void
    assemble_mass(const bool consistent);

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
                  LinearAlgebra::Vector       &target) const;

    /**
     * One Newmark step to @p t_new from (u, v, a) = (solution_owned, @p v,
     * @p a): Newton on M a(u) + f_int(u) - f_ext = 0. On success
     * solution_owned, @p v and @p a hold the new state, @p f_ext the new
     * external force, and @p iterations the Newton iterations.
     */
    bool
    newmark_step(const double           t_new,
                 const double           dt,
                 LinearAlgebra::Vector &v,
                 LinearAlgebra::Vector &a,
                 LinearAlgebra::Vector &f_ext,
                 unsigned int          &iterations);

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

    LinearAlgebra::Vector       lumped_mass, inverse_mass;
    LinearAlgebra::SparseMatrix mass_matrix, condensed_mass;
    TimeIntegration::Energies   energies;
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
    LinearAlgebra::Vector       solution, solution_owned, converged_solution;
    LinearAlgebra::Vector       update, rhs, force;
    Vector<double>              u_full;

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

    /** Compute boundary_area_weights from the current d^k. */
    void
    compute_boundary_area_weights();

    std::mutex  failure_mutex;
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
    owned_dofs    = dof_handler.locally_owned_dofs();
    relevant_dofs = complete_index_set(dof_handler.n_dofs());

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

    DynamicSparsityPattern               dsp(relevant_dofs);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : owned_fe_cells)
      {
        cell->get_dof_indices(dofs);
        zero_constraints.add_entries_local_to_global(dofs, dsp, true);
      }
    for (const unsigned int k : owned_families)
      {
        const auto members = families.members(k);
        dofs.resize(members.size() * dim);
        for (unsigned int a = 0; a < members.size(); ++a)
          for (unsigned int c = 0; c < dim; ++c)
            dofs[a * dim + c] = particles.dof(members[a], c);
        if (cpd)
          {
            // one horizon: particle k couples to its neighbours only (the
            // zero blocks of the family's local matrix are not added)
            const std::vector<types::global_dof_index> row(dofs.begin(),
                                                           dofs.begin() + dim);
            zero_constraints.add_entries_local_to_global(row, dofs, dsp, true);
            zero_constraints.add_entries_local_to_global(dofs, row, dsp, true);
          }
        else
          zero_constraints.add_entries_local_to_global(dofs, dsp, true);
      }
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
    u_full.reinit(dof_handler.n_dofs());
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
  }



  namespace
  {
    /** Unit normal of a planar face from its vertices (sign irrelevant). */
    template <typename CellIterator>
    auto
    planar_face_normal(const CellIterator &cell, const unsigned int f)
    {
      constexpr int  dim  = CellIterator::AccessorType::dimension;
      const auto     face = cell->face(f);
      Tensor<1, dim> n;
      if constexpr (dim == 2)
        {
          const Tensor<1, dim> e = face->vertex(1) - face->vertex(0);
          n[0]                   = e[1];
          n[1]                   = -e[0];
        }
      else
        n = cross_product_3d(face->vertex(1) - face->vertex(0),
                             face->vertex(2) - face->vertex(0));
      return n / n.norm();
    }
  } // namespace



  template <int dim>
  void
  Problem<dim>::Implementation::make_constraints(AffineConstraints<double> &c,
                                                 const bool homogeneous) const
  {
    // Built from all cells on every rank (parallel::shared::Triangulation
    // knows them all), so every rank has the constraints of every DoF its
    // families touch, however far they reach.
    c.clear();
    c.reinit(relevant_dofs);

    // The components in @p mask of vertex v of @p object (a cell or a face)
    // take the prescribed values, unless they are constrained already.
    const auto prescribe = [&](const auto              &object,
                               const unsigned int       v,
                               const std::vector<bool> &mask) {
      for (unsigned int comp = 0; comp < dim; ++comp)
        if (mask[comp])
          {
            const types::global_dof_index dof =
              object->vertex_dof_index(v, comp);
            if (c.is_constrained(dof))
              continue;
            c.add_line(dof);
            if (!homogeneous)
              {
                const double value =
                  prm.prescribed_displacement.value(object->vertex(v), comp);
                if (!std::isfinite(value))
                  {
                    std::ostringstream where;
                    where << object->vertex(v);
                    AssertThrow(
                      false,
                      ExcMessage(
                        "The 'Prescribed displacement' function "
                        "of subsection 'Boundary conditions' is "
                        "NaN or inf at (" +
                        where.str() + "), component " +
                        std::string(1, "xyz"[comp]) + ", load factor " +
                        std::to_string(prm.prescribed_displacement.get_time()) +
                        "."));
                  }
                c.set_inhomogeneity(dof, value);
              }
          }
    };

    // Dirichlet first: where a Dirichlet and a symmetry condition meet, the
    // Dirichlet value wins.
    for (const auto &[id, mask] : prm.boundary_conditions.dirichlet)
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == id)
            for (const unsigned int v : cell->face(f)->vertex_indices())
              prescribe(cell->face(f), v, mask);

    for (const auto &[coordinates, mask] : prm.boundary_conditions.fixed_points)
      {
        Point<dim> p;
        for (unsigned int d = 0; d < dim; ++d)
          p[d] = coordinates[d];
        const unsigned int vertex =
          GridTools::find_closest_vertex(dof_handler, p);
        const double tolerance = 1e-8 * mesh_diameter;
        AssertThrow(
          triangulation.get_vertices()[vertex].distance(p) <= tolerance,
          ExcBadParameter(
            "Boundary conditions/Fixed points",
            std::to_string(p[0]) + ", " + std::to_string(p[1]) +
              (dim == 3 ? ", " + std::to_string(p[2]) : std::string()),
            "no mesh vertex lies at this point; the "
            "nearest one is at distance " +
              std::to_string(triangulation.get_vertices()[vertex].distance(p)) +
              "."));
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
            if (cell->vertex_index(v) == vertex)
              {
                prescribe(cell, v, mask);
                break;
              }
      }

    const double box_tolerance = 1e-10 * mesh_diameter;
    for (const auto &box : prm.boundary_conditions.dirichlet_boxes)
      {
        const auto inside = [&](const Point<dim> &p) {
          for (unsigned int d = 0; d < dim; ++d)
            if (p[d] < box.lower[d] - box_tolerance ||
                p[d] > box.upper[d] + box_tolerance)
              return false;
          return true;
        };
        bool found = false;
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
            if (inside(cell->vertex(v)))
              {
                found = true;
                prescribe(cell, v, box.components);
              }
        std::string corners;
        for (const auto *corner : {&box.lower, &box.upper})
          {
            corners += corners.empty() ? "" : " : ";
            for (unsigned int d = 0; d < dim; ++d)
              corners += (d ? ", " : "") + std::to_string((*corner)[d]);
          }
        AssertThrow(found,
                    ExcBadParameter("Boundary conditions/Dirichlet boxes",
                                    corners,
                                    "a box holds no mesh vertex; enlarge it "
                                    "or check its corners against the "
                                    "geometry."));
      }

    for (const types::boundary_id id : prm.boundary_conditions.symmetry)
      {
        // The plane's normal, checked to be the same on every face.
        Tensor<1, dim> normal;
        bool           found = false;
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == id)
              {
                const Tensor<1, dim> n = planar_face_normal(cell, f);
                if (!found)
                  normal = n, found = true;
                AssertThrow(
                  std::abs(std::abs(n * normal) - 1.) < 1e-8,
                  ExcBadParameter("Boundary conditions/Symmetry",
                                  std::to_string(id),
                                  "a symmetry boundary must be planar, but the "
                                  "faces of this boundary id have different "
                                  "normals."));
              }
        AssertThrow(found,
                    ExcBadParameter("Boundary conditions/Symmetry",
                                    std::to_string(id),
                                    "no boundary face has this id."));
        // n . u = 0: solve for the component with the largest |n_c| that
        // is still free.
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == id)
              for (const unsigned int v : cell->face(f)->vertex_indices())
                {
                  std::array<types::global_dof_index, dim> dofs;
                  for (unsigned int comp = 0; comp < dim; ++comp)
                    dofs[comp] = cell->face(f)->vertex_dof_index(v, comp);
                  int pivot = -1;
                  for (unsigned int comp = 0; comp < dim; ++comp)
                    if (!c.is_constrained(dofs[comp]) &&
                        std::abs(normal[comp]) > 1e-12 &&
                        (pivot < 0 ||
                         std::abs(normal[comp]) > std::abs(normal[pivot])))
                      pivot = comp;
                  bool already = false;
                  for (unsigned int comp = 0; comp < dim; ++comp)
                    if (std::abs(normal[comp]) > 1e-12 &&
                        c.is_constrained(dofs[comp]) &&
                        std::abs(normal[comp]) > 1. - 1e-12)
                      already = true;
                  if (pivot < 0 || already)
                    continue;
                  c.add_line(dofs[pivot]);
                  for (unsigned int comp = 0; comp < dim; ++comp)
                    if (static_cast<int>(comp) != pivot &&
                        std::abs(normal[comp]) > 1e-12)
                      c.add_entry(dofs[pivot],
                                  dofs[comp],
                                  -normal[comp] / normal[pivot]);
                }
      }
    c.close();
  }



  template <int dim>
  void
  Problem<dim>::Implementation::compute_boundary_area_weights()
  {
    boundary_area_weights.assign(particles.n_particles(), {});
    for (unsigned int k = 0; k < particles.n_particles(); ++k)
      {
        const auto &areas = particles.boundary_area_vectors(k);
        if (areas.empty())
          continue;
        // least squares d^k = sum_b c_b n_b (the normals are independent at
        // corners; parts with parallel normals share by projection)
        const unsigned int          m = areas.size();
        std::vector<Tensor<1, dim>> n;
        for (const auto &area : areas)
          n.push_back(area.second / area.second.norm());
        FullMatrix<double> G(m, m);
        Vector<double>     rhs(m), c(m);
        for (unsigned int a = 0; a < m; ++a)
          {
            rhs(a) = n[a] * unit_stress[k];
            for (unsigned int b = 0; b < m; ++b)
              G(a, b) = n[a] * n[b];
          }
        bool independent = (m <= dim);
        if (independent)
          {
            FullMatrix<double> copy(G);
            independent = std::abs(copy.determinant()) > 1e-6;
          }
        if (independent)
          {
            G.gauss_jordan();
            G.vmult(c, rhs);
          }
        else
          c = rhs;
        unsigned int a = 0;
        for (const auto &area : areas)
          boundary_area_weights[k][area.first] = c(a++);
      }
  }



  template <int dim>
  void
  Problem<dim>::Implementation::compute_unit_stress_residual()
  {
    std::vector<double>         d(particles.n_particles() * dim, 0.);
    std::vector<Tensor<1, dim>> local;
    for (unsigned int f = 0; f < owned_families.size(); ++f)
      {
        const auto members = families.members(owned_families[f]);
        local.assign(members.size(), Tensor<1, dim>());
        add_unit_stress_residual(family_tables[f], local);
        for (unsigned int a = 0; a < members.size(); ++a)
          for (unsigned int c = 0; c < dim; ++c)
            d[members[a] * dim + c] += local[a][c];
      }
    Utilities::MPI::sum(d, comm, d);
    unit_stress.resize(particles.n_particles());
    summary.max_interior_unit_stress_residual = 0;
    for (unsigned int k = 0; k < particles.n_particles(); ++k)
      {
        for (unsigned int c = 0; c < dim; ++c)
          unit_stress[k][c] = d[k * dim + c];
        if (particles.boundary_area_vectors(k).empty() &&
            !particles.on_interface(k))
          summary.max_interior_unit_stress_residual =
            std::max(summary.max_interior_unit_stress_residual,
                     unit_stress[k].norm() /
                       std::pow(particles.spacing(k), dim - 1));
      }
    compute_boundary_area_weights();
  }



  template <int dim>
  void
  Problem<dim>::Implementation::correct_second_order_consistency()
  {
    const unsigned int n = particles.n_particles();
    std::vector<bool>  fixed(n, false);
    for (unsigned int k = 0; k < n; ++k)
      {
        AssertThrow(!particles.on_interface(k),
                    ExcBadParameter("Discretization/Formulation",
                                    formulation.text,
                                    "VC2 needs a body that is meshfree "
                                    "everywhere: set 'Meshfree region = all' "
                                    "in subsection 'Geometry', or use a "
                                    "first-order VC code."));
        fixed[k] = !particles.boundary_area_vectors(k).empty();
      }
    const SecondOrderCorrection<dim> correction =
      solve_second_order_correction(particles,
                                    families,
                                    *family_elements,
                                    fixed);
    summary.max_interior_second_order_residual =
      correction.max_second_order_residual_after;
    apply_correction_factors(correction.alpha, correction.second_order_alpha);
  }



  template <int dim>
  void
  Problem<dim>::Implementation::apply_correction_factors(
    const std::vector<Tensor<1, dim>> &alpha,
    const std::vector<Tensor<2, dim>> &second_order_alpha)
  {
    // The size of the correction, relative to the gradients (~1/h): large
    // values mean strongly modified test functions.
    summary.max_correction_factor = 0;
    for (unsigned int k = 0; k < alpha.size(); ++k)
      summary.max_correction_factor =
        std::max(summary.max_correction_factor,
                 alpha[k].norm() * particles.spacing(k));
    family_elements->set_correction_factors(alpha, second_order_alpha);
    for (unsigned int f = 0; f < owned_families.size(); ++f)
      family_elements->build(owned_families[f], family_tables[f]);
    compute_unit_stress_residual();
  }



  template <int dim>
  void
  Problem<dim>::Implementation::correct_variational_consistency()
  {
    if (formulation.second_order_consistency)
      {
        correct_second_order_consistency();
        return;
      }
    using VCBoundary     = FormulationCode::VCBoundary;
    const unsigned int n = particles.n_particles();
    // How the rows of every particle read (section 11.5):
    //   interior:   d^k(alpha) = target^k: 0, the area vector for p, and
    //               on the FE/meshfree interface the area vector of the
    //               meshfree side, so that FE and PG contributions of a
    //               constant stress cancel there (coupled patch test),
    //   tangential: n . alpha^k = 0 and t . d^k(alpha) = 0 (sn),
    //   fixed:      alpha^k = 0 (s; sn at edges and corners; p at d+1
    //               particles).
    enum class Row
    {
      interior,
      tangential,
      fixed
    };
    std::vector<Row>            kind(n, Row::interior);
    std::vector<Tensor<2, dim>> R(n, unit_symmetric_tensor<dim>());
    std::vector<Tensor<1, dim>> normal(n), target(n);
    std::vector<unsigned int>   surface;
    for (unsigned int k = 0; k < n; ++k)
      {
        const auto &areas = particles.boundary_area_vectors(k);
        if (particles.on_interface(k))
          {
            // full target: the interface area plus any surface area
            target[k] = particles.interface_area_vector(k);
            for (const auto &area : areas)
              target[k] += area.second;
            continue;
          }
        if (areas.empty())
          continue;
        surface.push_back(k);
        for (const auto &area : areas)
          normal[k] += area.second;
        if (formulation.vc_boundary == VCBoundary::p)
          target[k] = normal[k];
        normal[k] /= normal[k].norm();
        if (formulation.vc_boundary == VCBoundary::s ||
            (formulation.vc_boundary == VCBoundary::sn &&
             particles.at_corner(k)))
          kind[k] = Row::fixed;
        else if (formulation.vc_boundary == VCBoundary::sn)
          {
            // rows: [0; t_1; t_2], the tangents orthonormal to n
            kind[k] = Row::tangential;
            R[k]    = Tensor<2, dim>();
            Tensor<1, dim> t;
            if constexpr (dim == 2)
              {
                t[0]    = -normal[k][1];
                t[1]    = normal[k][0];
                R[k][1] = t;
              }
            else
              {
                unsigned int axis = 0;
                for (unsigned int c = 1; c < dim; ++c)
                  if (std::abs(normal[k][c]) < std::abs(normal[k][axis]))
                    axis = c;
                t = Point<dim>::unit_vector(axis);
                t -= (t * normal[k]) * normal[k];
                t /= t.norm();
                R[k][1] = t;
                R[k][2] = cross_product_3d(normal[k], t);
              }
          }
      }
    // Without a free surface (option p, or particles embedded in finite
    // elements) every row has a full target and the system has the nullity
    // d (d + 1) of the discrete Gauss identities. Fixing alpha at d + 1
    // particles spread over the boundary removes it (one particle for
    // PPG2, see below); the dropped equations
    // then hold automatically, since the targets obey the same identities.
    bool free_surface = false;
    for (unsigned int k = 0; k < n; ++k)
      free_surface = free_surface || (kind[k] != Row::interior);
    for (unsigned int k = 0; k < n; ++k)
      if (particles.on_interface(k) &&
          particles.boundary_area_vectors(k).empty())
        surface.push_back(k);
    if (formulation.vc_boundary == VCBoundary::p || !free_surface)
      {
        AssertThrow(surface.size() > dim,
                    ExcMessage("The VC correction needs at least dim + 1 "
                               "particles on the boundary of the meshfree "
                               "region."));
        std::vector<unsigned int> chosen = {surface[0]};
        const auto distance_to_chosen    = [&](const unsigned int k) {
          // distance to the affine hull of the chosen particles
          std::vector<Tensor<1, dim>> basis;
          for (unsigned int i = 1; i < chosen.size(); ++i)
            {
              Tensor<1, dim> e =
                particles.position(chosen[i]) - particles.position(chosen[0]);
              for (const auto &b : basis)
                e -= (e * b) * b;
              if (e.norm() > 0)
                basis.push_back(e / e.norm());
            }
          Tensor<1, dim> r =
            particles.position(k) - particles.position(chosen[0]);
          for (const auto &b : basis)
            r -= (r * b) * b;
          return r.norm();
        };
        // PPG2 test functions keep only sum_k d^k = 0 (section 11.4): its
        // nullity is d, so one particle is fixed. So is a V1 correction
        // anywhere (PPG interface masters use V1, family_elements.cc):
        // V1 does not preserve first-order consistency, so
        // sum_k X^k (x) d^k depends on alpha.
        bool first_order_identity =
          formulation.method != FormulationCode::Method::ppg2;
        for (unsigned int k = 0; k < n; ++k)
          if (family_elements->family_correction_function(k) ==
              FormulationCode::CorrectionFunction::v1)
            first_order_identity = false;
        const unsigned int n_fixed = (first_order_identity ? dim + 1 : 1);
        while (chosen.size() < n_fixed)
          {
            unsigned int best = surface[0];
            for (const unsigned int k : surface)
              if (distance_to_chosen(k) > distance_to_chosen(best))
                best = k;
            chosen.push_back(best);
          }
        for (const unsigned int k : chosen)
          kind[k] = Row::fixed;
      }

    matrix = 0;
    rhs    = 0;
    update = 0;
    for (const unsigned int k : owned_families)
      family_elements->for_each_correction_block(
        k,
        [&](const unsigned int    a,
            const unsigned int    f,
            const Tensor<2, dim> &C) {
          if (kind[a] == Row::fixed)
            return;
          const Tensor<2, dim> RC = R[a] * C;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int c = 0; c < dim; ++c)
              if (RC[i][c] != 0.)
                matrix.add(particles.dof(a, i), particles.dof(f, c), RC[i][c]);
        });
    std::vector<bool> is_particle_dof(dof_handler.n_dofs(), false);
    for (unsigned int k = 0; k < n; ++k)
      {
        for (unsigned int c = 0; c < dim; ++c)
          is_particle_dof[particles.dof(k, c)] = true;
        if (!owned_dofs.is_element(particles.dof(k, 0)))
          continue;
        const Tensor<1, dim> r = R[k] * (target[k] - unit_stress[k]);
        for (unsigned int i = 0; i < dim; ++i)
          {
            const auto row = particles.dof(k, i);
            if (kind[k] == Row::fixed)
              matrix.add(row, row, 1.);
            else if (kind[k] == Row::tangential && i == 0)
              for (unsigned int c = 0; c < dim; ++c)
                matrix.add(row, particles.dof(k, c), normal[k][c]);
            else
              rhs(row) = r[i];
          }
      }
    for (const auto dof : owned_dofs)
      if (!is_particle_dof[dof])
        matrix.add(dof, dof, 1.);
    matrix.compress(VectorOperation::add);
    rhs.compress(VectorOperation::insert);

    // The system can be singular but consistent: with FE coupling plus a
    // free surface, affine fields tangential on the surface give rows that
    // do not depend on alpha (doc/element-view.md section 5). A direct
    // solve would then return an ordering-dependent member of the solution
    // set. Iterative refinement with a slightly shifted factorization,
    //   alpha <- alpha + (A + eps D)^{-1} (b - A alpha),  alpha_0 = 0,
    // converges in a few steps on the regular part (eps << |lambda|) and
    // keeps the null-space part at zero: the same factors on any number of
    // MPI ranks. D is the largest entry of each row.
    const unsigned int corrections =
      solve_by_shifted_refinement(matrix, update, rhs, 1e-9, 1e-14, 50);
    AssertThrow(corrections < 50,
                ExcMessage("The VC system could not be solved: change "
                           "the VC boundary option of 'Formulation' in "
                           "subsection 'Discretization' (p, s or sn), or "
                           "check for coincident particles (unmerged mesh "
                           "vertices: 'Coincident vertices' in subsection "
                           "'Geometry')."));
    LinearAlgebra::Vector ghosted(owned_dofs, relevant_dofs, comm);
    ghosted = update;
    std::vector<Tensor<1, dim>> alpha(n);
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int c = 0; c < dim; ++c)
        alpha[k][c] = ghosted[particles.dof(k, c)];
    AssertThrow(std::all_of(alpha.begin(),
                            alpha.end(),
                            [](const Tensor<1, dim> &a) {
                              return std::isfinite(a.norm());
                            }),
                ExcMessage("The VC system is singular: change the VC "
                           "boundary option of 'Formulation' in subsection "
                           "'Discretization' (p, s or sn)."));

    apply_correction_factors(alpha);
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
    solution = solution_owned;
    for (types::global_dof_index i = 0; i < u_full.size(); ++i)
      u_full[i] = solution[i];
  }



  namespace
  {
    template <int dim>
    struct Scratch
    {
      Scratch(const FiniteElement<dim> &fe_scalar)
        : fe_values(fe_scalar,
                    QGauss<dim>(2),
                    update_gradients | update_values |
                      update_quadrature_points | update_JxW_values)
        , fe_face_values(fe_scalar,
                         QGauss<dim - 1>(2),
                         update_values | update_quadrature_points |
                           update_normal_vectors | update_JxW_values)
      {}
      Scratch(const Scratch &other)
        : fe_values(other.fe_values.get_fe(),
                    other.fe_values.get_quadrature(),
                    other.fe_values.get_update_flags())
        , fe_face_values(other.fe_face_values.get_fe(),
                         other.fe_face_values.get_quadrature(),
                         other.fe_face_values.get_update_flags())
      {}
      FEValues<dim>               fe_values;
      FEFaceValues<dim>           fe_face_values;
      QuadratureTable<dim>        table;
      std::vector<Tensor<1, dim>> y;
    };

    struct Copy
    {
      std::vector<types::global_dof_index> dofs;
      FullMatrix<double>                   matrix;
      /** f_int - f_ext of the element */
      Vector<double> residual;
      bool           with_matrix = true;
    };
  } // namespace



  template <int dim>
  bool
  Problem<dim>::Implementation::is_neumann(const types::boundary_id id) const
  {
    const auto &bc = prm.boundary_conditions;
    return std::find(bc.neumann.begin(), bc.neumann.end(), id) !=
             bc.neumann.end() ||
           std::find(bc.neumann_stress.begin(), bc.neumann_stress.end(), id) !=
             bc.neumann_stress.end();
  }



  template <int dim>
  Tensor<1, dim>
  Problem<dim>::Implementation::prescribed_traction(
    const types::boundary_id id,
    const Point<dim>        &point,
    const Tensor<1, dim>    &normal) const
  {
    const auto    &stress_ids = prm.boundary_conditions.neumann_stress;
    Tensor<1, dim> t;
    if (std::find(stress_ids.begin(), stress_ids.end(), id) == stress_ids.end())
      {
        for (unsigned int c = 0; c < dim; ++c)
          t[c] = prm.traction.value(point, c);
        return t;
      }
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        t[i] += prm.boundary_stress.value(point, i * dim + j) * normal[j];
    return t;
  }



  template <int dim>
  bool
  Problem<dim>::Implementation::has_neumann_face(
    const typename DoFHandler<dim>::active_cell_iterator &cell) const
  {
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary() &&
          is_neumann(cell->face(f)->boundary_id()))
        return true;
    return false;
  }



  template <int dim>
  void
  Problem<dim>::Implementation::add_face_tractions(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    FEFaceValues<dim>                                    &fe_face_values,
    Vector<double>                                       &residual) const
  {
    for (const unsigned int face : cell->face_indices())
      if (cell->face(face)->at_boundary() &&
          is_neumann(cell->face(face)->boundary_id()))
        {
          fe_face_values.reinit(
            typename Triangulation<dim>::active_cell_iterator(cell),
            face);
          for (const unsigned int q : fe_face_values.quadrature_point_indices())
            {
              const Tensor<1, dim> f =
                prescribed_traction(cell->face(face)->boundary_id(),
                                    fe_face_values.quadrature_point(q),
                                    fe_face_values.normal_vector(q));
              for (unsigned int b = 0; b < cell->n_vertices(); ++b)
                for (unsigned int c = 0; c < dim; ++c)
                  residual(b * dim + c) -= f[c] *
                                           fe_face_values.shape_value(b, q) *
                                           fe_face_values.JxW(q);
            }
        }
  }



  namespace
  {
    /** Whether a local vector (and matrix) has only finite entries. */
    bool
    all_finite(const Vector<double> &v, const FullMatrix<double> *m)
    {
      for (const double x : v)
        if (!std::isfinite(x))
          return false;
      if (m == nullptr || m->m() == 0 || m->n() == 0)
        return true;
      // the entries are contiguous; x * 0 is NaN exactly for NaN and inf,
      // and a raw loop keeps this cheap in Debug builds (CPD families hold
      // 10^5 entries and more)
      const double     *entries = &(*m)(0, 0);
      const std::size_t n       = std::size_t(m->m()) * m->n();
      double            sum     = 0;
      for (std::size_t e = 0; e < n; ++e)
        sum += entries[e] * 0.;
      return sum == 0.;
    }

    /** The message for a NaN or inf in an element's residual or tangent. */
    template <int dim>
    std::string
    non_finite_message(const std::string &element,
                       const Point<dim>  &where,
                       const std::string &hint)
    {
      std::ostringstream s;
      s << "NaN or inf in the residual or tangent of " << element << " at ("
        << where << "). " << hint;
      return s.str();
    }
  } // namespace



  template <int dim>
  void
  Problem<dim>::Implementation::assemble(const bool with_matrix)
  {
    Timer timer;
    if (with_matrix)
      matrix = 0;
    rhs   = 0;
    force = 0;
    failure.clear();
    const auto &body_force = prm.body_force;

    const auto copier = [&](const Copy &copy) {
      if (copy.dofs.empty())
        return;
      Vector<double> minus_residual(copy.residual);
      minus_residual *= -1.;
      if (copy.with_matrix)
        zero_constraints.distribute_local_to_global(copy.matrix,
                                                    minus_residual,
                                                    copy.dofs,
                                                    matrix,
                                                    rhs);
      else
        zero_constraints.distribute_local_to_global(minus_residual,
                                                    copy.dofs,
                                                    rhs);
      force.add(copy.dofs, copy.residual);
    };
    const auto record_failure = [&](const std::exception &e) {
      // a deal.II exception's own message, without the source location
      std::string       message = e.what();
      const auto *const exc     = dynamic_cast<const ExceptionBase *>(&e);
      if (exc != nullptr)
        {
          std::ostringstream info;
          exc->print_info(info);
          message = Utilities::trim(info.str());
        }
      std::lock_guard<std::mutex> lock(failure_mutex);
      if (failure.empty())
        failure = message;
    };

    Timer loop_timer;
    using CellIterator = typename std::vector<
      typename DoFHandler<dim>::active_cell_iterator>::const_iterator;
    WorkStream::run(
      owned_fe_cells.cbegin(),
      owned_fe_cells.cend(),
      [&](const CellIterator &it, Scratch<dim> &scratch, Copy &copy) {
        copy.dofs.clear();
        try
          {
            const auto &cell = *it;
            scratch.fe_values.reinit(
              typename Triangulation<dim>::active_cell_iterator(cell));
            fill_q1_table(scratch.fe_values, scratch.table);
            const unsigned int n = cell->n_vertices();
            copy.dofs.resize(n * dim);
            cell->get_dof_indices(copy.dofs);
            scratch.y.resize(n);
            for (unsigned int b = 0; b < n; ++b)
              for (unsigned int c = 0; c < dim; ++c)
                scratch.y[b][c] = cell->vertex(b)[c] - cell->vertex(0)[c] +
                                  u_full[copy.dofs[b * dim + c]];
            copy.with_matrix = with_matrix;
            assemble_element(scratch.table,
                             scratch.y,
                             *material,
                             copy.residual,
                             with_matrix ? &copy.matrix : nullptr);

            // body force and dead traction on finite element cells
            Vector<double> f(dim);
            if (!prm.zero_body_force)
              for (const unsigned int q :
                   scratch.fe_values.quadrature_point_indices())
                {
                  body_force.vector_value(scratch.fe_values.quadrature_point(q),
                                          f);
                  for (unsigned int b = 0; b < n; ++b)
                    for (unsigned int c = 0; c < dim; ++c)
                      copy.residual(b * dim + c) -=
                        f(c) * scratch.fe_values.shape_value(b, q) *
                        scratch.fe_values.JxW(q);
                }
            add_face_tractions(cell, scratch.fe_face_values, copy.residual);
            if (!all_finite(copy.residual,
                            with_matrix ? &copy.matrix : nullptr))
              throw std::runtime_error(non_finite_message(
                "Q1 cell " + std::to_string(cell->active_cell_index()),
                cell->center(),
                "Check the 'Traction', 'Body force' and 'Prescribed "
                "displacement' functions, the material, and the cell "
                "(degenerate or inverted)."));
          }
        catch (const std::exception &e)
          {
            copy.dofs.clear();
            record_failure(e);
          }
      },
      copier,
      Scratch<dim>(fe_scalar),
      Copy());

    auto &cost = summary.assembly_cost;
    if (with_matrix)
      {
        ++cost.n_assemblies;
        cost.fe_seconds += loop_timer.wall_time();
      }
    loop_timer.restart();
    using FamilyIterator = std::vector<unsigned int>::const_iterator;
    std::vector<unsigned int> family_index(owned_families.size());
    for (unsigned int f = 0; f < family_index.size(); ++f)
      family_index[f] = f;
    WorkStream::run(
      family_index.cbegin(),
      family_index.cend(),
      [&](const FamilyIterator &it, Scratch<dim> &scratch, Copy &copy) {
        copy.dofs.clear();
        try
          {
            const unsigned int k       = owned_families[*it];
            const auto         members = families.members(k);
            const unsigned int n       = members.size();
            copy.dofs.resize(n * dim);
            scratch.y.resize(n);
            for (unsigned int b = 0; b < n; ++b)
              for (unsigned int c = 0; c < dim; ++c)
                {
                  copy.dofs[b * dim + c] = particles.dof(members[b], c);
                  scratch.y[b][c]        = particles.position(members[b])[c] -
                                    particles.position(k)[c] +
                                    u_full[copy.dofs[b * dim + c]];
                }
            copy.with_matrix = with_matrix;
            if (cpd)
              cpd->assemble(k,
                            scratch.y,
                            copy.residual,
                            with_matrix ? &copy.matrix : nullptr);
            else
              assemble_element(family_tables[*it],
                               scratch.y,
                               *material,
                               copy.residual,
                               with_matrix ? &copy.matrix : nullptr);
            if (!all_finite(copy.residual,
                            with_matrix ? &copy.matrix : nullptr))
              throw std::runtime_error(non_finite_message(
                "the family of particle " + std::to_string(k),
                particles.position(k),
                "Coincident particles (e.g. unmerged mesh vertices), an "
                "empty or degenerate family, or a NaN in the prescribed "
                "displacement make it."));
          }
        catch (const std::exception &e)
          {
            copy.dofs.clear();
            record_failure(e);
          }
      },
      copier,
      Scratch<dim>(fe_scalar),
      Copy());
    if (with_matrix)
      cost.family_seconds += loop_timer.wall_time();

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
            body_force.vector_value(particles.position(k), f);
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
        if (!all_finite(local, nullptr) && failure.empty())
          failure =
            non_finite_message("the load of particle " + std::to_string(k),
                               particles.position(k),
                               "Check the 'Traction' and 'Body "
                               "force' functions.");
        for (unsigned int c = 0; c < dim; ++c)
          dofs[c] = particles.dof(k, c);
        zero_constraints.distribute_local_to_global(local, dofs, rhs);
        local *= -1.;
        force.add(dofs, local);
      }
    // 'geometry': the FE-consistent load on the meshfree boundary faces.
    {
      Scratch<dim> scratch(fe_scalar);
      Copy         copy;
      for (const auto &cell : owned_meshfree_neumann_cells)
        {
          copy.dofs.resize(fe.n_dofs_per_cell());
          cell->get_dof_indices(copy.dofs);
          copy.residual.reinit(copy.dofs.size());
          copy.with_matrix = false;
          add_face_tractions(cell, scratch.fe_face_values, copy.residual);
          if (!all_finite(copy.residual, nullptr) && failure.empty())
            failure =
              non_finite_message("the traction on meshfree cell " +
                                   std::to_string(cell->active_cell_index()),
                                 cell->center(),
                                 "Check the 'Traction' function.");
          copier(copy);
        }
    }

    if (with_matrix)
      matrix.compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);
    force.compress(VectorOperation::add);
    if (failure.empty() && !std::isfinite(rhs.l2_norm()))
      failure = "NaN or inf in the assembled residual (none in the "
                "elements' own contributions: check the constraints and "
                "'Prescribed displacement').";
    time_assembly += timer.wall_time();
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

    summary.newton_residuals_last_step.clear();
    double             first = 0;
    std::ostringstream line;
    line << std::scientific << std::setprecision(2);
    iterations = 0;
    for (unsigned int it = 0; it <= prm.newton.maximum_iterations; ++it)
      {
        assemble(true);
        const bool failed =
          Utilities::MPI::max(failure.empty() ? 0 : 1, comm) > 0;
        if (failed)
          {
            last_failure =
              failure.empty() ? "the assembly failed on another rank" : failure;
            pcout << "    assembly failed"
                  << (failure.empty() ? "" : ": " + failure.substr(0, 400))
                  << std::endl;
            return false;
          }
        const double residual = rhs.l2_norm();
        summary.newton_residuals_last_step.push_back(residual);
        if (it == 0)
          first = residual;
        if (!std::isfinite(residual))
          {
            // never print a NaN residual as a ratio 0
            line << " " << residual;
            last_failure = "the Newton residual is not finite (|R| = " +
                           std::to_string(residual) + ")";
            break;
          }
        line << " " << (first > 0 ? residual / first : 0.);
        if (residual <= prm.newton.absolute_tolerance ||
            residual <= prm.newton.relative_tolerance * first)
          {
            pcout << "    Newton " << it << ": |R|/|R_0| =" << line.str()
                  << std::endl;
            summary.newton_residuals.push_back(
              summary.newton_residuals_last_step);
            return true;
          }
        if (it == prm.newton.maximum_iterations)
          break;

        if (!apply_newton_update())
          return false;
        ++iterations;
      }
    pcout << "    Newton did not converge: |R|/|R_0| =" << line.str()
          << std::endl;
    return false;
  }



  template <int dim>
  bool
  Problem<dim>::Implementation::apply_newton_update()
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

    const unsigned int n_steps = prm.loading.load_steps;
    double             t       = 0;
    for (unsigned int step = 1; step <= n_steps; ++step)
      {
        const double       target = static_cast<double>(step) / n_steps;
        double             dt     = target - t;
        unsigned int       cuts   = 0;
        std::ostringstream header;
        header << "  load step " << step << ", t = " << target;
        pcout << header.str() << std::endl;
        unsigned int step_iterations = 0;
        while (t < target - 1e-14)
          {
            const double t_new      = std::min(target, t + dt);
            converged_solution      = solution_owned;
            unsigned int iterations = 0;
            if (solve_step(t_new, iterations))
              {
                t = t_new;
                step_iterations += iterations;
                continue;
              }
            solution_owned = converged_solution;
            update_full_solution();
            if (++cuts > prm.loading.maximum_step_cuts)
              {
                summary.converged = false;
                write_files(step, t);
                AssertThrow(
                  false,
                  ExcMessage(
                    "Load step " + std::to_string(step) +
                    " did not converge after " +
                    std::to_string(prm.loading.maximum_step_cuts) +
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
                    prm.output.directory + "'."));
              }
            dt /= 2;
            pcout << "    cutting the step to dt = " << dt << std::endl;
          }
        summary.newton_iterations += step_iterations;
        summary.load_steps = step;
        summary.converged  = true;
        postprocess_timer.start();
        postprocess(step, t, step_iterations);
        postprocess_timer.stop();
      }
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
  Problem<dim>::Implementation::assemble_mass(const bool consistent)
  {
    const double rho = prm.material.density;
    // Lumped: every rank sums over all cells (the shared triangulation
    // knows them), so the full vector needs no communication.
    Vector<double>     m(dof_handler.n_dofs());
    FEValues<dim>      fe_values(fe_scalar,
                            QGauss<dim>(2),
                            update_values | update_JxW_values);
    const unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    FullMatrix<double>                   local(dofs.size(), dofs.size());
    if (consistent)
      {
        mass_matrix.copy_from(matrix);
        mass_matrix = 0;
        condensed_mass.copy_from(matrix);
        condensed_mass = 0;
      }
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(
          typename Triangulation<dim>::active_cell_iterator(cell));
        cell->get_dof_indices(dofs);
        local             = 0;
        const bool lumped = !consistent || meshfree[cell->active_cell_index()];
        for (unsigned int a = 0; a < n_vertices; ++a)
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              const double w =
                rho * fe_values.shape_value(a, q) * fe_values.JxW(q);
              for (unsigned int c = 0; c < dim; ++c)
                m[dofs[a * dim + c]] += w;
              if (lumped)
                for (unsigned int c = 0; c < dim; ++c)
                  local(a * dim + c, a * dim + c) += w;
              else
                for (unsigned int b = 0; b < n_vertices; ++b)
                  for (unsigned int c = 0; c < dim; ++c)
                    local(a * dim + c, b * dim + c) +=
                      w * fe_values.shape_value(b, q);
            }
        if (consistent && cell->is_locally_owned())
          {
            mass_matrix.add(dofs, local);
            zero_constraints.distribute_local_to_global(local,
                                                        dofs,
                                                        condensed_mass);
          }
      }
    if (consistent)
      {
        mass_matrix.compress(VectorOperation::add);
        condensed_mass.compress(VectorOperation::add);
      }

    // The diagonal of C^T M C for the homogeneous constraints.
    Vector<double> m_condensed(m);
    for (const auto &line : zero_constraints.get_lines())
      {
        for (const auto &[j, c] : line.entries)
          m_condensed[j] += c * c * m[line.index];
        m_condensed[line.index] = 0;
      }
    lumped_mass.reinit(owned_dofs, comm);
    inverse_mass.reinit(owned_dofs, comm);
    for (const auto i : owned_dofs)
      {
        AssertThrow(m[i] > 0,
                    ExcBadParameter("Material/Density",
                                    std::to_string(rho),
                                    "dynamics needs a positive density."));
        lumped_mass(i)  = m[i];
        inverse_mass(i) = m_condensed[i] > 0 ? 1. / m_condensed[i] : 0.;
      }
    lumped_mass.compress(VectorOperation::insert);
    inverse_mass.compress(VectorOperation::insert);
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
  bool
  Problem<dim>::Implementation::newmark_step(const double           t_new,
                                             const double           dt,
                                             LinearAlgebra::Vector &v,
                                             LinearAlgebra::Vector &a,
                                             LinearAlgebra::Vector &f_ext,
                                             unsigned int          &iterations)
  {
    const double beta = prm.time.beta, gamma = prm.time.gamma;
    const double c0 = 1. / (beta * dt * dt);
    set_load_factor(t_new);
    compute_external_force(f_ext);
    if (prm.boundary_conditions.prescribes_values())
      make_constraints(constraints, false);
    // the predictor u~ = u + dt v + dt^2 (1/2 - beta) a, i.e. a_new = 0
    LinearAlgebra::Vector u_tilde(solution_owned);
    u_tilde.add(dt, v, dt * dt * (0.5 - beta), a);
    solution_owned = u_tilde;
    constraints.distribute(solution_owned);
    update_full_solution();

    LinearAlgebra::Vector a_new(owned_dofs, comm), Ma(owned_dofs, comm);
    summary.newton_residuals_last_step.clear();
    double             reference = 0;
    std::ostringstream line;
    line << std::scientific << std::setprecision(2);
    iterations = 0;
    for (unsigned int it = 0; it <= prm.newton.maximum_iterations; ++it)
      {
        assemble(true);
        if (Utilities::MPI::max(failure.empty() ? 0 : 1, comm) > 0)
          {
            last_failure =
              failure.empty() ? "the assembly failed on another rank" : failure;
            pcout << "    assembly failed"
                  << (failure.empty() ? "" : ": " + failure.substr(0, 400))
                  << std::endl;
            return false;
          }
        a_new = solution_owned;
        a_new -= u_tilde;
        a_new *= c0;
        mass_matrix.vmult(Ma, a_new);
        const double static_norm = rhs.l2_norm();
        add_condensed(Ma, -1., rhs);
        matrix.add(c0, condensed_mass);
        const double residual = rhs.l2_norm();
        summary.newton_residuals_last_step.push_back(residual);
        if (it == 0)
          reference = std::max({residual, static_norm, Ma.l2_norm()});
        if (!std::isfinite(residual))
          {
            line << " " << residual;
            last_failure = "the Newton residual is not finite (|R| = " +
                           std::to_string(residual) + ")";
            break;
          }
        line << " " << (reference > 0 ? residual / reference : 0.);
        if (residual <= prm.newton.absolute_tolerance ||
            residual <= prm.newton.relative_tolerance * reference)
          {
            v.add(dt * (1. - gamma), a, dt * gamma, a_new);
            a = a_new;
            return true;
          }
        if (it == prm.newton.maximum_iterations)
          break;
        if (!apply_newton_update())
          return false;
        ++iterations;
      }
    pcout << "    Newton did not converge: |R|/|R_0| =" << line.str()
          << std::endl;
    return false;
  }



  template <int dim>
  double
  Problem<dim>::Implementation::particle_disorder() const
  {
    const unsigned int          n = particles.n_particles();
    std::vector<Point<dim>>     X(n);
    std::vector<Tensor<1, dim>> u(n);
    std::vector<double>         V(n);
    for (unsigned int k = 0; k < n; ++k)
      {
        X[k] = particles.position(k);
        V[k] = particles.volume(k);
        for (unsigned int c = 0; c < dim; ++c)
          u[k][c] = u_full[particles.dof(k, c)];
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
    const auto  &time      = prm.time;
    const bool   explicit_ = (time.integrator == "leapfrog");
    const double T         = time.end_time;
    auto        &d         = summary.dynamics;
    d.integrator           = time.integrator;

    // Initial conditions at the vertices; the Dirichlet values of t = 0
    // win, and the constrained DoFs start at rest.
    set_load_factor(0.);
    LinearAlgebra::Vector v(owned_dofs, comm), a(owned_dofs, comm);
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
        for (unsigned int k = 0; k < u0.size(); ++k)
          {
            V[k] = particles.volume(k);
            for (unsigned int c = 0; c < dim; ++c)
              u0[k][c] = u_full[particles.dof(k, c)];
          }
        disorder_reference = TimeIntegration::rms_about_mean(u0, V);
      }
    // 1 at the constrained DoFs
    LinearAlgebra::Vector constrained(owned_dofs, comm);
    for (const auto i : owned_dofs)
      if (zero_constraints.is_constrained(i))
        constrained(i) = 1.;
    constrained.compress(VectorOperation::insert);

    // The stable step from the tangent of the initial state.
    assemble(true);
    AssertThrow(failure.empty(), ExcMessage(failure));
    assemble_mass(!explicit_);
    const double omega2 =
      TimeIntegration::largest_eigenvalue(matrix, inverse_mass);
    const double dt_stable = omega2 > 0 ? 2. / std::sqrt(omega2) : T;
    d.stable_time_step     = dt_stable;
    {
      std::ostringstream line;
      line << std::setprecision(4) << "  time integrator: " << time.integrator
           << ", stable leapfrog step 2/omega_max = " << dt_stable
           << " (omega_max = " << std::sqrt(omega2) << ")";
      pcout << line.str() << std::endl;
    }
    const auto text = [](const double x) {
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
    double dt =
      time.time_step > 0 ? time.time_step : time.safety_factor * dt_stable;
    const unsigned int n_steps =
      std::max(1., std::ceil(T / dt - 1e-9 * T / dt));
    dt          = T / n_steps;
    d.n_steps   = n_steps;
    d.time_step = dt;
    {
      std::ostringstream line;
      line << std::setprecision(4) << "  time step " << dt << ", " << n_steps
           << " steps to t = " << T;
      pcout << line.str() << std::endl;
    }

    // The state at t = 0: accelerations and energies.
    LinearAlgebra::Vector f_ext(owned_dofs, comm), f_int(owned_dofs, comm),
      Ma(owned_dofs, comm), u_old(owned_dofs, comm), du(owned_dofs, comm),
      r_old(owned_dofs, comm), r_new(owned_dofs, comm);
    compute_external_force(f_ext);
    assemble(false);
    AssertThrow(failure.empty(), ExcMessage(failure));
    if (explicit_)
      {
        a = rhs;
        a.scale(inverse_mass);
      }
    else
      {
        a = 0;
        solve_linear_system(prm.linear_solver,
                            dof_handler,
                            condensed_mass,
                            a,
                            rhs);
        zero_constraints.distribute(a);
      }
    f_int = force;
    f_int += f_ext;
    // E_kin (and that of the constrained DoFs, whose change the supports
    // pay for with lumped masses) and the reaction including inertia.
    const auto kinetic = [&](double &constrained_part) {
      constrained_part = 0;
      if (!explicit_)
        {
          mass_matrix.vmult(Ma, v);
          return 0.5 * (v * Ma);
        }
      double e = 0, e_constrained = 0;
      for (unsigned int i = 0; i < v.locally_owned_size(); ++i)
        {
          const double ei =
            0.5 * lumped_mass.begin()[i] * v.begin()[i] * v.begin()[i];
          e += ei;
          e_constrained += constrained.begin()[i] * ei;
        }
      constrained_part = Utilities::MPI::sum(e_constrained, comm);
      return Utilities::MPI::sum(e, comm);
    };
    const auto reaction = [&](LinearAlgebra::Vector &r) {
      // (f_int - f_ext + M a) at the constrained DoFs (Newmark), f_int -
      // f_ext there (leapfrog: the inertia enters through E_kin)
      r = force;
      if (!explicit_)
        {
          mass_matrix.vmult(Ma, a);
          r += Ma;
        }
      r.scale(constrained);
    };
    double kinetic_constrained = 0;
    energies                   = TimeIntegration::Energies();
    energies.kinetic           = kinetic(kinetic_constrained);
    energies.initial_kinetic   = energies.kinetic;
    reaction(r_old);

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
      if (!summary.dynamics.disorder.empty())
        line << std::defaultfloat << std::setprecision(3)
             << ", disorder = " << summary.dynamics.disorder.back();
      pcout << line.str() << std::endl;
    };

    summary.load_steps = 0;
    summary.converged  = true;
    postprocess_timer.start();
    postprocess(0, 0., 0);
    postprocess_timer.stop();
    progress(0, 0.);
    const double interval    = time.output_interval;
    double       next_output = interval;

    double t = 0;
    for (unsigned int step = 1; step <= n_steps; ++step)
      {
        const double t_new      = (step == n_steps ? T : step * dt);
        unsigned int iterations = 0;
        u_old                   = solution_owned;
        const double          kinetic_constrained_old = kinetic_constrained;
        LinearAlgebra::Vector f_ext_old(f_ext), f_int_old(f_int);
        if (explicit_)
          {
            // velocity Verlet: v += dt/2 a; u += dt v; a(u); v += dt/2 a
            v.add(0.5 * dt, a);
            solution_owned.add(dt, v);
            set_load_factor(t_new);
            if (prm.boundary_conditions.prescribes_values())
              make_constraints(constraints, false);
            constraints.distribute(solution_owned);
            update_full_solution();
            compute_external_force(f_ext);
            assemble(false);
            AssertThrow(failure.empty(),
                        ExcMessage("At t = " + std::to_string(t_new) + ": " +
                                   failure));
            a = rhs;
            a.scale(inverse_mass);
            v.add(0.5 * dt, a);
            // the constrained DoFs: the difference quotient
            du = solution_owned;
            du -= u_old;
            for (unsigned int i = 0; i < v.locally_owned_size(); ++i)
              if (constrained.begin()[i] > 0)
                v.begin()[i] = du.begin()[i] / dt;
          }
        else if (!newmark_step(t_new, dt, v, a, f_ext, iterations))
          {
            solution_owned = u_old;
            update_full_solution();
            summary.converged = false;
            write_files(step - 1, t);
            AssertThrow(false,
                        ExcMessage(
                          "The Newmark step to t = " + std::to_string(t_new) +
                          " did not converge. Reduce 'Time step' in "
                          "subsection 'Time', or increase 'Maximum "
                          "iterations' in subsection 'Newton'. The results "
                          "up to t = " +
                          std::to_string(t) + " are in '" +
                          prm.output.directory + "'."));
          }
        t = t_new;
        summary.newton_iterations += iterations;
        summary.load_steps = step;

        // energies (trapezoidal rule)
        du = solution_owned;
        du -= u_old;
        f_int = force;
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
        AssertThrow(std::isfinite(energies.kinetic),
                    ExcMessage("The motion became unbounded at t = " +
                               std::to_string(t) +
                               ": reduce 'Time step' in subsection 'Time'."));

        if (step == n_steps || interval == 0. || t >= next_output - 1e-9 * dt)
          {
            while (interval > 0. && next_output <= t + 1e-9 * dt)
              next_output += interval;
            postprocess_timer.start();
            postprocess(step, t, iterations);
            postprocess_timer.stop();
            progress(step, t);
          }
      }

    std::vector<Tensor<2, dim>> F(particles.n_particles());
    for (unsigned int k = 0; k < F.size(); ++k)
      F[k] = particle_deformation_gradient(k);
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
