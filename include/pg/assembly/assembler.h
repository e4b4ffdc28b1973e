#ifndef pg_assembly_assembler_h
#define pg_assembly_assembler_h

#include <pg/base/global.h>
#include <pg/base/linear_algebra.h>
#include <pg/elements/element_group.h>
#include <pg/history/quadrature_point_history.h>

#include <deal.II/base/point.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <functional>
#include <mutex>
#include <string>
#include <vector>

namespace pg
{
  /** Whether a local vector (and matrix) has only finite entries. */
  bool
  all_finite(const Vector<double> &v, const FullMatrix<double> *m = nullptr);

  /**
   * The global residual and tangent: WorkStream over the elements of every
   * element group (in the order given), each local system distributed with
   * the homogeneous constraints, then the load terms that are not element
   * integrals (particle loads). Results:
   *  - rhs = -(f_int - f_ext), condensed (zero at constrained DoFs),
   *  - force = f_int - f_ext, unconstrained (the reactions),
   *  - the tangent, condensed, if asked for.
   * An element that throws, or whose residual or tangent is not finite, is
   * left out and its message kept: assemble() returns the first one (on
   * this rank; empty if none).
   */
  template <int dim>
  class Assembler
  {
  public:
    /**
     * @p constraints are the homogeneous constraints of the Newton update.
     */
    Assembler(const AffineConstraints<double>        &constraints,
              const std::vector<ElementGroup<dim> *> &groups);

    /**
     * Let every element read and write its slices of @p history (keyed by
     * the groups' order); without it, elements get empty slices (stateless
     * materials).
     */
    void
    set_history(QuadraturePointHistory *history);

    /** Per group and element: the number of evaluation points. */
    std::vector<std::vector<unsigned int>>
    evaluation_points() const;

    /**
     * sum_q w_q f(s_q) over the evaluation points q of every group on this
     * rank, s_q being the first @p n_material values of q's committed
     * state (the material's part) and w_q the groups'
     * evaluation_point_weights(): the integral of a function of the
     * material state over this rank's part of the body.
     */
    double
    integrate_committed_state(
      const std::function<double(const ArrayView<const double> &)> &f,
      const unsigned int n_material) const;

    /** The couplings of all groups' elements. */
    void
    add_sparsity(DynamicSparsityPattern &sparsity) const;

    /**
     * A load term added after the groups, e.g. the particle loads: it calls
     * add_load() or distribute() and record_failure().
     */
    using LoadTerm = std::function<void(Assembler<dim> &)>;

    /**
     * Assemble at the displacement @p u (indexed by global DoF, ghosted: it
     * holds the DoFs of this rank's elements) into
     * @p rhs, @p force and, if not null, @p matrix (all zeroed first).
     * Returns the first failure on this rank, or an empty string.
     */
    std::string
    assemble(const LinearAlgebra::Vector &u,
             LinearAlgebra::SparseMatrix *matrix,
             LinearAlgebra::Vector       &rhs,
             LinearAlgebra::Vector       &force,
             const LoadTerm              &loads = LoadTerm());

    /**
     * The local update of the condensed fields of every group after the
     * Newton update @p du (ghosted like u of assemble()).
     */
    void
    recover_local_fields(const LinearAlgebra::Vector &du);

    /** Every group's condensed fields back to local equilibrium. */
    void
    reset_local_fields();

    /** ElementGroup::use_condensed_field_iterates() of every group. */
    void
    use_condensed_field_iterates(const bool use);

    /** A local system f_int - f_ext into rhs (minus, condensed) and force. */
    void
    distribute(const LocalSystem &local);

    /** An external load @p f at @p dofs: rhs += f (condensed), force -= f. */
    void
    add_load(const Vector<double>                       &f,
             const std::vector<types::global_dof_index> &dofs);

    /** Keep @p message if it is the first failure of this assembly. */
    void
    record_failure(const std::string &message);

    /** Whether a failure has been recorded in this assembly. */
    bool
    failed() const;

    /**
     * Wall seconds of each group's loop, summed over the assemblies with a
     * matrix (the cost of a tangent).
     */
    const std::vector<double> &
    tangent_seconds() const;

    /** "NaN or inf in the residual or tangent of <element> at (<p>). <hint>" */
    static std::string
    non_finite_message(const std::string &element,
                       const Point<dim>  &where,
                       const std::string &hint);

  private:
    /**
     * Add local.matrix (no constrained DoF) into the matrix: for each row,
     * the positions of the element's columns in the row's sorted column
     * list are found by one merge walk (reused for the next row of the same
     * column list), and the values are added in place, instead of
     * Epetra's binary search per entry in SumIntoGlobalValues (on
     * Peridigm's tensile bar, 189 x 189 entries per family: 6.8 % of the
     * run before, this walk 10 % of a run half as long). Rows this rank
     * does not own go through deal.II's add().
     */
    void
    add_to_matrix(const LocalSystem &local);

    const AffineConstraints<double>       &constraints;
    const std::vector<ElementGroup<dim> *> groups;
    std::vector<double>                    seconds;
    QuadraturePointHistory                *history = nullptr;
    /** The targets of the running assembly. */
    LinearAlgebra::SparseMatrix *matrix = nullptr;
    LinearAlgebra::Vector       *rhs    = nullptr;
    LinearAlgebra::Vector       *force  = nullptr;
    std::mutex                   failure_mutex;
    std::string                  failure;
    /**
     * -residual of the local system being distributed (distribute() runs
     * on one thread at a time: WorkStream's copier, the load term), kept to
     * spare an allocation per element.
     */
    Vector<double> minus_residual;
    /**
     * This rank's entries of rhs and force as the global range [first,
     * first + size) (always on one rank), or size 0: a residual-only local
     * system of unconstrained DoFs in the range is then added in place,
     * without the per-entry map lookups of the Trilinos wrappers (the same
     * sums in the same order).
     */
    types::global_dof_index range_first = 0, range_size = 0;
    /** Work space of add_to_matrix() (the copier's thread only). */
    std::vector<int>          local_columns;
    std::vector<unsigned int> column_order;
    std::vector<int>          row_positions;
  };
} // namespace pg

#endif
