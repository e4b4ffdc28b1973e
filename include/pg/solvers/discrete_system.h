#ifndef pg_solvers_discrete_system_h
#define pg_solvers_discrete_system_h

#include <pg/assembly/assembler.h>
#include <pg/assembly/loads.h>
#include <pg/assembly/particle_loads.h>
#include <pg/base/formulation_code.h>
#include <pg/base/global.h>
#include <pg/base/linear_algebra.h>
#include <pg/base/parameters.h>
#include <pg/constraints/rigid_wall.h>
#include <pg/dofs/discretization.h>
#include <pg/elements/correction_system.h>
#include <pg/elements/element_group.h>
#include <pg/elements/family_group.h>
#include <pg/elements/q1_cell_group.h>
#include <pg/history/quadrature_point_history.h>
#include <pg/materials/material.h>
#include <pg/solvers/linear_solver.h>
#include <pg/solvers/mechanical_system.h>
#include <pg/solvers/newton_solver.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>

namespace pg
{
  struct RunSummary;

  /**
   * The discrete mechanical system of a run on a Discretization: the
   * constraints (Dirichlet and symmetry, and their homogeneous version of
   * the Newton update), the tangent K, the vectors u, du, R = -(f_int -
   * f_ext) and f_int - f_ext, the loads (Loads, ParticleLoads), the
   * element groups (Q1 cells, then the families or the CPD interactions)
   * with their Assembler, the material state at their evaluation points
   * (QuadraturePointHistory) and the VC correction of the family tables
   * (CorrectionSystem). It implements the MechanicalSystem of the time
   * integrators and the analyses, and the Newton load step of the static
   * analysis (solve_step()).
   *
   * The members are public data, as in Discretization: the problem wires
   * them into the ProblemView and the analyses. It records the sizes, the
   * assembly counts and the Newton residuals into the RunSummary it is
   * given; the wall times (s) of the VC correction, the assemblies and
   * the linear solves are time_vc, time_assembly and time_solve.
   *
   * The discretization is not const: the VC correction rebuilds its
   * family_elements and family_tables (correct_variational_consistency()).
   */
  template <int dim>
  class DiscreteSystem : public MechanicalSystem
  {
  public:
    using CellIterator = typename DoFHandler<dim>::active_cell_iterator;

    /**
     * The system of @p parameters, @p formulation and @p material on
     * @p discretization (set up later: setup()); messages go to @p pcout,
     * the counts to @p summary. Checks that the linear solver can solve
     * the tangents of the formulation (no CG for PPG).
     */
    DiscreteSystem(const Parameters::AllParameters<dim> &parameters,
                   const MPI_Comm                        mpi_communicator,
                   const ConditionalOStream             &pcout,
                   const FormulationCode                &formulation,
                   const Materials::Material<dim>       &material,
                   Discretization<dim>                  &discretization,
                   RunSummary                           &summary);

    /**
     * Is the meshfree @p cell loaded by FE-consistent face tractions (the
     * 'geometry' particle traction area and a Neumann face)? The argument
     * of Discretization::reinit().
     */
    bool
    loaded_by_face_traction(const CellIterator &cell) const;

    /**
     * After Discretization::reinit(): d^k, the constraints, the element
     * groups and the assembler, the sparsity and the tangent, the VC
     * correction (VC codes with particles), the vectors and the material
     * state at the evaluation points.
     */
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
     * 'Predictor = linearized': one solve with the tangent of the last
     * converged state for the Dirichlet increment (inhomogeneous update
     * constraints), before Newton starts. The constraints of the update are
     * homogeneous again afterwards.
     */
    void
    apply_linearized_predictor();

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
      return discretization.owned_dofs;
    }

    LinearAlgebra::Vector &
    displacement() override
    {
      return solution_owned;
    }

    void
    displacement_changed() override
    {
      update_ghost_values();
      assembler->reset_local_fields();
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
      // dynamics: the rigid wall's active set once per step, at the
      // predicted displacement and the forces of the last step
      // (Newmark: nodes are released after the solve, update_contact(),
      // where the reactions include the inertia)
      if (rigid_wall)
        {
          update_ghost_values();
          update_rigid_wall(force, prm.time.integrator == "leapfrog");
        }
      constraints.distribute(solution_owned);
    }

    void
    hold_at_wall(LinearAlgebra::Vector &v) const override
    {
      if (rigid_wall)
        rigid_wall->hold(v);
    }

    /**
     * Update the active set of the rigid wall (RigidWall::update()) at
     * the current displacement and the nodal reactions @p reaction (f_int
     * - f_ext, or with Newmark's inertia), releasing tensile nodes if
     * @p release, and rebuild both constraints if it changed. Returns the
     * numbers of nodes activated and released.
     */
    std::pair<unsigned int, unsigned int>
    update_rigid_wall(const LinearAlgebra::Vector &reaction,
                      const bool                   release);

    /**
     * After a converged solve of round @p round of a step: update the
     * active set from @p reaction (update_rigid_wall(), releasing) and
     * print what changed. 0: unchanged (or no wall); 1: changed, the
     * constraints are rebuilt and distributed, solve again; -1: changed
     * 'Maximum active set changes' times, @p failure says so.
     */
    int
    update_active_set(const LinearAlgebra::Vector &reaction,
                      const unsigned int           round,
                      std::string                 &failure);

    int
    update_contact(const LinearAlgebra::Vector &reaction,
                   const unsigned int           round) override;

    /** The rigid wall's active set (empty without a wall). */
    std::vector<bool>
    contact_state() const override
    {
      return rigid_wall ? rigid_wall->active_set() : std::vector<bool>();
    }

    void
    set_contact_state(const std::vector<bool> &state) override;

    /** The integral of the material's plastic_work_density(). */
    std::optional<double>
    plastic_work() const override;

    const AffineConstraints<double> &
    homogeneous_constraints() const override
    {
      return zero_constraints;
    }

    std::string
    assemble_residual(const bool with_matrix) override
    {
      assemble(with_matrix);
      return reduced_failure();
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
    set_tangent_mass(const double                       factor,
                     const LinearAlgebra::SparseMatrix *mass) override
    {
      tangent_mass        = mass;
      tangent_mass_factor = factor;
    }

    void
    external_force(LinearAlgebra::Vector &f_ext) override
    {
      compute_external_force(f_ext);
    }

    void
    solve(const LinearAlgebra::SparseMatrix &A,
          LinearAlgebra::Vector             &x,
          const LinearAlgebra::Vector       &b) override;
    /** @} */

    /** solution = solution_owned: the ghost entries from their owners. */
    void
    update_ghost_values();

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

    /**
     * The Q1 group and the sparsity of amg_matrix for 'AMG operator = Q1
     * cells' (mixed codes: Q1P0 / H1P0 with @p condensed_pressure).
     */
    void
    setup_amg_operator(
      const Materials::VolumetricSplit<dim> *condensed_pressure);

    /**
     * amg_matrix at the current displacement, the matrix of a new ML
     * hierarchy; nullptr if a Q1 cell fails there (e.g. inverted), and the
     * hierarchy is built from the tangent.
     */
    const LinearAlgebra::SparseMatrix *
    assemble_amg_operator();

    /** Set the time of every parsed function to the load factor @p t. */
    void
    set_load_factor(const double t) const
    {
      prm.set_load_factor(t);
    }

    /**
     * f_ext at the time of the parsed functions: the loads are dead, so
     * f_ext = -(f_int - f_ext)(u = 0), one residual assembly (none without
     * body force and Neumann boundaries). Overwrites rhs and force.
     */
    void
    compute_external_force(LinearAlgebra::Vector &f_ext);

    /**
     * The failure of the last assembly on any rank: this rank's message,
     * another rank's note, or empty on all ranks (collective).
     */
    std::string
    reduced_failure() const;

    /**
     * The hourglass force of 'Discretization/Hourglass coefficient' on the
     * owned families (U1).
     */
    U1Stabilisation<dim>
    hourglass_stabilisation() const;

    /**
     * U1SIG: the MLS1 second derivatives ('Discretization/Self-weight
     * distance') and second moments of the owned families, with W~.
     */
    U1Stabilisation<dim>
    implicit_gradient_stabilisation() const;

    /** @p target += @p factor C^T y with C of zero_constraints. */
    void
    add_condensed(const LinearAlgebra::Vector &y,
                  const double                 factor,
                  LinearAlgebra::Vector       &target) const override;

    const Parameters::AllParameters<dim> &prm;
    const MPI_Comm                        comm;
    const ConditionalOStream             &pcout;
    const FormulationCode                &formulation;
    const Materials::Material<dim>       &material;
    /** Mesh, DoFs, particles, families and tables (set up before setup()). */
    Discretization<dim> &discretization;
    /** Sizes, assembly counts, Newton residuals and VC measures. */
    RunSummary &summary;

    AffineConstraints<double> constraints, zero_constraints;
    /**
     * 'Boundary conditions/Rigid wall' (null without one), and the
     * homogeneous constraints without its lines (which DoFs other
     * conditions hold).
     */
    std::unique_ptr<RigidWall<dim>> rigid_wall;
    AffineConstraints<double>       wall_free_constraints;
    LinearAlgebra::SparseMatrix     matrix;
    /**
     * 'AMG operator = Q1 cells' or 'automatic' (with particles, cg or gmres,
     * hexahedral / quadrilateral cells): the Q1
     * (Q1P0 / H1P0) tangent on every owned cell, on the DoFs and with the
     * constraints of matrix, that ML's hierarchy is built from; its cells,
     * group and assembler (null otherwise). Declared before amg_cache,
     * whose hierarchy wraps it.
     */
    LinearAlgebra::SparseMatrix       amg_matrix;
    std::vector<CellIterator>         owned_cells;
    std::unique_ptr<Q1CellGroup<dim>> amg_cells;
    std::unique_ptr<Assembler<dim>>   amg_assembler;
    /**
     * A material with history: the state of amg_cells' points, always the
     * initial one (never committed): the AMG operator of a stateful
     * material is that of its initial (virgin) state, a preconditioner
     * only.
     */
    QuadraturePointHistory amg_history;
    /** Newmark's c0 M in the tangent (set_tangent_mass()), or nullptr. */
    const LinearAlgebra::SparseMatrix *tangent_mass        = nullptr;
    double                             tangent_mass_factor = 0;
    /**
     * ML's hierarchy of the Newton solves ('Reuse AMG'), built from matrix
     * or from amg_matrix.
     */
    AMGCache amg_cache;
    /**
     * solution is ghosted over the relevant DoFs (what the assembly and the
     * postprocessors read); solution_owned holds the owned DoFs that the
     * Newton updates change.
     */
    LinearAlgebra::Vector solution, solution_owned;
    LinearAlgebra::Vector update, rhs, force;

    /** The VC system, with its own matrix (VC codes only). */
    std::unique_ptr<CorrectionSystem<dim>> correction_system;
    /**
     * U1SUnl only: the VC system of the stabilisation tables (Unl) and the
     * pseudo-material W~ of eq. (6.20).
     */
    std::unique_ptr<CorrectionSystem<dim>>    stabilisation_correction_system;
    std::unique_ptr<Materials::Material<dim>> pseudo_material;

    /** The dead loads of 'Boundary conditions' and the body force. */
    const Loads<dim> loads;
    /**
     * The loads on the particles and meshfree faces (the load term of the
     * Assembler) and the unit-stress residual d^k they use.
     */
    ParticleLoads<dim> particle_loads;
    /** The element groups and the assembler over them (set up in setup()). */
    std::unique_ptr<Q1CellGroup<dim>>  q1_cells;
    std::unique_ptr<ElementGroup<dim>> family_group;
    std::unique_ptr<Assembler<dim>>    assembler;
    /**
     * Whether the groups keep their condensed p and Theta as Newton
     * iterates ('Newton/Condensed fields = linearized' with a mixed code and
     * an implicit method), so that apply_newton_update() recovers them.
     */
    bool condensed_field_iterates = false;
    /**
     * The material state at the groups' evaluation points: committed after
     * every accepted (sub)step, reverted after a cut.
     */
    QuadraturePointHistory history;
    /**
     * The initial state of history's points (empty for a stateless
     * material and kernel): the external force is the residual at u = 0
     * from this state, where the internal force is zero (from the
     * committed state a plastic body has stresses at u = 0).
     */
    QuadraturePointHistory initial_history;

    /** The first failure of the last assembly on this rank (or empty). */
    std::string failure;
    /** Why the last failed (sub)step failed, for the final message. */
    std::string last_failure;

    /**
     * Wall times (s) of the phases, reported in summary.json;
     * time_amg_operator (part of time_solve) assembles amg_matrix.
     */
    double time_vc = 0, time_assembly = 0, time_solve = 0,
           time_amg_operator = 0;
  };
} // namespace pg

#endif
