#ifndef pg_history_quadrature_point_history_h
#define pg_history_quadrature_point_history_h

#include <pg/base/global.h>

#include <deal.II/base/array_view.h>

#include <boost/serialization/split_member.hpp>
#include <boost/serialization/vector.hpp>

#include <cstddef>
#include <functional>
#include <vector>

namespace pg
{
  /**
   * The state variables of a material at every evaluation point: the Gauss
   * points of Q1 cells and the evaluation points of PG families alike,
   * keyed by (group, element, point), where a group is e.g. the Q1 cells or
   * one kind of family and an element is a cell or a family of it (deal.II's
   * CellDataStorage is keyed by cells and cannot key families).
   *
   * Two copies are kept in flat vectors: the committed state (end of the
   * last accepted load step) and the trial state (the current Newton
   * iterate). The values of one element are contiguous, point by point, so
   * an element gets one slice for the kernel (assemble_element()). The
   * cycle of a load step:
   * - every iteration evaluates from committed() and writes trial();
   * - commit() when the step is accepted: committed = trial;
   * - revert() on a failed Newton iteration or a step cut: trial =
   *   committed, bit for bit.
   * Distinct elements' slices are disjoint, so elements can be assembled
   * concurrently.
   */
  class QuadraturePointHistory
  {
  public:
    /**
     * Size the storage for @p n_points_per_element[g][e] points of element
     * e of group g, with @p n_variables values per point, and set both
     * copies of every point to @p initializer(state) (e.g. [&](const
     * ArrayView<double> &s) { material.initialize_state(s); }); without an
     * initializer the values are zero.
     */
    void
    reinit(
      const std::vector<std::vector<unsigned int>> &n_points_per_element,
      const unsigned int                            n_variables,
      const std::function<void(const ArrayView<double> &)> &initializer = {});

    unsigned int
    n_groups() const;
    unsigned int
    n_elements(const unsigned int group) const;
    unsigned int
    n_points(const unsigned int group, const unsigned int element) const;
    /** Values per point. */
    unsigned int
    n_variables() const;

    /** The committed state of point @p q (n_variables() values). */
    ArrayView<const double>
    committed(const unsigned int group,
              const unsigned int element,
              const unsigned int q) const;
    /** The trial state of point @p q. */
    ArrayView<double>
    trial(const unsigned int group,
          const unsigned int element,
          const unsigned int q);

    /**
     * The committed state of all points of an element: point q's values
     * start at q * n_variables(). The slice the kernel takes.
     */
    ArrayView<const double>
    committed(const unsigned int group, const unsigned int element) const;
    /** The trial state of all points of an element. */
    ArrayView<double>
    trial(const unsigned int group, const unsigned int element);

    /** Accept the step: committed = trial. */
    void
    commit();
    /** Discard the iterate: trial = committed. */
    void
    revert();

    /** Bytes used. */
    std::size_t
    memory_consumption() const;

    /**
     * The flat committed values, element after element in (group, element)
     * order, and the point offsets (point_offsets[i] is the first point of
     * element i over all groups; group_offsets[g] the first element of
     * group g). Checkpointing stores these; trial is committed after a
     * restart.
     */
    const std::vector<double> &
    committed_values() const;
    const std::vector<unsigned int> &
    group_offsets() const;
    const std::vector<unsigned int> &
    point_offsets() const;

    /** Write the layout and the committed values (boost archive). */
    template <class Archive>
    void
    save(Archive &archive, const unsigned int /*version*/) const
    {
      archive &variables_per_point &first_element &first_point
        &committed_storage;
    }

    /** Read what save() wrote; trial = committed. */
    template <class Archive>
    void
    load(Archive &archive, const unsigned int /*version*/)
    {
      archive &variables_per_point &first_element &first_point
        &committed_storage;
      trial_storage = committed_storage;
    }

    BOOST_SERIALIZATION_SPLIT_MEMBER()

  private:
    /** Index over all groups of element @p e of group @p g. */
    unsigned int
    element_index(const unsigned int group, const unsigned int element) const;

    unsigned int              variables_per_point = 0;
    std::vector<unsigned int> first_element       = {0}; //!< per group, + end
    std::vector<unsigned int> first_point         = {0}; //!< per element, + end
    std::vector<double>       committed_storage;
    std::vector<double>       trial_storage;
  };
} // namespace pg

#endif
