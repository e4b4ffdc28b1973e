#include <pg/base/global_reader.h>
#include <pg/elements/element_group.h>

#include <algorithm>

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
    // a mirror image has its original's DoFs: each DoF once
    std::sort(dofs.begin(), dofs.end());
    dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
    constraints.add_entries_local_to_global(dofs, sparsity, true);
  }



  void
  apply_dof_signs(const std::vector<double> &signs, FullMatrix<double> &matrix)
  {
    AssertIndexRange(signs.size(), std::min(matrix.m(), matrix.n()) + 1);
    for (unsigned int i = 0; i < signs.size(); ++i)
      if (signs[i] != 1.)
        {
          for (unsigned int j = 0; j < matrix.n(); ++j)
            matrix(i, j) *= signs[i];
          for (unsigned int j = 0; j < matrix.m(); ++j)
            matrix(j, i) *= signs[i];
        }
  }



  void
  apply_dof_signs(const std::vector<double> &signs, LocalSystem &local)
  {
    AssertDimension(signs.size(), local.dofs.size());
    for (unsigned int i = 0; i < signs.size(); ++i)
      local.residual[i] *= signs[i];
    if (local.with_matrix)
      apply_dof_signs(signs, local.matrix);
  }



  template <int dim>
  void
  ElementGroup<dim>::get_dof_signs(const unsigned int,
                                   std::vector<double> &signs) const
  {
    signs.clear();
  }



  template <int dim>
  std::vector<double>
  ElementGroup<dim>::evaluation_point_weights() const
  {
    return {};
  }



  template <int dim>
  void
  ElementGroup<dim>::add_group_sparsity(
    const AffineConstraints<double> &constraints,
    DynamicSparsityPattern          &sparsity) const
  {
    for (unsigned int e = 0; e < n_elements(); ++e)
      add_sparsity(e, constraints, sparsity);
  }



  template <int dim>
  void
  ElementGroup<dim>::keep_condensed_field_iterates()
  {
    condensed_iterates.assign(n_elements(), CondensedFieldIterate());
  }



  template <int dim>
  void
  ElementGroup<dim>::recover_local_fields(const LinearAlgebra::Vector &du)
  {
    const LinearAlgebra::GlobalReader    du_at(du);
    std::vector<types::global_dof_index> dofs;
    std::vector<double>                  du_local, signs;
    for (unsigned int e = 0; e < condensed_iterates.size(); ++e)
      {
        // (U2P1C keeps iterates without fields to recover)
        if (!condensed_iterates[e].linearised())
          continue;
        get_dof_indices(e, dofs);
        get_dof_signs(e, signs);
        du_local.resize(dofs.size());
        for (unsigned int i = 0; i < dofs.size(); ++i)
          du_local[i] = (signs.empty() ? 1. : signs[i]) * du_at[dofs[i]];
        update_condensed_fields(condensed_iterates[e], du_local);
      }
  }



  template <int dim>
  void
  ElementGroup<dim>::reset_local_fields()
  {
    for (auto &iterate : condensed_iterates)
      {
        // Unl+P1C's bubble stays as the start of its local Newton
        // iteration: from u_b = 0 the family can be inverted where the
        // converged bubble was holding it (3-D punch, doc/benchmarks/
        // punch_3d.md)
        std::vector<double> bubble = std::move(iterate.bubble);
        iterate                    = CondensedFieldIterate();
        iterate.bubble             = std::move(bubble);
      }
  }



  template <int dim>
  CondensedFieldIterate *
  ElementGroup<dim>::condensed_field_iterate(const unsigned int e) const
  {
    return (condensed_iterates.empty() || !iterates_in_use) ?
             nullptr :
             &condensed_iterates[e];
  }



  template <int dim>
  void
  ElementGroup<dim>::use_condensed_field_iterates(const bool use)
  {
    iterates_in_use = use;
  }



  template class ElementGroup<2>;
  template class ElementGroup<3>;
} // namespace pg
