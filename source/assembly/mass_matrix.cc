#include <pg/assembly/mass_matrix.h>
#include <pg/base/exceptions.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <string>

namespace pg
{
  template <int dim>
  void
  assemble_masses(const DoFHandler<dim>             &dof_handler,
                  const std::vector<bool>           &meshfree,
                  const AffineConstraints<double>   &zero_constraints,
                  const LinearAlgebra::SparseMatrix &pattern,
                  const double                       rho,
                  const bool                         consistent,
                  MassMatrices                      &masses)
  {
    const FE_Q<dim> fe_scalar(1);
    const IndexSet &owned_dofs     = dof_handler.locally_owned_dofs();
    const MPI_Comm  comm           = dof_handler.get_communicator();
    auto           &mass_matrix    = masses.consistent;
    auto           &condensed_mass = masses.condensed;
    auto           &lumped_mass    = masses.lumped;
    auto           &inverse_mass   = masses.inverse;
    // Lumped: every rank sums over all cells (the shared triangulation
    // knows them), so the full vector needs no communication.
    Vector<double>     m(dof_handler.n_dofs());
    FEValues<dim>      fe_values(fe_scalar,
                            QGauss<dim>(2),
                            update_values | update_JxW_values);
    const unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;
    std::vector<types::global_dof_index> dofs(
      dof_handler.get_fe().n_dofs_per_cell());
    FullMatrix<double> local(dofs.size(), dofs.size());
    if (consistent)
      {
        mass_matrix.copy_from(pattern);
        mass_matrix = 0;
        condensed_mass.copy_from(pattern);
        condensed_mass = 0;
      }
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(
          typename Triangulation<dim>::active_cell_iterator(cell));
        cell->get_dof_indices(dofs);
        local             = 0;
        const bool lumped = !consistent || meshfree[cell->active_cell_index()];
        for (unsigned int a = 0; a < n_vertices; ++a)
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              const double w =
                rho * fe_values.shape_value(a, q) * fe_values.JxW(q);
              for (unsigned int c = 0; c < dim; ++c)
                m[dofs[a * dim + c]] += w;
              if (lumped)
                for (unsigned int c = 0; c < dim; ++c)
                  local(a * dim + c, a * dim + c) += w;
              else
                for (unsigned int b = 0; b < n_vertices; ++b)
                  for (unsigned int c = 0; c < dim; ++c)
                    local(a * dim + c, b * dim + c) +=
                      w * fe_values.shape_value(b, q);
            }
        if (consistent && cell->is_locally_owned())
          {
            mass_matrix.add(dofs, local);
            zero_constraints.distribute_local_to_global(local,
                                                        dofs,
                                                        condensed_mass);
          }
      }
    if (consistent)
      {
        mass_matrix.compress(VectorOperation::add);
        condensed_mass.compress(VectorOperation::add);
      }

    // The diagonal of C^T M C for the homogeneous constraints.
    Vector<double> m_condensed(m);
    for (const auto &line : zero_constraints.get_lines())
      {
        for (const auto &[j, c] : line.entries)
          m_condensed[j] += c * c * m[line.index];
        m_condensed[line.index] = 0;
      }
    lumped_mass.reinit(owned_dofs, comm);
    inverse_mass.reinit(owned_dofs, comm);
    for (const auto i : owned_dofs)
      {
        AssertThrow(m[i] > 0,
                    ExcBadParameter("Material/Density",
                                    std::to_string(rho),
                                    "dynamics needs a positive density."));
        lumped_mass(i)  = m[i];
        inverse_mass(i) = m_condensed[i] > 0 ? 1. / m_condensed[i] : 0.;
      }
    lumped_mass.compress(VectorOperation::insert);
    inverse_mass.compress(VectorOperation::insert);
  }



  template void
  assemble_masses<2>(const DoFHandler<2> &,
                     const std::vector<bool> &,
                     const AffineConstraints<double> &,
                     const LinearAlgebra::SparseMatrix &,
                     const double,
                     const bool,
                     MassMatrices &);
  template void
  assemble_masses<3>(const DoFHandler<3> &,
                     const std::vector<bool> &,
                     const AffineConstraints<double> &,
                     const LinearAlgebra::SparseMatrix &,
                     const double,
                     const bool,
                     MassMatrices &);
} // namespace pg
