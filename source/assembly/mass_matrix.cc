#include <pg/assembly/mass_matrix.h>
#include <pg/base/exceptions.h>
#include <pg/mesh/linear_cells.h>

#include <deal.II/base/quadrature_lib.h>
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
    const LinearCells<dim> cells(dof_handler.get_triangulation());
    const IndexSet        &owned_dofs     = dof_handler.locally_owned_dofs();
    const MPI_Comm         comm           = dof_handler.get_communicator();
    auto                  &mass_matrix    = masses.consistent;
    auto                  &condensed_mass = masses.condensed;
    auto                  &lumped_mass    = masses.lumped;
    auto                  &inverse_mass   = masses.inverse;
    // Lumped: every rank sums over all cells (the shared triangulation
    // knows them), so the full vector needs no communication.
    Vector<double> m(dof_handler.n_dofs());
    // the DoFs of the extra nodal fields (pressure, dilatation): no mass
    std::vector<bool>                    massless(dof_handler.n_dofs(), false);
    FEValues<dim>                        fe_values(cells.mapping(),
                            cells.scalar_element(),
                            cells.quadrature(2),
                            update_values | update_JxW_values);
    std::vector<types::global_dof_index> dofs;
    FullMatrix<double>                   local;
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
        // Components 0 ... dim-1 are the displacement (FieldLayout); for
        // FE_Q(1) and FE_SimplexP(1) bases the index within the base
        // element is the vertex.
        const FiniteElement<dim> &fe = cell->get_fe();
        dofs.resize(fe.n_dofs_per_cell());
        cell->get_dof_indices(dofs);
        local.reinit(dofs.size(), dofs.size());
        const bool lumped = !consistent || meshfree[cell->active_cell_index()];
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            const auto [c, a] = fe.system_to_component_index(i);
            if (c >= dim)
              {
                massless[dofs[i]] = true;
                continue;
              }
            for (const unsigned int q : fe_values.quadrature_point_indices())
              {
                const double w =
                  rho * fe_values.shape_value(a, q) * fe_values.JxW(q);
                m[dofs[i]] += w;
                if (lumped)
                  local(i, i) += w;
                else
                  for (unsigned int j = 0; j < dofs.size(); ++j)
                    {
                      const auto [c_j, b] = fe.system_to_component_index(j);
                      if (c_j == c)
                        local(i, j) += w * fe_values.shape_value(b, q);
                    }
              }
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
    masses.massless.clear();
    masses.massless.set_size(dof_handler.n_dofs());
    for (const auto i : owned_dofs)
      {
        if (massless[i])
          {
            masses.massless.add_index(i);
            continue;
          }
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
