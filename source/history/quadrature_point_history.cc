#include <pg/history/quadrature_point_history.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/memory_consumption.h>

namespace pg
{
  void
  QuadraturePointHistory::reinit(
    const std::vector<std::vector<unsigned int>>         &n_points_per_element,
    const unsigned int                                    n_variables,
    const std::function<void(const ArrayView<double> &)> &initializer)
  {
    variables_per_point = n_variables;
    first_element.assign(1, 0);
    first_point.assign(1, 0);
    for (const std::vector<unsigned int> &group : n_points_per_element)
      {
        for (const unsigned int n : group)
          first_point.push_back(first_point.back() + n);
        first_element.push_back(first_element.back() + group.size());
      }

    const std::size_t n_values =
      static_cast<std::size_t>(first_point.back()) * n_variables;
    committed_storage.assign(n_values, 0.);
    if (initializer && n_variables > 0)
      for (std::size_t start = 0; start < n_values; start += n_variables)
        initializer(
          make_array_view(committed_storage.begin() + start,
                          committed_storage.begin() + start + n_variables));
    trial_storage = committed_storage;
  }



  unsigned int
  QuadraturePointHistory::n_groups() const
  {
    return first_element.size() - 1;
  }



  unsigned int
  QuadraturePointHistory::n_elements(const unsigned int group) const
  {
    AssertIndexRange(group, n_groups());
    return first_element[group + 1] - first_element[group];
  }



  unsigned int
  QuadraturePointHistory::element_index(const unsigned int group,
                                        const unsigned int element) const
  {
    AssertIndexRange(element, n_elements(group));
    return first_element[group] + element;
  }



  unsigned int
  QuadraturePointHistory::n_points(const unsigned int group,
                                   const unsigned int element) const
  {
    const unsigned int i = element_index(group, element);
    return first_point[i + 1] - first_point[i];
  }



  unsigned int
  QuadraturePointHistory::n_variables() const
  {
    return variables_per_point;
  }



  ArrayView<const double>
  QuadraturePointHistory::committed(const unsigned int group,
                                    const unsigned int element,
                                    const unsigned int q) const
  {
    AssertIndexRange(q, n_points(group, element));
    const std::size_t start =
      (static_cast<std::size_t>(first_point[element_index(group, element)]) +
       q) *
      variables_per_point;
    return make_array_view(committed_storage.data() + start,
                           committed_storage.data() + start +
                             variables_per_point);
  }



  ArrayView<double>
  QuadraturePointHistory::trial(const unsigned int group,
                                const unsigned int element,
                                const unsigned int q)
  {
    AssertIndexRange(q, n_points(group, element));
    const std::size_t start =
      (static_cast<std::size_t>(first_point[element_index(group, element)]) +
       q) *
      variables_per_point;
    return make_array_view(trial_storage.data() + start,
                           trial_storage.data() + start + variables_per_point);
  }



  ArrayView<const double>
  QuadraturePointHistory::committed(const unsigned int group,
                                    const unsigned int element) const
  {
    const unsigned int i = element_index(group, element);
    return make_array_view(committed_storage.data() +
                             static_cast<std::size_t>(first_point[i]) *
                               variables_per_point,
                           committed_storage.data() +
                             static_cast<std::size_t>(first_point[i + 1]) *
                               variables_per_point);
  }



  ArrayView<double>
  QuadraturePointHistory::trial(const unsigned int group,
                                const unsigned int element)
  {
    const unsigned int i = element_index(group, element);
    return make_array_view(trial_storage.data() +
                             static_cast<std::size_t>(first_point[i]) *
                               variables_per_point,
                           trial_storage.data() +
                             static_cast<std::size_t>(first_point[i + 1]) *
                               variables_per_point);
  }



  void
  QuadraturePointHistory::commit()
  {
    committed_storage = trial_storage;
  }



  void
  QuadraturePointHistory::revert()
  {
    trial_storage = committed_storage;
  }



  std::size_t
  QuadraturePointHistory::memory_consumption() const
  {
    return sizeof(*this) +
           MemoryConsumption::memory_consumption(first_element) +
           MemoryConsumption::memory_consumption(first_point) +
           MemoryConsumption::memory_consumption(committed_storage) +
           MemoryConsumption::memory_consumption(trial_storage);
  }



  const std::vector<double> &
  QuadraturePointHistory::committed_values() const
  {
    return committed_storage;
  }



  const std::vector<unsigned int> &
  QuadraturePointHistory::group_offsets() const
  {
    return first_element;
  }



  const std::vector<unsigned int> &
  QuadraturePointHistory::point_offsets() const
  {
    return first_point;
  }
} // namespace pg
