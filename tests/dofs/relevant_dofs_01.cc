// The ghosted DoFs of a rank (compute_relevant_dofs) and the gather of a
// distributed vector (gather_to_all), on a parallel::shared mesh:
// 1. the relevant set holds the owned DoFs, the DoFs of every member of
//    every owned family and the DoFs of every locally owned cell, and on
//    more than one rank it is smaller than the set of all DoFs;
// 2. a ghosted Trilinos vector over it reads every member DoF of the owned
//    families (what the family groups gather) with the owners' values;
// 3. gather_to_all copies the owners' entries bit for bit on every rank
//    (a -0 stays -0, which a sum over the ranks would not keep).

#include <pg/base/linear_algebra.h>
#include <pg/dofs/relevant_dofs.h>
#include <pg/families/family_set.h>
#include <pg/mesh/particle_set.h>

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>

#include "../tests.h"

using namespace pg;

template <int dim>
void
test(const MPI_Comm comm)
{
  parallel::shared::Triangulation<dim> tria(
    comm,
    Triangulation<dim>::none,
    false,
    parallel::shared::Triangulation<dim>::partition_metis);
  GridGenerator::subdivided_hyper_cube(tria, dim == 2 ? 12 : 8, 0., 1.);
  const FESystem<dim> fe(FE_Q<dim>(1), dim);
  DoFHandler<dim>     dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  ParticleSet<dim> particles;
  particles.reinit(dof_handler, std::vector<bool>(tria.n_active_cells(), true));
  FamilySet<dim> families;
  families.reinit(particles, 2.51, 0);

  const IndexSet           &owned = dof_handler.locally_owned_dofs();
  std::vector<unsigned int> owned_families;
  for (unsigned int k = 0; k < particles.n_particles(); ++k)
    if (owned.is_element(particles.dof(k, 0)))
      owned_families.push_back(k);
  const IndexSet relevant =
    compute_relevant_dofs(dof_handler, particles, families, owned_families);

  // 1. what the set must hold
  bool complete = true;
  for (const auto i : owned)
    complete = complete && relevant.is_element(i);
  for (const unsigned int k : owned_families)
    for (const unsigned int b : families.members(k))
      for (unsigned int c = 0; c < dim; ++c)
        complete = complete && relevant.is_element(particles.dof(b, c));
  std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
  for (const auto &cell : dof_handler.active_cell_iterators())
    if (cell->is_locally_owned())
      {
        cell->get_dof_indices(cell_dofs);
        for (const auto i : cell_dofs)
          complete = complete && relevant.is_element(i);
      }
  AssertThrow(Utilities::MPI::min(complete ? 1 : 0, comm) == 1,
              ExcMessage("a needed DoF is not relevant"));
  const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
  const bool         smaller = relevant.n_elements() < dof_handler.n_dofs();
  AssertThrow(n_ranks == 1 ? relevant.n_elements() == dof_handler.n_dofs() :
                             Utilities::MPI::max(smaller ? 0 : 1, comm) == 0,
              ExcMessage("the relevant set is not what it should be"));
  deallog << dim << "-D: " << dof_handler.n_dofs() << " DoFs, "
          << particles.n_particles() << " particles on " << n_ranks
          << " ranks: owned, family members and owned cells relevant: yes"
          << std::endl;
  deallog << "every rank holds fewer than all DoFs (more than one rank): "
          << (n_ranks == 1 || smaller ? "yes" : "NO") << std::endl;

  // 2. ghost reads, 3. the gather (one -0 entry)
  pg::LinearAlgebra::Vector owned_values(owned, comm);
  for (const auto i : owned)
    owned_values(i) = (i == 1 ? -0. : 0.25 * i + 1.);
  owned_values.compress(VectorOperation::insert);
  pg::LinearAlgebra::Vector ghosted(owned, relevant, comm);
  ghosted   = owned_values;
  bool read = true;
  for (const unsigned int k : owned_families)
    for (const unsigned int b : families.members(k))
      for (unsigned int c = 0; c < dim; ++c)
        {
          const auto i = particles.dof(b, c);
          read         = read && (ghosted[i] == (i == 1 ? -0. : 0.25 * i + 1.));
        }
  AssertThrow(Utilities::MPI::min(read ? 1 : 0, comm) == 1,
              ExcMessage("a ghost entry has the wrong value"));
  const Vector<double> all   = gather_to_all(ghosted);
  bool                 exact = (all.size() == dof_handler.n_dofs());
  for (unsigned int i = 0; i < all.size() && exact; ++i)
    exact = (i == 1 ? (all[i] == 0. && std::signbit(all[i])) :
                      all[i] == 0.25 * i + 1.);
  AssertThrow(Utilities::MPI::min(exact ? 1 : 0, comm) == 1,
              ExcMessage("gather_to_all is not exact"));
  deallog << "ghost entries read the owners' values: yes" << std::endl;
  deallog << "gather_to_all bit for bit on every rank (-0 kept): yes"
          << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  if (Utilities::MPI::this_mpi_process(comm) == 0)
    initlog();
  else
    deallog.depth_console(0);
  test<2>(comm);
  test<3>(comm);
}
