#include <pg/assembly/assembler.h>
#include <pg/base/exceptions.h>
#include <pg/base/global_reader.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <deal.II/base/work_stream.h>

#include <Epetra_CrsMatrix.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace pg
{
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



  namespace
  {

    /** A group's per-thread scratch, copyable as WorkStream wants it. */
    struct ScratchHolder
    {
      explicit ScratchHolder(std::unique_ptr<GroupScratch> scratch)
        : scratch(std::move(scratch))
      {}
      ScratchHolder(const ScratchHolder &other)
        : scratch(other.scratch->clone())
      {}
      std::unique_ptr<GroupScratch> scratch;
      /** ElementGroup::get_dof_signs() of the element. */
      std::vector<double> signs;
    };
  } // namespace



  template <int dim>
  Assembler<dim>::Assembler(const AffineConstraints<double>        &constraints,
                            const std::vector<ElementGroup<dim> *> &groups)
    : constraints(constraints)
    , groups(groups)
    , seconds(groups.size(), 0.)
  {}



  template <int dim>
  void
  Assembler<dim>::recover_local_fields(const LinearAlgebra::Vector &du)
  {
    for (ElementGroup<dim> *group : groups)
      group->recover_local_fields(du);
  }



  template <int dim>
  void
  Assembler<dim>::reset_local_fields()
  {
    for (ElementGroup<dim> *group : groups)
      group->reset_local_fields();
  }



  template <int dim>
  void
  Assembler<dim>::use_condensed_field_iterates(const bool use)
  {
    for (ElementGroup<dim> *group : groups)
      group->use_condensed_field_iterates(use);
  }



  template <int dim>
  void
  Assembler<dim>::set_history(QuadraturePointHistory *history_)
  {
    history = history_;
  }



  template <int dim>
  std::vector<std::vector<unsigned int>>
  Assembler<dim>::evaluation_points() const
  {
    std::vector<std::vector<unsigned int>> n(groups.size());
    for (unsigned int g = 0; g < groups.size(); ++g)
      for (unsigned int e = 0; e < groups[g]->n_elements(); ++e)
        n[g].push_back(groups[g]->n_evaluation_points(e));
    return n;
  }



  template <int dim>
  double
  Assembler<dim>::integrate_committed_state(
    const std::function<double(const ArrayView<const double> &)> &f,
    const unsigned int n_material) const
  {
    AssertThrow(history != nullptr, ExcInternalError());
    double integral = 0;
    for (unsigned int g = 0; g < groups.size(); ++g)
      {
        const std::vector<double> weights =
          groups[g]->evaluation_point_weights();
        unsigned int i = 0;
        for (unsigned int e = 0; e < groups[g]->n_elements(); ++e)
          for (unsigned int q = 0; q < history->n_points(g, e); ++q, ++i)
            {
              AssertThrow(i < weights.size(),
                          ExcMessage("The evaluation points of the " +
                                     groups[g]->name() +
                                     " have no quadrature weights: the "
                                     "integral of the material state over "
                                     "the body is not defined for them."));
              const ArrayView<const double> state = history->committed(g, e, q);
              integral +=
                weights[i] *
                f(make_array_view(state.begin(), state.begin() + n_material));
            }
      }
    return integral;
  }



  template <int dim>
  void
  Assembler<dim>::add_sparsity(DynamicSparsityPattern &sparsity) const
  {
    for (const ElementGroup<dim> *group : groups)
      group->add_group_sparsity(constraints, sparsity);
  }



  template <int dim>
  std::string
  Assembler<dim>::non_finite_message(const std::string &element,
                                     const Point<dim>  &where,
                                     const std::string &hint)
  {
    std::ostringstream s;
    s << "NaN or inf in the residual or tangent of " << element << " at ("
      << where << "). " << hint;
    return s.str();
  }



  template <int dim>
  void
  Assembler<dim>::record_failure(const std::string &message)
  {
    std::lock_guard<std::mutex> lock(failure_mutex);
    if (failure.empty())
      failure = message;
  }



  template <int dim>
  bool
  Assembler<dim>::failed() const
  {
    return !failure.empty();
  }



  template <int dim>
  const std::vector<double> &
  Assembler<dim>::tangent_seconds() const
  {
    return seconds;
  }



  template <int dim>
  void
  Assembler<dim>::distribute(const LocalSystem &local)
  {
    if (local.dofs.empty())
      return;
    const bool with_matrix = local.with_matrix && matrix != nullptr;

    // Most elements touch no constrained DoF. Their entries go straight
    // into the matrix and vectors; AffineConstraints would sort and resolve
    // every row first, which for the large local matrices of CPD families
    // took half of a Debug test run (cpd_convergence_01: 136 s -> 105 s;
    // no measurable change in Release).
    bool unconstrained = true, in_range = range_size > 0;
    for (const auto dof : local.dofs)
      {
        if (constraints.is_constrained(dof))
          {
            unconstrained = false;
            break;
          }
        if (dof - range_first >= range_size) // also dof < range_first
          in_range = false;
      }
    if (unconstrained)
      {
        if (with_matrix)
          add_to_matrix(local);
        if (in_range)
          {
            double *const rhs_values   = (*rhs).trilinos_vector()[0];
            double *const force_values = (*force).trilinos_vector()[0];
            for (unsigned int i = 0; i < local.dofs.size(); ++i)
              {
                const auto j = local.dofs[i] - range_first;
                rhs_values[j] += -local.residual[i];
                force_values[j] += local.residual[i];
              }
            return;
          }
      }
    minus_residual.reinit(local.residual.size(), true);
    for (unsigned int i = 0; i < local.residual.size(); ++i)
      minus_residual[i] = -local.residual[i];
    if (unconstrained)
      rhs->add(local.dofs, minus_residual);
    else if (with_matrix)
      constraints.distribute_local_to_global(local.matrix,
                                             minus_residual,
                                             local.dofs,
                                             *matrix,
                                             *rhs);
    else
      constraints.distribute_local_to_global(minus_residual, local.dofs, *rhs);
    force->add(local.dofs, local.residual);
  }



  template <int dim>
  void
  Assembler<dim>::add_to_matrix(const LocalSystem &local)
  {
    const Epetra_CrsMatrix &A       = matrix->trilinos_matrix();
    const Epetra_BlockMap  &columns = A.ColMap();
    const Epetra_BlockMap  &rows    = A.RowMap();
    const unsigned int      n       = local.dofs.size();
    local_columns.resize(n);
    column_order.resize(n);
    row_positions.resize(n);
    for (unsigned int j = 0; j < n; ++j)
      {
        local_columns[j] = columns.LID(
          static_cast<TrilinosWrappers::types::int_type>(local.dofs[j]));
        if (local_columns[j] < 0) // not in the pattern: deal.II's message
          {
            matrix->add(local.dofs, local.matrix);
            return;
          }
        column_order[j] = j;
      }
    std::sort(column_order.begin(),
              column_order.end(),
              [&](const unsigned int a, const unsigned int b) {
                return local_columns[a] < local_columns[b];
              });

    bool have_positions = false;
    for (unsigned int i = 0; i < n; ++i)
      {
        const double *const local_row = &local.matrix(i, 0);
        const int           row       = rows.LID(
          static_cast<TrilinosWrappers::types::int_type>(local.dofs[i]));
        int     n_entries = 0;
        double *values    = nullptr;
        int    *indices   = nullptr;
        if (row < 0 || A.ExtractMyRowView(row, n_entries, values, indices) != 0)
          {
            matrix->add(local.dofs[i], n, local.dofs.data(), local_row);
            continue;
          }
        // the positions of the previous row fit if its column list is the
        // same (the rows of one particle's components)
        bool found = have_positions;
        for (unsigned int t = 0; found && t < n; ++t)
          found = (row_positions[t] < n_entries &&
                   indices[row_positions[t]] == local_columns[column_order[t]]);
        if (!found)
          {
            found = true;
            int p = 0;
            for (unsigned int t = 0; found && t < n; ++t)
              {
                const int c = local_columns[column_order[t]];
                while (p < n_entries && indices[p] < c)
                  ++p;
                found            = (p < n_entries && indices[p] == c);
                row_positions[t] = p;
              }
          }
        have_positions = found;
        if (!found) // unsorted or not in the pattern: deal.II's add()
          {
            matrix->add(local.dofs[i], n, local.dofs.data(), local_row);
            continue;
          }
        for (unsigned int t = 0; t < n; ++t)
          values[row_positions[t]] += local_row[column_order[t]];
      }
  }



  template <int dim>
  void
  Assembler<dim>::add_load(const Vector<double>                       &f,
                           const std::vector<types::global_dof_index> &dofs)
  {
    constraints.distribute_local_to_global(f, dofs, *rhs);
    Vector<double> minus_f(f);
    minus_f *= -1.;
    force->add(dofs, minus_f);
  }



  template <int dim>
  std::string
  Assembler<dim>::assemble(const LinearAlgebra::Vector &u,
                           LinearAlgebra::SparseMatrix *matrix_,
                           LinearAlgebra::Vector       &rhs_,
                           LinearAlgebra::Vector       &force_,
                           const LoadTerm              &loads)
  {
    matrix = matrix_;
    rhs    = &rhs_;
    force  = &force_;
    if (matrix != nullptr)
      *matrix = 0;
    *rhs   = 0;
    *force = 0;
    failure.clear();
    range_first = range_size = 0;
    if (const auto &map = rhs->trilinos_vector().Map();
        map.SameAs(force->trilinos_vector().Map()) &&
        LinearAlgebra::is_index_range(map))
      {
        range_first = map.MinMyGID64();
        range_size  = map.NumMyElements();
      }
    const bool with_matrix = (matrix != nullptr);

    for (unsigned int g = 0; g < groups.size(); ++g)
      {
        const ElementGroup<dim>  &group = *groups[g];
        Timer                     timer;
        std::vector<unsigned int> elements(group.n_elements());
        for (unsigned int e = 0; e < elements.size(); ++e)
          elements[e] = e;
        WorkStream::run(
          elements.cbegin(),
          elements.cend(),
          [&](const std::vector<unsigned int>::const_iterator &it,
              ScratchHolder                                   &scratch,
              LocalSystem                                     &local) {
            local.dofs.clear();
            local.failure.clear();
            try
              {
                local.with_matrix = with_matrix;
                ElementHistory element_history;
                if (history != nullptr && history->n_variables() > 0)
                  {
                    element_history.committed   = history->committed(g, *it);
                    element_history.trial       = history->trial(g, *it);
                    element_history.n_variables = history->n_variables();
                  }
                group.assemble(*it,
                               u,
                               element_history,
                               *scratch.scratch,
                               local);
                // mirror images: the element's DoF is +-1 times the global
                group.get_dof_signs(*it, scratch.signs);
                if (!scratch.signs.empty())
                  apply_dof_signs(scratch.signs, local);
                if (!all_finite(local.residual,
                                with_matrix ? &local.matrix : nullptr))
                  {
                    local.dofs.clear();
                    local.failure =
                      non_finite_message(group.element_name(*it),
                                         group.element_position(*it),
                                         group.non_finite_hint());
                  }
              }
            catch (const std::exception &e)
              {
                // (the kernels do not know which element they evaluate:
                // the message names it, e.g. an inverted family)
                local.dofs.clear();
                std::ostringstream where;
                where << "In " << group.element_name(*it) << " at ("
                      << group.element_position(*it)
                      << "): " << user_message(e);
                local.failure = where.str();
              }
          },
          [this](const LocalSystem &local) {
            // in element order: the first failing element is reported
            if (!local.failure.empty())
              record_failure(local.failure);
            distribute(local);
          },
          ScratchHolder(group.create_scratch()),
          LocalSystem());
        if (with_matrix)
          seconds[g] += timer.wall_time();
      }

    if (loads)
      loads(*this);

    if (with_matrix)
      matrix->compress(VectorOperation::add);
    rhs->compress(VectorOperation::add);
    force->compress(VectorOperation::add);
    // l2_norm() is collective: every rank computes it, also one whose
    // elements failed (calling it only where failure is empty hung a step
    // cut on 2 ranks when the elements failed on one of them)
    const double rhs_norm = rhs->l2_norm();
    if (failure.empty() && !std::isfinite(rhs_norm))
      failure = "NaN or inf in the assembled residual (none in the "
                "elements' own contributions: check the constraints and "
                "'Prescribed displacement').";
    return failure;
  }



  template class Assembler<2>;
  template class Assembler<3>;
} // namespace pg
