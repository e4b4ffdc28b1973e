#ifndef pg_elements_element_group_h
#define pg_elements_element_group_h

#include <pg/base/global.h>
#include <pg/base/linear_algebra.h>
#include <pg/elements/condensed_pressure.h>

#include <deal.II/base/array_view.h>
#include <deal.II/base/point.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>
#include <vector>

namespace pg
{
  /**
   * Per-thread work space of an element group (FEValues, local tables):
   * created once per thread by the Assembler through clone().
   */
  struct GroupScratch
  {
    virtual ~GroupScratch() = default;

    virtual std::unique_ptr<GroupScratch>
    clone() const = 0;
  };

  /**
   * The element's slices of the QuadraturePointHistory: the committed state
   * it reads and the trial state it writes, n_evaluation_points() times the
   * material's n_state_variables() values each (empty for stateless
   * materials).
   */
  struct ElementHistory
  {
    ArrayView<const double> committed;
    ArrayView<double>       trial;
    /**
     * Values per point in the store: the material's n_state_variables(),
     * followed by a kernel's own entries (U1SIG: the master's accepted F,
     * dim^2 values); 0 for an empty history.
     */
    unsigned int n_variables = 0;
  };

  /**
   * The material's part of an element's history: the first @p n_material
   * of the history's n_variables values of each of @p n_points points, as
   * the contiguous slices assemble_element() takes. Where the store holds
   * nothing else the slices are the history's own; otherwise they are
   * copies, and write_back() copies the trial values into the history.
   */
  class MaterialStateSlices
  {
  public:
    MaterialStateSlices(const ElementHistory &history,
                        const unsigned int    n_points,
                        const unsigned int    n_material)
      : history(history)
      , n_points(n_points)
      , n_material(n_material)
      , copied(n_material > 0 && history.n_variables != n_material)
    {
      AssertThrow(
        n_material == 0 ||
          (history.n_variables >= n_material &&
           history.committed.size() == n_points * history.n_variables),
        ExcMessage("The point history holds " +
                   std::to_string(history.committed.size()) + " values for " +
                   std::to_string(n_points) + " points of a material with " +
                   std::to_string(n_material) + " state variables per point."));
      if (copied)
        {
          committed_copy.resize(n_points * n_material);
          trial_copy.resize(n_points * n_material);
          for (unsigned int q = 0; q < n_points; ++q)
            for (unsigned int i = 0; i < n_material; ++i)
              committed_copy[q * n_material + i] =
                history.committed[q * history.n_variables + i];
        }
    }

    /** The committed material state of all points. */
    ArrayView<const double>
    committed() const
    {
      if (n_material == 0)
        return {};
      return copied ? make_array_view(committed_copy) : history.committed;
    }

    /** The trial material state of all points. */
    ArrayView<double>
    trial()
    {
      if (n_material == 0)
        return {};
      return copied ? make_array_view(trial_copy) : history.trial;
    }

    /** Copy the trial values into the history (nothing if not copied). */
    void
    write_back() const
    {
      if (!copied)
        return;
      for (unsigned int q = 0; q < n_points; ++q)
        for (unsigned int i = 0; i < n_material; ++i)
          history.trial[q * history.n_variables + i] =
            trial_copy[q * n_material + i];
    }

  private:
    const ElementHistory history;
    const unsigned int   n_points, n_material;
    const bool           copied;
    std::vector<double>  committed_copy, trial_copy;
  };

  /** What one element hands to the global system. */
  struct LocalSystem
  {
    /** Global DoF indices, node-major (node a, component c: a * dim + c). */
    std::vector<types::global_dof_index> dofs;
    /** f_int - f_ext of the element (force units), in the order of dofs. */
    Vector<double> residual;
    /** d residual / d u (filled only if with_matrix). */
    FullMatrix<double> matrix;
    bool               with_matrix = true;
    /**
     * Why the element could not be assembled (set by the Assembler's
     * worker, reported by its copier in element order, so that the message
     * names the same element whatever the number of threads).
     */
    std::string failure;
  };

  /**
   * Turn the residual and tangent of an element's local DoFs into those of
   * the global DoFs, local DoF i being @p signs[i] times global DoF i:
   * r_i *= s_i, K_ij *= s_i s_j.
   */
  void
  apply_dof_signs(const std::vector<double> &signs, LocalSystem &local);

  /**
   * The tangent part of the above: K_ij *= s_i s_j for the first
   * signs.size() local DoFs of @p matrix (the others, e.g. a bubble or a
   * pressure node, are even).
   */
  void
  apply_dof_signs(const std::vector<double> &signs, FullMatrix<double> &matrix);

  /**
   * Everything that assembles is an element group (architecture.md section
   * 7): the Q1 cells, the PG families, the CPD interactions, later the mixed
   * cells and families. A group knows its locally owned elements, their DoF
   * indices and couplings, their evaluation points, and the local residual
   * and tangent at a displacement; local fields (a P0 pressure, bubbles)
   * are condensed inside assemble() and recovered by
   * recover_local_fields(). The Assembler runs WorkStream over every group;
   * nothing outside a group branches on the formulation it implements.
   */
  template <int dim>
  class ElementGroup
  {
  public:
    virtual ~ElementGroup() = default;

    /** For messages and timings, e.g. "Q1 cells". */
    virtual std::string
    name() const = 0;

    /** The locally owned elements, numbered 0 .. n_elements() - 1. */
    virtual unsigned int
    n_elements() const = 0;

    /** The global DoF indices of element @p e, node-major. */
    virtual void
    get_dof_indices(const unsigned int                    e,
                    std::vector<types::global_dof_index> &dofs) const = 0;

    /**
     * The sign of each DoF of get_dof_indices(): the element's local DoF i
     * is signs[i] times the global DoF dofs[i] (-1 for the reflected
     * components of a mirror image, ParticleSet::mirror_sign()). Empty if
     * all are +1 (the default). assemble() reads u with these signs; the
     * Assembler applies them to the local residual and tangent
     * (apply_dof_signs()).
     */
    virtual void
    get_dof_signs(const unsigned int e, std::vector<double> &signs) const;

    /**
     * The couplings of element @p e in the sparsity pattern; by default
     * every pair of its DoFs.
     */
    virtual void
    add_sparsity(const unsigned int               e,
                 const AffineConstraints<double> &constraints,
                 DynamicSparsityPattern          &sparsity) const;

    /**
     * The couplings of all elements of the group: by default add_sparsity()
     * of each. A group may add them row by row instead, which gives the
     * same pattern faster.
     */
    virtual void
    add_group_sparsity(const AffineConstraints<double> &constraints,
                       DynamicSparsityPattern          &sparsity) const;

    /** Evaluation points of element @p e (the keys of its point history). */
    virtual unsigned int
    n_evaluation_points(const unsigned int e) const = 0;

    /**
     * The reference volume (volume units) each evaluation point stands for,
     * element after element in the order of the point history: the
     * weights of the elements' quadratures (JxW of a cell's Gauss points,
     * w_q of a family's table), so that sum_q w_q g(state_q) integrates a
     * function of the material state over this rank's part of the body
     * (e.g. the plastic work, Material::plastic_work_density()). Empty if
     * the points are no quadrature of the body (CPD interactions).
     */
    virtual std::vector<double>
    evaluation_point_weights() const;

    virtual std::unique_ptr<GroupScratch>
    create_scratch() const = 0;

    /**
     * The local system of element @p e at the displacement @p u (indexed by
     * global DoF; a ghosted vector that holds the DoFs of the element, see
     * compute_relevant_dofs()): dofs, residual and (if local.with_matrix) the
     * tangent, reading the committed and writing the trial state of @p history.
     * Throws with a message on failure.
     */
    virtual void
    assemble(const unsigned int           e,
             const LinearAlgebra::Vector &u,
             const ElementHistory        &history,
             GroupScratch                &scratch,
             LocalSystem                 &local) const = 0;

    /**
     * Keep the condensed p and Theta of every element as Newton iterates
     * (CondensedFieldIterate: three fields, the local update after each
     * global solve) instead of the closed form. For groups whose assemble()
     * passes condensed_field_iterate() to the condensed kernel.
     */
    void
    keep_condensed_field_iterates();

    /**
     * After a Newton update @p du (indexed by global DoF, ghosted like u of
     * assemble()): the local update of every element's condensed fields.
     * Nothing without iterates.
     */
    void
    recover_local_fields(const LinearAlgebra::Vector &du);

    /**
     * The displacement was set outside Newton's method (a new start, a
     * step cut, a restart, an explicit step): the condensed fields return
     * to local equilibrium at the next assembly.
     */
    void
    reset_local_fields();

    /**
     * Whether assemble() uses the iterates (default) or the closed form,
     * leaving the iterates alone: the external force is computed as the
     * residual at u = 0, where the closed form's internal force is zero.
     */
    void
    use_condensed_field_iterates(const bool use);

    /** "Q1 cell 17", "the family of particle 4", for messages. */
    virtual std::string
    element_name(const unsigned int e) const = 0;

    /** A position of element @p e for messages (a cell centre, a master). */
    virtual Point<dim>
    element_position(const unsigned int e) const = 0;

    /** What to check when an element's residual is not finite. */
    virtual std::string
    non_finite_hint() const = 0;

  protected:
    /**
     * The condensed-field iterate of element @p e, or nullptr (closed form,
     * keep_condensed_field_iterates() not called). assemble() of element e
     * writes it; distinct elements are distinct objects (thread-safe).
     */
    CondensedFieldIterate *
    condensed_field_iterate(const unsigned int e) const;

  private:
    mutable std::vector<CondensedFieldIterate> condensed_iterates;
    bool                                       iterates_in_use = true;
  };
} // namespace pg

#endif
