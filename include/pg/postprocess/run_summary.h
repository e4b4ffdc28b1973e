#ifndef pg_postprocess_run_summary_h
#define pg_postprocess_run_summary_h

#include <pg/base/global.h>

#include <deal.II/base/types.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace pg
{
  /**
   * What a run reports in summary.json (and what tests check).
   */
  struct RunSummary
  {
    unsigned int            dimension = 0;
    std::string             formulation;
    unsigned int            n_particles      = 0;
    unsigned int            n_fe_cells       = 0;
    unsigned int            n_meshfree_cells = 0;
    unsigned int            n_families       = 0;
    types::global_dof_index n_dofs           = 0;
    std::size_t             matrix_nonzeros  = 0;
    /** Of the Q1 matrix of 'AMG operator' (0: ML uses the tangent). */
    std::size_t amg_operator_nonzeros = 0;
    bool        converged             = false;
    /**
     * Why the run stopped: empty while it runs and when it finished; the
     * error message (user_message(), on one line) when an exception ended
     * it after set-up (summary.json: "status" and "message").
     */
    std::string stop_message;
    /**
     * summary.json's "status": "running" until the analysis has finished
     * ("finished"), "failed" with a stop_message, "interrupted" when SIGINT
     * or SIGTERM stopped the run (after a checkpoint).
     */
    bool         finished = false, interrupted = false;
    unsigned int load_steps        = 0;
    unsigned int newton_iterations = 0;
    /** |R| of every Newton iteration of the last (sub)step. */
    std::vector<double> newton_residuals_last_step;
    /** |R| of every Newton iteration of every converged (sub)step. */
    std::vector<std::vector<double>> newton_residuals;
    /** name -> displacement at the final converged step. */
    std::vector<std::pair<std::string, std::vector<double>>> points;
    /** A sample of 'Output/Lines' at the final converged step. */
    struct LineSample
    {
      std::string         line;
      double              arc_length;
      std::vector<double> position, displacement;
    };
    std::vector<LineSample> line_samples;
    /** Dirichlet boundary id -> reaction force (f_int - f_ext). */
    std::map<types::boundary_id, std::vector<double>> reactions;
    /**
     * The reaction (f_int - f_ext, dim components) of each of 'Dirichlet
     * boxes', in their order: summed over the prescribed components of the
     * vertices in the box (a vertex in two boxes counts for both).
     */
    std::vector<std::vector<double>> box_reactions;
    /**
     * The same for each 'Dirichlet node sets' item, by node set name: the
     * vertices of the node set.
     */
    std::map<std::string, std::vector<double>> node_set_reactions;
    /**
     * 'Boundary conditions/Rigid wall': the wall's force on the body (sum
     * of f_int - f_ext over the held nodes, dim components; empty without
     * a wall), the number of held nodes and min n . (x - p) over all
     * nodes, at the last output step.
     */
    std::vector<double> wall_reaction;
    unsigned int        wall_active_nodes = 0;
    double              wall_min_gap      = 0;
    /**
     * The traction of one Neumann id at load factor 1 on the particles
     * ('test functions' or 'geometry'; ParticleLoads::Resultant): its
     * resultant force and moment about the centre (the area centroid of
     * the id's meshfree faces; moment: z in 2-D, three components in 3-D)
     * beside the exact ones, the face integrals of the traction.
     */
    struct NeumannResultant
    {
      types::boundary_id  id   = 0;
      double              area = 0;
      std::vector<double> centre, force, exact_force, moment, exact_moment;
      /** 'test functions': the resultant of eq. 4.32 alone (else empty). */
      std::vector<double> point_force;
      /** Particles at the edge of the loaded region (load corrected). */
      unsigned int n_partly_loaded = 0;
    };
    std::vector<NeumannResultant> neumann_resultants;
    bool                          have_errors = false;
    double L2 = 0, H1 = 0, L2_relative = 0, H1_relative = 0;
    /**
     * Energy norm of the error, sqrt(int grad e : A(1) : grad e) with the
     * material tangent A of the reference state (the strain energy of the
     * linearised problem), and its ratio to the exact field's.
     */
    double energy = 0, energy_relative = 0;
    /**
     * name -> Cauchy stress (in-plane components, row-major) at the mesh
     * vertex nearest the named point of 'Output/Points': the particle's
     * value, or the average of the adjacent Q1 cells (as in
     * stress_along_boundaries.txt).
     */
    std::vector<std::pair<std::string, std::vector<double>>> point_stresses;
    /** The exact stress at the same vertices (with 'Compute errors'). */
    std::vector<std::pair<std::string, std::vector<double>>>
      point_exact_stresses;
    /**
     * The cost of the tangent assemblies (assemble() with the matrix): wall
     * seconds of the loops over the Q1 cells and over the families (this
     * rank's, summed over all assemblies, local kernel and scatter into the
     * global matrix), and, per assembly and summed over all ranks, the
     * entries of the local tangents and the floating point operations of
     * the kernel (tangent_flops()).
     */
    struct AssemblyCost
    {
      unsigned int n_assemblies = 0, n_solves = 0;
      /** Krylov iterations summed over the Newton solves (cg, gmres). */
      unsigned int linear_iterations = 0;
      /**
       * ML hierarchies built for them (fewer than n_solves with 'Reuse
       * AMG'; counted from the start of this run, also after a restart).
       */
      unsigned int amg_builds = 0;
      /**
       * 'AMG operator = automatic': a trial solve found the tangent's
       * hierarchy faster than the Q1 cells', which then were dropped.
       */
      bool   amg_operator_rejected = false;
      double fe_seconds = 0, family_seconds = 0;
      double fe_entries = 0, family_entries = 0;
      double fe_flops = 0, family_flops = 0;
    } assembly_cost;
    /**
     * Wall seconds: mesh (generation, refinement, distortion), setup (DoFs,
     * particles, sparsity), shape_functions (families and their tables),
     * vc (the correction), assembly, solve, postprocess (errors,
     * statistics, output files) and total.
     */
    std::map<std::string, double> timing;
    /**
     * Mixed formulations: the smallest and largest condensed pressure p
     * over the elements at the last output (empty otherwise).
     */
    std::vector<double> condensed_pressure_range;
    /**
     * A material with state outputs (Material::state_output_names()): each
     * name and its largest value over all committed points at the last
     * output, written as "max_<name>" (e.g. max_equivalent_plastic_strain).
     */
    std::vector<std::pair<std::string, double>> state_output_maxima;
    /** Largest |d^k| at interior particles, divided by spacing^(dim-1). */
    double max_interior_unit_stress_residual = 0;
    /**
     * VC2: largest second-order residual D^k at interior particles,
     * divided by spacing^dim (SecondOrderCorrection).
     */
    double max_interior_second_order_residual = 0;
    /** Eigenmode analysis: the smallest eigenvalues (real parts). */
    std::vector<double> eigenvalues;
    /** Eigenmode analysis: eigenvalues below 1e-10 times the largest. */
    unsigned int n_zero_eigenvalues = 0;
    double       max_eigenvalue     = 0;
    /**
     * Oscillation of the particle deformation gradients at the final step:
     * sqrt(sum_k V^k |F^k - mean_{H^k} F|^2 / sum_k V^k |F^k - 1|^2), with
     * the volume-weighted mean over the family. Near 0 for smooth fields;
     * spurious (zero-energy) modes and defective shape functions raise it.
     */
    double gradient_oscillation = 0;
    /**
     * Largest |sigma_xx| difference between the particle value and the
     * average of the adjacent Q1 cells at FE/meshfree interface vertices
     * (stress units; 0 without an interface).
     */
    double max_interface_stress_jump = 0;
    /** Largest VC correction factor |alpha^k| times the spacing. */
    double max_correction_factor = 0;
    /**
     * How the VC system was solved (CorrectionFactors::solver); empty
     * without VC (or with VC2).
     */
    std::string vc_solver;
    /** GMRES iterations of the iterative VC solve. */
    unsigned int vc_iterations = 0;
    /**
     * Inf-sup analysis (section 7.2.5): one entry per mesh N of the series
     * in every array; NaN (null in summary.json) where a value does not
     * exist (the slope of the first mesh, k_pm without a pressure space).
     */
    struct InfSup
    {
      std::string         pressure_space;
      double              zero_tolerance = 0;
      std::vector<double> N, n_dofs, n_free, n_pressure, n_zero, k_pm, beta,
        slope, lambda_max, largest_zero;
    } inf_sup;
    /**
     * Dynamics ('Time/Integrator' leapfrog or newmark): the steps and, one
     * entry per output time, the energies of statistics.txt.
     */
    struct Dynamics
    {
      std::string integrator;
      /** dt used, and the stable estimate 2 / omega_max of leapfrog. */
      double time_step = 0, stable_time_step = 0;
      /** The smallest and largest accepted steps, the time reached. */
      double       smallest_time_step = 0, largest_time_step = 0;
      double       final_time = 0;
      unsigned int n_steps    = 0;
      /** Failed steps redone with half the step ('adaptive'). */
      unsigned int        step_cuts = 0;
      std::vector<double> time, kinetic, internal_work, external_work,
        support_work, balance;
      /**
       * The plastic work (TimeIntegration::Energies::plastic_work); empty
       * for a material that does not dissipate.
       */
      std::vector<double> plastic_work;
      /**
       * The disorder indicator of the particles (TimeIntegration::
       * local_fit_deviation relative to the RMS of the initial
       * displacement about its mean); empty without particles.
       */
      std::vector<double> disorder;
    } dynamics;
  };
} // namespace pg

#endif
