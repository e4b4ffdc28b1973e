#include <pg/dofs/relevant_dofs.h>
#include <pg/postprocess/problem_view.h>

#include <algorithm>
#include <limits>

namespace pg
{
  namespace Postprocess
  {
    namespace
    {
      /** F^k from a vector @p u read by global DoF index. */
      template <int dim, typename VectorType>
      Tensor<2, dim>
      deformation_gradient(const ProblemView<dim> &view,
                           const unsigned int      k,
                           const VectorType       &u)
      {
        const auto     members   = view.families->members(k);
        const auto    &B         = view.family_elements->master_gradients(k);
        const auto    &particles = *view.particles;
        Tensor<2, dim> F;
        for (unsigned int b = 0; b < members.size(); ++b)
          for (unsigned int i = 0; i < dim; ++i)
            {
              const double y = particles.position(members[b])[i] -
                               particles.position(k)[i] +
                               particles.mirror_sign(members[b], i) *
                                 u[particles.dof(members[b], i)];
              for (unsigned int j = 0; j < dim; ++j)
                F[i][j] += y * B[b][j];
            }
        return F;
      }
    } // namespace



    template <int dim>
    Vector<double>
    ProblemView<dim>::gather_displacement() const
    {
      return gather_to_all(*u);
    }



    template <int dim>
    Tensor<2, dim>
    ProblemView<dim>::particle_deformation_gradient(const unsigned int k) const
    {
      return deformation_gradient(*this, k, *u);
    }



    template <int dim>
    Tensor<2, dim>
    ProblemView<dim>::particle_deformation_gradient(
      const unsigned int    k,
      const Vector<double> &u_all) const
    {
      return deformation_gradient(*this, k, u_all);
    }



    template <int dim>
    CommittedStates
    ProblemView<dim>::committed_states() const
    {
      CommittedStates states;
      if (history == nullptr || material->n_state_variables() == 0)
        return states;
      const unsigned int n   = material->n_state_variables();
      states.n_material      = n;
      states.points_per_cell = 0;
      for (unsigned int e = 0; e < owned_fe_cells->size(); ++e)
        states.points_per_cell =
          std::max(states.points_per_cell, history->n_points(0, e));
      states.points_per_cell =
        Utilities::MPI::max(states.points_per_cell, mpi_communicator);
      // each cell and family is owned by one rank: the others add zeros
      states.cells.assign(static_cast<std::size_t>(
                            triangulation->n_active_cells()) *
                            states.points_per_cell * n,
                          0.);
      states.particles
        .assign(static_cast<std::size_t>(particles->n_particles()) * n, 0.);
      for (unsigned int e = 0; e < owned_fe_cells->size(); ++e)
        {
          const unsigned int c = (*owned_fe_cells)[e]->active_cell_index();
          for (unsigned int q = 0; q < history->n_points(0, e); ++q)
            {
              const auto state = history->committed(0, e, q);
              for (unsigned int i = 0; i < n; ++i)
                states.cells[(c * states.points_per_cell + q) * n + i] =
                  state[i];
            }
        }
      if (history->n_groups() > 1)
        for (unsigned int e = 0; e < owned_families->size(); ++e)
          if (history->n_points(1, e) > 0)
            {
              const unsigned int k     = (*owned_families)[e];
              const auto         state = history->committed(1, e, 0);
              for (unsigned int i = 0; i < n; ++i)
                states.particles[k * n + i] = state[i];
            }
      if (Utilities::MPI::n_mpi_processes(mpi_communicator) > 1)
        {
          Utilities::MPI::sum(states.cells, mpi_communicator, states.cells);
          Utilities::MPI::sum(states.particles,
                              mpi_communicator,
                              states.particles);
        }
      return states;
    }



    template <int dim>
    std::vector<double>
    ProblemView<dim>::maximum_state_outputs() const
    {
      const unsigned int  n_outputs = material->state_output_names().size();
      std::vector<double> maxima(n_outputs,
                                 -std::numeric_limits<double>::max());
      if (n_outputs == 0)
        return maxima;
      const unsigned int  n = material->n_state_variables();
      std::vector<double> values(n_outputs);
      if (history != nullptr && n > 0)
        for (unsigned int g = 0; g < history->n_groups(); ++g)
          for (unsigned int e = 0; e < history->n_elements(g); ++e)
            for (unsigned int q = 0; q < history->n_points(g, e); ++q)
              {
                const auto state = history->committed(g, e, q);
                material->state_outputs(make_array_view(state.begin(),
                                                        state.begin() + n),
                                        make_array_view(values));
                for (unsigned int i = 0; i < n_outputs; ++i)
                  maxima[i] = std::max(maxima[i], values[i]);
              }
      Utilities::MPI::max(maxima, mpi_communicator, maxima);
      return maxima;
    }



    template <int dim>
    std::vector<Tensor<2, dim>>
    ProblemView<dim>::particle_deformation_gradients() const
    {
      // F^k of the owned families from the ghosted u, then copied to every
      // rank (bit for bit: the same F as from a full vector)
      std::vector<Tensor<2, dim>> F(particles->n_particles());
      std::vector<unsigned int>   masters;
      std::vector<double>         values;
      for (const unsigned int k : *owned_families)
        {
          F[k] = deformation_gradient(*this, k, *u);
          masters.push_back(k);
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              values.push_back(F[k][i][j]);
        }
      if (Utilities::MPI::n_mpi_processes(mpi_communicator) == 1)
        return F;
      const auto all_masters =
        Utilities::MPI::all_gather(mpi_communicator, masters);
      const auto all_values =
        Utilities::MPI::all_gather(mpi_communicator, values);
      for (unsigned int r = 0; r < all_masters.size(); ++r)
        for (unsigned int m = 0; m < all_masters[r].size(); ++m)
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              F[all_masters[r][m]][i][j] =
                all_values[r][(m * dim + i) * dim + j];
      return F;
    }



    template <int dim>
    std::vector<double>
    ProblemView<dim>::displacement_at(const CellIterator   &cell,
                                      const Point<dim>     &reference,
                                      const Vector<double> &u_all) const
    {
      // (cell->get_fe(): a meshfree cell may carry extra nodal fields)
      const FiniteElement<dim>            &cell_fe = cell->get_fe();
      std::vector<types::global_dof_index> dofs(cell_fe.n_dofs_per_cell());
      cell->get_dof_indices(dofs);
      std::vector<double> value(dim, 0.);
      for (unsigned int j = 0; j < dofs.size(); ++j)
        {
          const unsigned int c = cell_fe.system_to_component_index(j).first;
          if (c < dim)
            value[c] += cell_fe.shape_value(j, reference) * u_all[dofs[j]];
        }
      return value;
    }



    template <int dim>
    Tensor<2, dim>
    ProblemView<dim>::exact_displacement_gradient(const Point<dim> &p) const
    {
      return Postprocess::exact_displacement_gradient(*parameters,
                                                      *mesh_diameter,
                                                      p);
    }



    template <int dim>
    Tensor<2, dim>
    exact_displacement_gradient(const Parameters::AllParameters<dim> &prm,
                                const double      mesh_diameter,
                                const Point<dim> &p)
    {
      Tensor<2, dim> G;
      if (prm.exact_gradient)
        {
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              G[i][j] = prm.exact_gradient->value(p, i * dim + j);
          return G;
        }
      // Without 'Gradient expression': the fourth-order central difference
      //   (-u(p + 2h) + 8 u(p + h) - 8 u(p - h) + u(p - 2h)) / (12 h)
      // with h = 1e-4 of the mesh diameter. Polynomials to degree 4 are
      // differentiated to round-off (about 1e-13 relative), smooth fields to
      // about 1e-12 (sin(pi x / 2) on [-1, 1]^2: 2e-13; Kirsch's field at the
      // hole: 1e-11). The deal.II default (central, h = 1e-8) stops at 1e-9.
      const double h = 1e-4 * mesh_diameter;
      for (unsigned int j = 0; j < dim; ++j)
        {
          const Tensor<1, dim> e = h * Point<dim>::unit_vector(j);
          for (unsigned int i = 0; i < dim; ++i)
            G[i][j] = (-prm.exact_solution.value(p + 2 * e, i) +
                       8 * prm.exact_solution.value(p + e, i) -
                       8 * prm.exact_solution.value(p - e, i) +
                       prm.exact_solution.value(p - 2 * e, i)) /
                      (12 * h);
        }
      return G;
    }



    template Tensor<2, 2>
    exact_displacement_gradient(const Parameters::AllParameters<2> &,
                                const double,
                                const Point<2> &);
    template Tensor<2, 3>
    exact_displacement_gradient(const Parameters::AllParameters<3> &,
                                const double,
                                const Point<3> &);
    template struct ProblemView<2>;
    template struct ProblemView<3>;
  } // namespace Postprocess
} // namespace pg
