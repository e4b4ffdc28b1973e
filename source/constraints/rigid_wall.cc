#include <pg/base/exceptions.h>
#include <pg/constraints/rigid_wall.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace pg
{
  template <int dim>
  RigidWall<dim>::RigidWall(
    const Parameters::BoundaryConditions::RigidWall &parameters,
    const DoFHandler<dim>                           &dof_handler,
    const IndexSet                                  &relevant_dofs,
    const IndexSet                                  &owned_dofs,
    const double                                     mesh_diameter,
    const MPI_Comm                                   comm,
    const bool                                       hold_touching)
    : component(0)
    , sign(1.)
    , unilateral(parameters.unilateral)
    , comm(comm)
  {
    // parse_parameters() checked: one non-zero component of a unit vector
    for (unsigned int d = 0; d < dim; ++d)
      {
        point[d] = parameters.point[d];
        if (std::abs(parameters.normal[d]) > 0.5)
          {
            component = d;
            sign      = parameters.normal[d] > 0 ? 1. : -1.;
          }
      }
    std::vector<bool> seen(dof_handler.get_triangulation().n_vertices(), false);
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        {
          if (seen[cell->vertex_index(v)])
            continue;
          seen[cell->vertex_index(v)] = true;
          const types::global_dof_index dof =
            cell->vertex_dof_index(v, component, cell->active_fe_index());
          const Point<dim> &X = cell->vertex(v);
          if (sign * (X[component] - point[component]) < -1e-10 * mesh_diameter)
            {
              std::ostringstream where, text;
              where << "(" << X << ")";
              for (unsigned int d = 0; d < dim; ++d)
                text << (d ? ", " : "") << point[d];
              AssertThrow(
                false,
                ExcBadParameter(
                  "Boundary conditions/Rigid wall/Point",
                  text.str(),
                  "the wall plane cuts the initial body: vertex " +
                    std::to_string(cell->vertex_index(v)) + " at " +
                    where.str() + " lies behind it (n . (X - p) = " +
                    std::to_string(sign * (X[component] - point[component])) +
                    "). Move the point to the body's surface or beyond it, "
                    "or reverse 'Normal' (it points from the wall into the "
                    "body)."));
            }
          if (relevant_dofs.is_element(dof))
            {
              nodes.push_back({X, dof, owned_dofs.is_element(dof)});
              active.push_back(hold_touching &&
                               sign * (X[component] - point[component]) <=
                                 1e-10 * mesh_diameter);
            }
        }
  }



  template <int dim>
  std::map<types::global_dof_index, double>
  RigidWall<dim>::values(const bool homogeneous) const
  {
    std::map<types::global_dof_index, double> result;
    for (unsigned int i = 0; i < nodes.size(); ++i)
      if (active[i])
        result[nodes[i].dof] =
          homogeneous ? 0. : point[component] - nodes[i].position[component];
    return result;
  }



  template <int dim>
  std::pair<unsigned int, unsigned int>
  RigidWall<dim>::update(const LinearAlgebra::Vector     &u,
                         const LinearAlgebra::Vector     &force,
                         const AffineConstraints<double> &other_constraints,
                         const bool                       release)
  {
    // the force on the relevant DoFs, so that every rank decides alike
    IndexSet relevant(force.size());
    for (const Node &node : nodes)
      relevant.add_index(node.dof);
    relevant.compress();
    LinearAlgebra::Vector ghosted(force.locally_owned_elements(),
                                  relevant,
                                  comm);
    ghosted            = force;
    unsigned int added = 0, released = 0;
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        const types::global_dof_index dof = nodes[i].dof;
        if (!active[i])
          {
            if (!other_constraints.is_constrained(dof) && gap(i, u[dof]) < 0.)
              {
                active[i] = true;
                added += nodes[i].owned;
              }
          }
        else if (release && unilateral && sign * ghosted[dof] < 0.)
          {
            active[i] = false;
            released += nodes[i].owned;
          }
      }
    return {Utilities::MPI::sum(added, comm),
            Utilities::MPI::sum(released, comm)};
  }



  template <int dim>
  void
  RigidWall<dim>::hold(LinearAlgebra::Vector &v) const
  {
    for (unsigned int i = 0; i < nodes.size(); ++i)
      if (active[i] && nodes[i].owned)
        v[nodes[i].dof] = 0.;
    v.compress(VectorOperation::insert);
  }



  template <int dim>
  Tensor<1, dim>
  RigidWall<dim>::reaction(const LinearAlgebra::Vector &force) const
  {
    Tensor<1, dim> r;
    for (unsigned int i = 0; i < nodes.size(); ++i)
      if (active[i] && nodes[i].owned)
        r[component] += force[nodes[i].dof];
    return Utilities::MPI::sum(r, comm);
  }



  template <int dim>
  unsigned int
  RigidWall<dim>::n_active() const
  {
    unsigned int n = 0;
    for (unsigned int i = 0; i < nodes.size(); ++i)
      n += (active[i] && nodes[i].owned);
    return Utilities::MPI::sum(n, comm);
  }



  template <int dim>
  double
  RigidWall<dim>::min_gap(const LinearAlgebra::Vector &u) const
  {
    double g = std::numeric_limits<double>::max();
    for (unsigned int i = 0; i < nodes.size(); ++i)
      if (nodes[i].owned)
        g = std::min(g, gap(i, u[nodes[i].dof]));
    return Utilities::MPI::min(g, comm);
  }



  template class RigidWall<2>;
  template class RigidWall<3>;
} // namespace pg
