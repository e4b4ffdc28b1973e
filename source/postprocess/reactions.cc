#include <pg/constraints/boundary_constraints.h>
#include <pg/postprocess/postprocessors.h>
#include <pg/postprocess/run_summary.h>

#include <cmath>

namespace pg
{
  namespace Postprocess
  {
    template <int dim>
    void
    Reactions<dim>::execute(const ProblemView<dim> &view,
                            const Step &,
                            TableHandler &,
                            RunSummary &summary)
    {
      const auto &prm         = *view.parameters;
      const auto &dof_handler = *view.dof_handler;
      const auto &owned_dofs  = *view.owned_dofs;
      const auto &force       = *view.force;
      const auto  comm        = view.mpi_communicator;
      // Reactions: f_int - f_ext summed over the constrained components of
      // the vertices of each Dirichlet boundary id (a vertex shared by two
      // Dirichlet boundaries counts for both).
      summary.reactions.clear();
      for (const auto &[id, mask] : prm.boundary_conditions.dirichlet)
        {
          std::vector<bool>   counted(dof_handler.n_dofs(), false);
          std::vector<double> reaction(dim, 0.);
          for (const auto &cell : dof_handler.active_cell_iterators())
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  cell->face(f)->boundary_id() == id)
                for (const unsigned int v : cell->face(f)->vertex_indices())
                  for (unsigned int c = 0; c < dim; ++c)
                    if (mask[c])
                      {
                        const auto dof =
                          cell->face(f)
                            ->vertex_dof_index(v, c, cell->active_fe_index());
                        if (!counted[dof] && owned_dofs.is_element(dof))
                          reaction[c] += force[dof];
                        counted[dof] = true;
                      }
          Utilities::MPI::sum(reaction, comm, reaction);
          summary.reactions[id] = reaction;
        }
      // The same for 'Dirichlet boxes': the vertices in each box, as in
      // make_constraints().
      summary.box_reactions.clear();
      const double box_tolerance = 1e-10 * (*view.mesh_diameter);
      for (const auto &box : prm.boundary_conditions.dirichlet_boxes)
        {
          std::vector<bool>   counted(dof_handler.n_dofs(), false);
          std::vector<double> reaction(dim, 0.);
          for (const auto &cell : dof_handler.active_cell_iterators())
            for (const unsigned int v : cell->vertex_indices())
              {
                bool inside = true;
                for (unsigned int d = 0; d < dim; ++d)
                  inside = inside &&
                           cell->vertex(v)[d] >= box.lower[d] - box_tolerance &&
                           cell->vertex(v)[d] <= box.upper[d] + box_tolerance;
                if (inside)
                  for (unsigned int c = 0; c < dim; ++c)
                    if (box.components[c])
                      {
                        const auto dof = cell->vertex_dof_index(v, c);
                        if (!counted[dof] && owned_dofs.is_element(dof))
                          reaction[c] += force[dof];
                        counted[dof] = true;
                      }
              }
          Utilities::MPI::sum(reaction, comm, reaction);
          summary.box_reactions.push_back(reaction);
        }
      // And for 'Dirichlet node sets': the vertices of each node set.
      summary.node_set_reactions.clear();
      if (!prm.boundary_conditions.dirichlet_node_sets.empty())
        {
          const auto vertex_cell = vertex_cells(dof_handler);
          for (const auto &[name, mask] :
               prm.boundary_conditions.dirichlet_node_sets)
            {
              std::vector<double> reaction(dim, 0.);
              for (const unsigned int vertex :
                   node_set_vertices(name, *view.node_sets))
                {
                  const auto &[cell, v] = vertex_cell[vertex];
                  for (unsigned int c = 0; c < dim; ++c)
                    if (mask[c])
                      {
                        const auto dof =
                          cell->vertex_dof_index(v, c, cell->active_fe_index());
                        if (owned_dofs.is_element(dof))
                          reaction[c] += force[dof];
                      }
                }
              Utilities::MPI::sum(reaction, comm, reaction);
              summary.node_set_reactions[name] = reaction;
            }
        }
      // The rigid wall: the sum of the contact forces of the held nodes.
      summary.wall_reaction.clear();
      if (view.rigid_wall != nullptr)
        {
          const Tensor<1, dim> r = view.rigid_wall->reaction(force);
          for (unsigned int d = 0; d < dim; ++d)
            summary.wall_reaction.push_back(r[d]);
          summary.wall_active_nodes = view.rigid_wall->n_active();
          summary.wall_min_gap      = view.rigid_wall->min_gap(*view.u);
        }
    }



    template <int dim>
    void
    Reactions<dim>::finalize(const ProblemView<dim> &view,
                             const Step &,
                             TableHandler &,
                             RunSummary &summary)
    {
      const ConditionalOStream &pcout = *view.pcout;
      for (const auto &[id, r] : summary.reactions)
        {
          pcout << "  reaction on boundary " << static_cast<int>(id) << ":";
          for (const double v : r)
            pcout << " " << (std::abs(v) < 1e-9 ? 0. : v);
          pcout << std::endl;
        }
      for (unsigned int b = 0; b < summary.box_reactions.size(); ++b)
        {
          pcout << "  reaction on Dirichlet box " << b + 1 << ":";
          for (const double v : summary.box_reactions[b])
            pcout << " " << (std::abs(v) < 1e-9 ? 0. : v);
          pcout << std::endl;
        }
      if (!summary.wall_reaction.empty())
        {
          pcout << "  reaction of the rigid wall:";
          for (const double v : summary.wall_reaction)
            pcout << " " << (std::abs(v) < 1e-9 ? 0. : v);
          pcout << " (" << summary.wall_active_nodes << " nodes held, min gap "
                << summary.wall_min_gap << ")" << std::endl;
        }
      for (const auto &[name, r] : summary.node_set_reactions)
        {
          pcout << "  reaction on node set " << name << ":";
          for (const double v : r)
            pcout << " " << (std::abs(v) < 1e-9 ? 0. : v);
          pcout << std::endl;
        }
    }



    template class Reactions<2>;
    template class Reactions<3>;
  } // namespace Postprocess
} // namespace pg
