#ifndef pg_elements_correction_system_h
#define pg_elements_correction_system_h

#include <pg/base/formulation_code.h>
#include <pg/base/global.h>
#include <pg/base/linear_algebra.h>
#include <pg/elements/family_elements.h>
#include <pg/elements/quadrature_table.h>
#include <pg/families/family_set.h>
#include <pg/mesh/particle_set.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <vector>

namespace pg
{
  /** The solution of the VC system: the factors of every particle. */
  template <int dim>
  struct CorrectionFactors
  {
    /** alpha_1^k (1/length) per particle. */
    std::vector<Tensor<1, dim>> alpha;
    /** VC2 only: alpha_2^k (1/length^2) per particle; empty otherwise. */
    std::vector<Tensor<2, dim>> second_order_alpha;
    /**
     * VC2 only: max |D^k| / h^dim over the free particles after the
     * correction (SecondOrderCorrection); 0 otherwise.
     */
    double max_second_order_residual = 0;
    /**
     * How the system was solved: "GMRES + ILU(0)", "GMRES + AMG", "direct",
     * "direct (singular system)", "direct (V2: zero diagonal)" or "direct
     * (fallback)" (GMRES did not converge).
     */
    std::string solver;
    /** GMRES iterations of the iterative solve (0 if solved directly). */
    unsigned int solver_iterations = 0;

    /** max_k |alpha^k| h_k: the size of the correction relative to ~1/h. */
    double
    max_scaled_factor(const ParticleSet<dim> &particles) const;
  };



  /**
   * The variational-consistency (VC) correction system of pg-methods.md
   * sections 11.4-11.7, with its own sparsity pattern, matrix, right-hand
   * side and solution (the Newton tangent is not involved). The unknowns
   * are the factors alpha^k of every particle k, the equations
   *   d^k(alpha) = d^k(0) + sum_f C^{kf} alpha^f = target^k,
   * with the blocks C of FamilyElements::for_each_correction_block() and
   * the boundary option of the formulation code (section 11.5):
   *   interior:   d^k(alpha) = target^k (0; the area vector for p and on
   *               the FE/meshfree interface),
   *   tangential: n . alpha^k = 0 and t . d^k(alpha) = 0 (sn); at an
   *               edge of a 3-D body (ParticleSet::edge_direction() e)
   *               alpha^k parallel to e and e . d^k(alpha) = 0, so that
   *               d^k lies in the plane of the two face normals,
   *   fixed:      alpha^k = 0 (s; sn at corners: 2-D corners and 3-D
   *               vertices where three faces meet; p at d + 1 particles,
   *               or 1 for PPG2 and V1).
   * Rows and columns are the global DoFs of the particles (row i of
   * particle k is particles.dof(k, i)); all other owned DoFs get an
   * identity row. VC2 (PPG2, section 11.6) is solved by
   * solve_second_order_correction() with every surface particle fixed.
   *
   * reinit() may be called again whenever the family tables change (an
   * updated-Lagrangian reference update, fracture); solve() then solves
   * the new system.
   */
  template <int dim>
  class CorrectionSystem
  {
  public:
    /**
     * For the VC code @p formulation on the ranks of @p comm, solved by
     * @p solver ('VC solver' in subsection 'Linear solver'): "automatic"
     * (GMRES where the system is regular, with ILU(0) below
     * #amg_from_rows rows and ML AMG first from there, ILU(0) where the
     * AMG fails; the direct solver where the system is singular, i.e. FE
     * coupling plus a free surface, or where GMRES does not converge),
     * "ilu" or "amg" (GMRES with that preconditioner where the system is
     * regular) or "direct".
     */
    CorrectionSystem(const FormulationCode &formulation,
                     const MPI_Comm         comm,
                     const std::string     &solver = "automatic");

    /** |b - A alpha| / |b| at which GMRES stops. */
    static constexpr double relative_tolerance = 1e-13;
    /** GMRES iterations before the direct solver takes over. */
    static constexpr unsigned int max_iterations = 2000;
    /**
     * 'VC solver = automatic' tries GMRES with ML AMG first from this many
     * rows on, ILU(0) below. ILU(0)'s iterations grow like 1/h, AMG's
     * slowly, but AMG's set-up costs more: on the 3-D cantilever (V5sn,
     * 1.51 h) ILU(0) 0.99 / 5.2 / 20.9 s (99 / 154 / 241 iterations), AMG
     * 1.10 / 4.3 / 12.5 s (32 / 43 / 53) at 56,355 / 181,875 / 421,443
     * rows; on Peridigm's tensile bar (48,816 rows, 63 members per family)
     * 3.3 s against 4.4 s (doc/benchmarks/vc_solve.md).
     */
    static constexpr unsigned int amg_from_rows = 100000;
    /**
     * The automatic choice drops the AMG for ILU(0) when the residual has
     * not fallen below 1e-4 |b| after this many GMRES iterations (where it
     * works it reaches 1e-13 in 32 to 53) or when its true residual misses
     * the tolerance: it breaks down on the 3-D Cook membrane
     * (doc/benchmarks/vc_solve.md).
     */
    static constexpr unsigned int amg_stagnation_iterations = 100;

    /**
     * Classify the rows, build the sparsity pattern from the correction
     * couplings of the families in @p owned_families (this rank's) and
     * assemble the matrix. @p owned_dofs are this rank's DoFs (the
     * masters of @p owned_families among them). The three objects must stay
     * alive until the next reinit(); @p elements must have its correction
     * function values (FamilyElements::initialize()). Throws with advice
     * if the boundary option cannot be applied.
     */
    void
    reinit(const ParticleSet<dim>          &particles,
           const FamilySet<dim>            &families,
           const FamilyElements<dim>       &elements,
           const std::vector<unsigned int> &owned_families,
           const IndexSet                  &owned_dofs);

    /**
     * Solve for the factors, given the uncorrected unit-stress residual
     * @p unit_stress d^k(0) of every particle (unit_stress_residual()).
     * Throws with advice if the system cannot be solved or is singular.
     * The factors are the same on every rank.
     */
    CorrectionFactors<dim>
    solve(const std::vector<Tensor<1, dim>> &unit_stress);

    /**
     * Make every surface particle k a row d^k(alpha) = @p targets[k]
     * (n_particles values), with the factors fixed at d + 1 particles as
     * for option p: call before reinit(). The targets must obey the
     * discrete Gauss identities (they do if they are the unit-stress
     * residual of other corrected tables). U1SUnl corrects its U1 tables
     * so that their surface area vectors are those of its corrected Unl
     * tables, and the loads balance both.
     */
    void
    set_prescribed_targets(const std::vector<Tensor<1, dim>> &targets);

    /**
     * What to change when the VC system of @p formulation cannot be solved
     * (the end of the error message).
     */
    static std::string
    failure_advice(const FormulationCode &formulation);

    /** The system matrix of the last reinit() (not for VC2). */
    const LinearAlgebra::SparseMatrix &
    system_matrix() const;

  private:
    enum class Row
    {
      interior,
      tangential,
      fixed
    };

    /** kind, R, normal and target of every particle (section 11.5). */
    void
    classify_rows();

    /**
     * Mirror symmetry planes: the rows and factors of the particles on a
     * plane keep the directions parallel to it.
     */
    void
    restrict_to_mirror_planes();

    /**
     * Fix alpha at particles of @p surface spread over the boundary when
     * the system has no free surface or the option is p.
     */
    void
    fix_null_space(const std::vector<unsigned int> &surface,
                   const bool                       free_surface);

    /**
     * fix_null_space() with mirror planes: of the null space of the full
     * body, the fields that are their own mirror image remain, each fixed
     * by one component of one particle of @p surface.
     */
    void
    fix_mirrored_null_space(const std::vector<unsigned int> &surface,
                            const bool first_order_identity);

    /** The pattern of the correction couplings and the identity rows. */
    void
    make_sparsity_pattern();

    /** matrix = R C on the equation rows, the constraint rows, identity. */
    void
    assemble_matrix();

    /**
     * The AMG's near-null space: one mask over the owned rows per
     * component, true on the rows of that component of a particle.
     */
    std::vector<std::vector<bool>>
    component_modes() const;

    FormulationCode formulation;
    const MPI_Comm  comm;
    /** set_prescribed_targets(); empty: the targets of the option. */
    std::vector<Tensor<1, dim>> prescribed_targets;
    const std::string           solver;

    const ParticleSet<dim>    *particles = nullptr;
    const FamilySet<dim>      *families  = nullptr;
    const FamilyElements<dim> *elements  = nullptr;
    std::vector<unsigned int>  owned_families;
    IndexSet                   owned_dofs;
    /** Owned DoFs and the DoFs of every particle (to read all alpha). */
    IndexSet particle_dofs;

    std::vector<Row> kind;
    /**
     * The row operator of each particle: 1, or for sn rows the tangents
     * t_i (unit projections of e_i onto the tangent plane) in the rows
     * that hold an equation t_i . d^k = 0 (at a 3-D edge the edge
     * direction in one row) and 0 in the rows of the constraints.
     */
    std::vector<Tensor<2, dim>> R;
    /**
     * sn rows: row i holds the constraint c_i . alpha^k = 0 if c_i =
     * constraint[k][i] is nonzero: the normal in one row on a face, the
     * two unit projections of e_j onto the plane of the face normals at a
     * 3-D edge. Zero for interior and fixed particles.
     */
    std::vector<Tensor<2, dim>> constraint;
    std::vector<Tensor<1, dim>> normal, target;
    /**
     * true if the system keeps a null space (FE coupling plus a free
     * surface, without option p): solved directly.
     */
    bool singular = false;
    /** VC2: the particles whose factors stay zero. */
    std::vector<bool> second_order_fixed;

    DynamicSparsityPattern      sparsity_pattern;
    LinearAlgebra::SparseMatrix matrix;
    LinearAlgebra::Vector       rhs, solution;
  };



  /**
   * The VC (or VC2) correction of the family tables (pg-methods.md
   * sections 11.4-11.7): reinit @p system on the families @p owned_families
   * of this rank (with its DoFs @p owned_dofs), solve it for the
   * uncorrected unit-stress residual @p unit_stress d^k(0), hand the
   * factors to @p elements (PBG: test = trial corrected) and correct
   * @p tables (tables[i] of family owned_families[i], as @p elements built
   * them before: FamilyElements::correct()) with them. Returns
   * the factors, for their statistics; d^k of the new tables is then
   * round-off at interior particles.
   */
  template <int dim>
  CorrectionFactors<dim>
  correct_family_tables(CorrectionSystem<dim>             &system,
                        const ParticleSet<dim>            &particles,
                        const FamilySet<dim>              &families,
                        FamilyElements<dim>               &elements,
                        const std::vector<unsigned int>   &owned_families,
                        const IndexSet                    &owned_dofs,
                        const std::vector<Tensor<1, dim>> &unit_stress,
                        std::vector<QuadratureTable<dim>> &tables);
} // namespace pg

#endif
