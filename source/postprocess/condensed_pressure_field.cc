#include <pg/elements/condensed_pressure.h>
#include <pg/elements/family_elements.h>
#include <pg/elements/nodal_pressure.h>
#include <pg/elements/q1_cell.h>
#include <pg/families/family_set.h>
#include <pg/mesh/particle_set.h>
#include <pg/postprocess/condensed_pressure_field.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <limits>

namespace pg
{
  namespace Postprocess
  {
    template <int dim>
    CondensedPressureField
    condensed_pressure_field(const ProblemView<dim> &view,
                             const Vector<double>   &u_all)
    {
      const auto &formulation = *view.formulation;
      Assert(formulation.mixed(), ExcInternalError());
      const auto *split =
        dynamic_cast<const Materials::VolumetricSplit<dim> *>(view.material);
      AssertThrow(split != nullptr, ExcInternalError());
      const auto            &particles   = *view.particles;
      const unsigned int     n_particles = particles.n_particles();
      CondensedPressureField field;
      field.particle_pressure.assign(n_particles, 0.);
      field.particle_dilatation.assign(n_particles, 0.);
      double     lowest  = std::numeric_limits<double>::max();
      double     highest = std::numeric_limits<double>::lowest();
      const auto note    = [&](const double p) {
        lowest  = std::min(lowest, p);
        highest = std::max(highest, p);
      };

      // (the nodal dilatation unknown is Theta - theta(I))
      const double theta_0 = rest_volume_measure(*split);
      // The families: on their own table (PBG) or the master's (PPG).
      const bool ppg = (formulation.method != FormulationCode::Method::pbg);
      std::vector<Tensor<1, dim>> y;
      QuadratureTable<dim>        master_table;
      for (unsigned int f = 0; f < view.owned_families->size(); ++f)
        {
          const unsigned int k       = (*view.owned_families)[f];
          const auto         members = view.families->members(k);
          y.resize(members.size());
          for (unsigned int b = 0; b < members.size(); ++b)
            for (unsigned int c = 0; c < dim; ++c)
              y[b][c] = particles.position(members[b])[c] -
                        particles.position(k)[c] +
                        particles.mirror_sign(members[b], c) *
                          u_all[particles.dof(members[b], c)];
          if (ppg)
            view.family_elements->build_master_table(k, master_table);
          const QuadratureTable<dim> &volumetric_table =
            ppg ? master_table : (*view.family_tables)[f];
          if (formulation.incompressible())
            {
              // IUnlP0: the family's pressure DoF; Theta = 1, and the
              // dilatation written is theta-bar, where the constraint holds
              field.particle_pressure[k] = u_all[particles.dof(k, dim)];
              field.particle_dilatation[k] =
                condensed_pressure(volumetric_table, y, *split).dilatation;
              note(field.particle_pressure[k]);
              continue;
            }
          if (formulation.n_nodal_fields() > 0)
            {
              // U2P1C, Unl+P1C: the nodal values
              field.particle_pressure[k] = u_all[particles.dof(k, dim)];
              field.particle_dilatation[k] =
                theta_0 + u_all[particles.dof(k, dim + 1)];
              note(field.particle_pressure[k]);
              continue;
            }
          const CondensedPressure value =
            condensed_pressure(volumetric_table,
                               y,
                               *split,
                               formulation.condensed_pressure_degree());
          field.particle_pressure[k]   = value.pressure;
          field.particle_dilatation[k] = value.dilatation;
          note(value.pressure);
        }
      // every family belongs to one rank: the sum gathers them
      Utilities::MPI::sum(field.particle_pressure,
                          view.mpi_communicator,
                          field.particle_pressure);
      Utilities::MPI::sum(field.particle_dilatation,
                          view.mpi_communicator,
                          field.particle_dilatation);

      const auto &triangulation = *view.triangulation;
      field.cell_pressure.reinit(triangulation.n_active_cells());
      field.cell_dilatation.reinit(triangulation.n_active_cells());
      // Q1P0/H1P0 cells: P0 on the cell's Gauss points
      FEValues<dim>                        fe_values(view.cells->mapping(),
                              *view.fe_scalar,
                              view.cells->fe_cell_quadrature(),
                              update_gradients | update_JxW_values);
      QuadratureTable<dim>                 table;
      std::vector<types::global_dof_index> dofs(view.fe->n_dofs_per_cell());
      for (const auto &cell : *view.owned_fe_cells)
        {
          fe_values.reinit(
            typename Triangulation<dim>::active_cell_iterator(cell));
          fill_q1_table(fe_values, table);
          cell->get_dof_indices(dofs);
          y.resize(cell->n_vertices());
          for (unsigned int b = 0; b < y.size(); ++b)
            for (unsigned int c = 0; c < dim; ++c)
              y[b][c] = cell->vertex(b)[c] - cell->vertex(0)[c] +
                        u_all[dofs[b * dim + c]];
          const CondensedPressure value = condensed_pressure(table, y, *split);
          field.cell_pressure[cell->active_cell_index()]   = value.pressure;
          field.cell_dilatation[cell->active_cell_index()] = value.dilatation;
          note(value.pressure);
        }
      // meshfree cells: the mean of their particles
      std::vector<int> particle_at(triangulation.n_vertices(), -1);
      for (unsigned int k = 0; k < n_particles; ++k)
        particle_at[particles.vertex(k)] = k;
      for (const auto &cell : triangulation.active_cell_iterators())
        if ((*view.meshfree)[cell->active_cell_index()])
          {
            double       p = 0, theta = 0;
            unsigned int n = 0;
            for (const unsigned int v : cell->vertex_indices())
              if (particle_at[cell->vertex_index(v)] >= 0)
                {
                  const unsigned int k = particle_at[cell->vertex_index(v)];
                  p += field.particle_pressure[k];
                  theta += field.particle_dilatation[k];
                  ++n;
                }
            if (n > 0)
              {
                field.cell_pressure[cell->active_cell_index()]   = p / n;
                field.cell_dilatation[cell->active_cell_index()] = theta / n;
              }
          }
      field.min_pressure = Utilities::MPI::min(lowest, view.mpi_communicator);
      field.max_pressure = Utilities::MPI::max(highest, view.mpi_communicator);
      return field;
    }



    template CondensedPressureField
    condensed_pressure_field(const ProblemView<2> &, const Vector<double> &);
    template CondensedPressureField
    condensed_pressure_field(const ProblemView<3> &, const Vector<double> &);
  } // namespace Postprocess
} // namespace pg
