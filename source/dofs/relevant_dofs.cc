#include <pg/dofs/relevant_dofs.h>

#include <deal.II/base/mpi.h>

#include <algorithm>

namespace pg
{
  template <int dim>
  IndexSet
  compute_relevant_dofs(const DoFHandler<dim>           &dof_handler,
                        const ParticleSet<dim>          &particles,
                        const FamilySet<dim>            &families,
                        const std::vector<unsigned int> &owned_families)
  {
    // Collect, sort and add at once: IndexSet::add_index inserts an
    // out-of-order index with a memmove.
    std::vector<types::global_dof_index> dofs;
    for (const unsigned int k : owned_families)
      for (const unsigned int b : families.members(k))
        for (unsigned int c = 0; c < particles.n_components(); ++c)
          dofs.push_back(particles.dof(b, c));
    std::vector<types::global_dof_index> cell_dofs;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell_dofs.resize(cell->get_fe().n_dofs_per_cell());
          cell->get_dof_indices(cell_dofs);
          dofs.insert(dofs.end(), cell_dofs.begin(), cell_dofs.end());
        }
    std::sort(dofs.begin(), dofs.end());
    dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());

    IndexSet relevant = dof_handler.locally_owned_dofs();
    relevant.add_indices(dofs.begin(), dofs.end());
    relevant.compress();
    return relevant;
  }



  Vector<double>
  gather_to_all(const LinearAlgebra::Vector &v)
  {
    const MPI_Comm                       comm  = v.get_mpi_communicator();
    const IndexSet                       owned = v.locally_owned_elements();
    std::vector<types::global_dof_index> indices;
    std::vector<double>                  values;
    indices.reserve(owned.n_elements());
    values.reserve(owned.n_elements());
    for (const auto i : owned)
      {
        indices.push_back(i);
        values.push_back(v(i));
      }
    Vector<double> all(v.size());
    if (Utilities::MPI::n_mpi_processes(comm) == 1)
      {
        for (std::size_t j = 0; j < indices.size(); ++j)
          all[indices[j]] = values[j];
        return all;
      }
    // Copies, not a sum over the ranks: a sum would turn -0 into +0.
    const auto all_indices = Utilities::MPI::all_gather(comm, indices);
    const auto all_values  = Utilities::MPI::all_gather(comm, values);
    for (std::size_t r = 0; r < all_indices.size(); ++r)
      for (std::size_t j = 0; j < all_indices[r].size(); ++j)
        all[all_indices[r][j]] = all_values[r][j];
    return all;
  }



  template IndexSet
  compute_relevant_dofs(const DoFHandler<2> &,
                        const ParticleSet<2> &,
                        const FamilySet<2> &,
                        const std::vector<unsigned int> &);
  template IndexSet
  compute_relevant_dofs(const DoFHandler<3> &,
                        const ParticleSet<3> &,
                        const FamilySet<3> &,
                        const std::vector<unsigned int> &);
} // namespace pg
