#include <pg/elements/element_group.h>

namespace pg
{
  template <int dim>
  void
  ElementGroup<dim>::add_sparsity(const unsigned int               e,
                                  const AffineConstraints<double> &constraints,
                                  DynamicSparsityPattern &sparsity) const
  {
    std::vector<types::global_dof_index> dofs;
    get_dof_indices(e, dofs);
    constraints.add_entries_local_to_global(dofs, sparsity, true);
  }



  template <int dim>
  void
  ElementGroup<dim>::recover_local_fields(const unsigned int,
                                          const LinearAlgebra::Vector &)
  {}



  template class ElementGroup<2>;
  template class ElementGroup<3>;
} // namespace pg
