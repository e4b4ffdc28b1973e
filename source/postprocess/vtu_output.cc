#include <pg/postprocess/condensed_pressure_field.h>
#include <pg/postprocess/output.h>
#include <pg/postprocess/postprocessors.h>
#include <pg/postprocess/run_summary.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/numerics/data_out.h>

#include <fstream>
#include <iomanip>
#include <optional>

namespace pg
{
  namespace Postprocess
  {
    template <int dim>
    void
    VtuOutput<dim>::execute(const ProblemView<dim> &view,
                            const Step             &step,
                            TableHandler           &statistics,
                            RunSummary             &summary)
    {
      write(view, step.number, step.time, statistics, summary);
    }



    template <int dim>
    void
    VtuOutput<dim>::finalize(const ProblemView<dim> &view,
                             const Step             &step,
                             TableHandler           &statistics,
                             RunSummary             &summary)
    {
      write(view, step.number, step.time, statistics, summary);
      // IUnlP0: the pressure is a primary unknown (one per family); a
      // checkerboard shows in its range
      if (view.formulation->incompressible())
        *view.pcout << "  family pressure: min "
                    << summary.condensed_pressure_range[0] << ", max "
                    << summary.condensed_pressure_range[1] << std::endl;
    }



    template <int dim>
    void
    VtuOutput<dim>::write(const ProblemView<dim> &view,
                          const unsigned int      step,
                          const double            t,
                          const TableHandler     &statistics,
                          RunSummary             &summary)
    {
      const auto       &prm = *view.parameters;
      const std::string dir = prm.output.directory + "/";
      summary.timing        = {{"mesh", *view.time_mesh},
                               {"setup", *view.time_setup},
                               {"shape_functions", *view.time_shape},
                               {"vc", *view.time_vc},
                               {"assembly", *view.time_assembly},
                               {"solve", *view.time_solve},
                               {"amg_operator", *view.time_amg_operator},
                               {"postprocess", view.postprocess_timer->wall_time()},
                               {"total", view.total_timer->wall_time()}};
      // The condensed pressure of a mixed formulation: its range goes to
      // summary.json, its field to the VTU files.
      const bool                            mixed = view.formulation->mixed();
      Vector<double>                        u_full;
      std::optional<CondensedPressureField> pressure;
      if (mixed || prm.output.vtu)
        u_full = view.gather_displacement(); // collective
      if (mixed)
        {
          pressure = condensed_pressure_field(view, u_full);
          summary.condensed_pressure_range = {pressure->min_pressure,
                                              pressure->max_pressure};
        }
      // A material with history: the largest value of each state output
      // over the committed points (collective)
      const std::vector<std::string> state_names =
        view.material->state_output_names();
      if (!state_names.empty())
        {
          const std::vector<double> maxima = view.maximum_state_outputs();
          summary.state_output_maxima.clear();
          for (unsigned int i = 0; i < state_names.size(); ++i)
            summary.state_output_maxima.emplace_back(state_names[i], maxima[i]);
        }
      if (view.root)
        {
          std::ofstream stat(dir + "statistics.txt");
          statistics.write_text(
            stat,
            TableHandler::table_with_separate_column_description);
          write_summary_json(summary, dir + "summary.json");
          std::ofstream timing(dir + "timing.txt");
          for (const auto &[name, seconds] : summary.timing)
            timing << std::left << std::setw(16) << name << seconds << " s\n";
          timing << std::left << std::setw(16) << "threads"
                 << MultithreadInfo::n_threads() << " per MPI rank, "
                 << Utilities::MPI::n_mpi_processes(view.mpi_communicator)
                 << " ranks\n";
        }
      if (!prm.output.vtu)
        return;

      const auto &particles = *view.particles;
      // (DataOut reads any DoF: u_full is gathered)
      const auto    &material = *view.material;
      const MPI_Comm comm     = view.mpi_communicator;
      DataOut<dim>   data_out;
      data_out.attach_dof_handler(*view.dof_handler);
      // U2P1C, Unl+P1C: the nodal pressure and Theta - theta(I) (zero on
      // the FE cells, whose condensed fields are the cell data below);
      // IUnlP0: the pressure of each particle's family
      std::vector<std::string> names(dim, "displacement");
      std::vector<DataComponentInterpretation::DataComponentInterpretation>
        interpretation(
          dim,
          DataComponentInterpretation::component_is_part_of_vector);
      if (view.formulation->n_nodal_fields() > 0)
        {
          names.emplace_back(view.formulation->incompressible() ?
                               "family_pressure" :
                               "nodal_pressure");
          if (view.formulation->n_nodal_fields() == 2)
            names.emplace_back("nodal_dilatation_change");
          interpretation.resize(
            dim + view.formulation->n_nodal_fields(),
            DataComponentInterpretation::component_is_scalar);
        }
      data_out.add_data_vector(u_full,
                               names,
                               DataOut<dim>::type_dof_data,
                               interpretation);
      // meshfree cells show the particles' F (section "What a run writes")
      const std::vector<Tensor<2, dim>> particle_F =
        view.particle_deformation_gradients();
      std::vector<int> particle_at(view.triangulation->n_vertices(), -1);
      for (unsigned int k = 0; k < particles.n_particles(); ++k)
        particle_at[particles.vertex(k)] = k;
      // IUnlP0: the material is the isochoric part; its pressure is the
      // family's DoF
      const bool incompressible = view.formulation->incompressible();
      std::function<double(unsigned int)> family_pressure;
      if (incompressible)
        family_pressure = [&](const unsigned int v) {
          return pressure->particle_pressure[particle_at[v]];
        };
      StressPostprocessor<dim> stress(
        material,
        *view.meshfree,
        [&](const unsigned int v) -> const Tensor<2, dim> * {
          return particle_at[v] >= 0 ? &particle_F[particle_at[v]] : nullptr;
        },
        family_pressure);
      // a material with history: stresses from the committed state, and
      // its state outputs as cell data (the mean over the cell's Gauss
      // points, or over the particles at a meshfree cell's vertices)
      const CommittedStates states = view.committed_states(); // collective
      stress.set_states(&states,
                        [&](const unsigned int v) { return particle_at[v]; });
      data_out.add_data_vector(u_full, stress);
      std::vector<Vector<double>> cell_state_outputs(
        state_names.size(),
        Vector<double>(view.triangulation->n_active_cells()));
      if (!state_names.empty() && states.n_material > 0)
        {
          std::vector<double> values(state_names.size());
          for (const auto &cell : view.triangulation->active_cell_iterators())
            {
              const unsigned int c = cell->active_cell_index();
              std::vector<ArrayView<const double>> points;
              if ((*view.meshfree)[c])
                {
                  for (const unsigned int v : cell->vertex_indices())
                    if (particle_at[cell->vertex_index(v)] >= 0)
                      points.push_back(
                        states.particle(particle_at[cell->vertex_index(v)]));
                }
              else
                for (unsigned int q = 0; q < states.points_per_cell; ++q)
                  points.push_back(states.cell(c, q));
              for (const auto &state : points)
                {
                  material.state_outputs(state, make_array_view(values));
                  for (unsigned int i = 0; i < values.size(); ++i)
                    cell_state_outputs[i][c] += values[i] / points.size();
                }
            }
        }
      for (unsigned int i = 0; i < state_names.size(); ++i)
        data_out.add_data_vector(cell_state_outputs[i],
                                 state_names[i],
                                 DataOut<dim>::type_cell_data);
      const auto   &meshfree = *view.meshfree;
      Vector<float> meshfree_cell(view.triangulation->n_active_cells());
      for (unsigned int c = 0; c < meshfree.size(); ++c)
        meshfree_cell[c] = meshfree[c];
      data_out.add_data_vector(meshfree_cell, "meshfree");
      if (pressure)
        {
          data_out.add_data_vector(pressure->cell_pressure,
                                   "condensed_pressure");
          data_out.add_data_vector(pressure->cell_dilatation,
                                   "condensed_dilatation");
        }
      // (MappingFE on triangles and tetrahedra)
      data_out.build_patches(view.cells->mapping());
      const std::string cells =
        data_out.write_vtu_with_pvtu_record(dir, "solution", step, comm, 4);
      // finalize() writes the last step again: one record per file
      if (pvd_cells.empty() || pvd_cells.back().second != cells)
        pvd_cells.emplace_back(t, cells);

      std::vector<std::string> particle_names(dim, "displacement");
      for (const std::string &n : stress_field_names<dim>())
        particle_names.push_back(n);
      particle_names.push_back("volume");
      for (unsigned int c = 0; c < dim; ++c)
        particle_names.push_back("unit_stress_residual");
      if (pressure)
        {
          particle_names.push_back("condensed_pressure");
          particle_names.push_back("condensed_dilatation");
        }
      // the state outputs at point 0 of the particle's family
      for (const std::string &n : state_names)
        particle_names.push_back(n);
      ParticleOutput<dim> particle_out(particle_names);
      std::vector<double> data, stress_values, state_values(state_names.size());
      for (const unsigned int k : *view.owned_families)
        {
          data.clear();
          for (unsigned int c = 0; c < dim; ++c)
            data.push_back(u_full[particles.dof(k, c)]);
          stress_field_values(material,
                              particle_F[k],
                              stress_values,
                              incompressible ? pressure->particle_pressure[k] :
                                               0.,
                              states.particle(k));
          data.insert(data.end(), stress_values.begin(), stress_values.end());
          data.push_back(particles.volume(k));
          for (unsigned int c = 0; c < dim; ++c)
            data.push_back((*view.unit_stress)[k][c]);
          if (pressure)
            {
              data.push_back(pressure->particle_pressure[k]);
              data.push_back(pressure->particle_dilatation[k]);
            }
          if (!state_names.empty())
            {
              if (states.n_material > 0)
                material.state_outputs(states.particle(k),
                                       make_array_view(state_values));
              data.insert(data.end(), state_values.begin(), state_values.end());
            }
          particle_out.add_particle(particles.position(k), data);
        }
      const std::string particles_file =
        particle_out.write_vtu_with_pvtu_record(dir,
                                                "particles",
                                                step,
                                                comm,
                                                4);
      if (pvd_particles.empty() ||
          pvd_particles.back().second != particles_file)
        pvd_particles.emplace_back(t, particles_file);
      if (view.root)
        {
          std::ofstream pvd(dir + "solution.pvd");
          DataOutBase::write_pvd_record(pvd, pvd_cells);
          std::ofstream ppvd(dir + "particles.pvd");
          DataOutBase::write_pvd_record(ppvd, pvd_particles);
        }
    }



    template class VtuOutput<2>;
    template class VtuOutput<3>;
  } // namespace Postprocess
} // namespace pg
