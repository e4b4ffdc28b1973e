#include <pg/postprocess/output.h>
#include <pg/postprocess/run_summary.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <limits>
#include <utility>
#include <vector>

namespace pg
{
  template <int dim>
  std::vector<std::string>
  stress_field_names()
  {
    std::vector<std::string> names;
    const char               axis[] = {'x', 'y', 'z'};
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        names.push_back(std::string("F_") + axis[i] + axis[j]);
    for (const std::string c : {"xx", "yy", "zz", "xy", "yz", "xz"})
      names.push_back("sigma_" + c);
    names.push_back("von_mises");
    return names;
  }



  template <int dim>
  Tensor<2, 3>
  cauchy_stress_or_nan(const Materials::Material<dim> &material,
                       const Tensor<2, dim>           &F,
                       const ArrayView<const double>  &state)
  {
    try
      {
        return state.size() == 0 ? material.cauchy_stress(F) :
                                   material.cauchy_stress_with_state(F, state);
      }
    catch (...)
      {
        Tensor<2, 3> s;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            s[i][j] = std::numeric_limits<double>::quiet_NaN();
        return s;
      }
  }



  template <int dim>
  void
  stress_field_values(const Materials::Material<dim> &material,
                      const Tensor<2, dim>           &F,
                      std::vector<double>            &values,
                      const double                    pressure,
                      const ArrayView<const double>  &state)
  {
    values.clear();
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        values.push_back(F[i][j]);
    // Where F is inverted (J <= 0) the stress is undefined: written as NaN,
    // so ParaView shows the hole instead of a made-up value. This happens
    // for the Q1 interpolant of badly wrong PG solutions on meshfree cells.
    Tensor<2, 3> s = cauchy_stress_or_nan(material, F, state);
    for (unsigned int i = 0; i < 3; ++i)
      s[i][i] += pressure;
    for (const double v :
         {s[0][0], s[1][1], s[2][2], s[0][1], s[1][2], s[0][2]})
      values.push_back(v);
    values.push_back(std::isfinite(s[0][0]) ?
                       Materials::von_mises_stress(s) :
                       std::numeric_limits<double>::quiet_NaN());
  }



  template <int dim>
  StressPostprocessor<dim>::StressPostprocessor(
    const Materials::Material<dim>                            &material,
    const std::vector<bool>                                   &meshfree_cell,
    const std::function<const Tensor<2, dim> *(unsigned int)> &particle_F,
    const std::function<double(unsigned int)> &particle_pressure)
    : material(material)
    , meshfree_cell(meshfree_cell)
    , particle_F(particle_F)
    , particle_pressure(particle_pressure)
  {}



  template <int dim>
  StressPostprocessor<dim>::StressPostprocessor(
    const Materials::Material<dim> &material)
    : material(material)
  {}



  template <int dim>
  void
  StressPostprocessor<dim>::set_states(
    const Postprocess::CommittedStates     *new_states,
    const std::function<int(unsigned int)> &new_particle_at)
  {
    states      = new_states;
    particle_at = new_particle_at;
  }



  template <int dim>
  void
  StressPostprocessor<dim>::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<dim> &inputs,
    std::vector<Vector<double>>                &computed_quantities) const
  {
    // On a meshfree cell: the particle at the vertex nearest each point
    // (DataOut evaluates at the vertices when it does not subdivide).
    const auto cell = inputs.template get_cell<dim>();
    const bool from_particles =
      particle_F && meshfree_cell[cell->active_cell_index()] &&
      std::all_of(cell->vertex_indices().begin(),
                  cell->vertex_indices().end(),
                  [&](const unsigned int v) {
                    return particle_F(cell->vertex_index(v)) != nullptr;
                  });
    std::vector<double> values;
    for (unsigned int p = 0; p < inputs.solution_gradients.size(); ++p)
      {
        Tensor<2, dim> F;
        double         pressure = 0.;
        unsigned int   nearest  = 0;
        if (from_particles || states != nullptr)
          for (const unsigned int v : cell->vertex_indices())
            if (cell->vertex(v).distance(inputs.evaluation_points[p]) <
                cell->vertex(nearest).distance(inputs.evaluation_points[p]))
              nearest = v;
        ArrayView<const double> state;
        if (states != nullptr && states->n_material > 0)
          {
            if (from_particles)
              {
                const int k = particle_at(cell->vertex_index(nearest));
                if (k >= 0)
                  state = states->particle(k);
              }
            else if (!meshfree_cell.empty() &&
                     meshfree_cell[cell->active_cell_index()])
              ; // a meshfree cell without particles at its corners
            else
              state =
                states->cell(cell->active_cell_index(),
                             states->points_per_cell == cell->n_vertices() ?
                               nearest :
                               0);
          }
        if (from_particles)
          {
            F = *particle_F(cell->vertex_index(nearest));
            if (particle_pressure)
              pressure = particle_pressure(cell->vertex_index(nearest));
          }
        else
          for (unsigned int i = 0; i < dim; ++i)
            {
              F[i] = inputs.solution_gradients[p][i];
              F[i][i] += 1.;
            }
        stress_field_values(material, F, values, pressure, state);
        for (unsigned int c = 0; c < values.size(); ++c)
          computed_quantities[p][c] = values[c];
      }
  }



  template <int dim>
  std::vector<std::string>
  StressPostprocessor<dim>::get_names() const
  {
    return stress_field_names<dim>();
  }



  template <int dim>
  UpdateFlags
  StressPostprocessor<dim>::get_needed_update_flags() const
  {
    return update_gradients | update_quadrature_points;
  }



  template <int dim>
  ParticleOutput<dim>::ParticleOutput(const std::vector<std::string> &names)
    : names(names)
  {}



  template <int dim>
  void
  ParticleOutput<dim>::add_particle(const Point<dim>          &position,
                                    const std::vector<double> &data)
  {
    AssertDimension(data.size(), names.size());
    DataOutBase::Patch<0, dim> patch;
    patch.vertices[0] = position;
    patch.patch_index = patches.size();
    patch.data.reinit(names.size(), 1);
    for (unsigned int c = 0; c < data.size(); ++c)
      patch.data(c, 0) = data[c];
    patches.push_back(patch);
  }



  template <int dim>
  const std::vector<DataOutBase::Patch<0, dim>> &
  ParticleOutput<dim>::get_patches() const
  {
    return patches;
  }



  template <int dim>
  std::vector<std::string>
  ParticleOutput<dim>::get_dataset_names() const
  {
    return names;
  }



  template <int dim>
  std::vector<
    std::tuple<unsigned int,
               unsigned int,
               std::string,
               DataComponentInterpretation::DataComponentInterpretation>>
  ParticleOutput<dim>::get_nonscalar_data_ranges() const
  {
    std::vector<
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>>
      ranges;
    for (unsigned int c = 0; c + dim <= names.size();)
      {
        bool vector = true;
        for (unsigned int d = 1; d < dim; ++d)
          vector = vector && (names[c + d] == names[c]);
        if (vector)
          {
            ranges.emplace_back(
              c,
              c + dim - 1,
              names[c],
              DataComponentInterpretation::component_is_part_of_vector);
            c += dim;
          }
        else
          ++c;
      }
    return ranges;
  }



  namespace
  {
    std::string
    json_number(const double x)
    {
      if (!std::isfinite(x))
        return "null";
      std::ostringstream s;
      s << std::setprecision(17) << x;
      return s.str();
    }



    /** @p text as a JSON string: quoted, with '"', '\\' and controls escaped.
     */
    std::string
    json_string(const std::string &text)
    {
      std::ostringstream s;
      s << '"';
      for (const char c : text)
        if (c == '"' || c == '\\')
          s << '\\' << c;
        else if (static_cast<unsigned char>(c) < 0x20)
          s << "\\u" << std::hex << std::setw(4) << std::setfill('0')
            << static_cast<int>(c) << std::dec;
        else
          s << c;
      s << '"';
      return s.str();
    }



    std::string
    json_list(const std::vector<double> &values)
    {
      std::string s = "[";
      for (unsigned int i = 0; i < values.size(); ++i)
        s += (i > 0 ? ", " : "") + json_number(values[i]);
      return s + "]";
    }
  } // namespace



  void
  write_summary_json(const RunSummary &s, const std::string &filename)
  {
    std::ofstream out(filename);
    AssertThrow(out,
                ExcMessage("Cannot write <" + filename +
                           ">: check 'Directory' in subsection 'Output'."));
    out << "{\n"
        << "  \"dimension\": " << s.dimension << ",\n"
        << "  \"formulation\": \"" << s.formulation << "\",\n"
        << "  \"n_particles\": " << s.n_particles << ",\n"
        << "  \"n_fe_cells\": " << s.n_fe_cells << ",\n"
        << "  \"n_meshfree_cells\": " << s.n_meshfree_cells << ",\n"
        << "  \"n_families\": " << s.n_families << ",\n"
        << "  \"n_dofs\": " << s.n_dofs << ",\n"
        << "  \"matrix_nonzeros\": " << s.matrix_nonzeros << ",\n"
        << "  \"amg_operator_nonzeros\": " << s.amg_operator_nonzeros << ",\n"
        << "  \"converged\": " << (s.converged ? "true" : "false") << ",\n"
        << "  \"status\": \""
        << (s.interrupted           ? "interrupted" :
            !s.stop_message.empty() ? "failed" :
            s.finished              ? "finished" :
                                      "running")
        << "\",\n"
        << "  \"message\": " << json_string(s.stop_message) << ",\n"
        << "  \"load_steps\": " << s.load_steps << ",\n"
        << "  \"newton_iterations\": " << s.newton_iterations << ",\n"
        << "  \"newton_residuals_last_step\": "
        << json_list(s.newton_residuals_last_step) << ",\n"
        << "  \"gradient_oscillation\": " << json_number(s.gradient_oscillation)
        << ",\n"
        << "  \"max_interior_unit_stress_residual\": "
        << json_number(s.max_interior_unit_stress_residual) << ",\n"
        << "  \"max_interface_stress_jump\": "
        << json_number(s.max_interface_stress_jump) << ",\n"
        << "  \"max_interior_second_order_residual\": "
        << json_number(s.max_interior_second_order_residual) << ",\n"
        << "  \"condensed_pressure_range\": "
        << json_list(s.condensed_pressure_range) << ",\n";
    for (const auto &[name, value] : s.state_output_maxima)
      out << "  \"max_" << name << "\": " << json_number(value) << ",\n";
    const auto json_named_lists =
      [&out](
        const std::string                                              &key,
        const std::vector<std::pair<std::string, std::vector<double>>> &v) {
        out << "  \"" << key << "\": {";
        for (unsigned int i = 0; i < v.size(); ++i)
          out << (i > 0 ? ", " : "") << "\"" << v[i].first
              << "\": " << json_list(v[i].second);
        out << "},\n";
      };
    json_named_lists("points", s.points);
    json_named_lists("point_stresses", s.point_stresses);
    if (!s.point_exact_stresses.empty())
      json_named_lists("point_exact_stresses", s.point_exact_stresses);
    out << "  \"reactions\": {";
    bool first = true;
    for (const auto &r : s.reactions)
      {
        out << (first ? "" : ", ") << "\"" << static_cast<int>(r.first)
            << "\": " << json_list(r.second);
        first = false;
      }
    out << "},\n";
    if (!s.neumann_resultants.empty())
      {
        out << "  \"neumann_resultants\": {";
        for (unsigned int i = 0; i < s.neumann_resultants.size(); ++i)
          {
            const auto &r = s.neumann_resultants[i];
            out << (i > 0 ? ", " : "") << "\"" << static_cast<int>(r.id)
                << "\": {\"area\": " << json_number(r.area)
                << ", \"centre\": " << json_list(r.centre)
                << ", \"force\": " << json_list(r.force)
                << ", \"exact_force\": " << json_list(r.exact_force)
                << ", \"eq_4_32_force\": " << json_list(r.point_force)
                << ", \"moment\": " << json_list(r.moment)
                << ", \"exact_moment\": " << json_list(r.exact_moment)
                << ", \"n_partly_loaded\": " << r.n_partly_loaded << "}";
          }
        out << "},\n";
      }
    if (!s.box_reactions.empty())
      {
        out << "  \"box_reactions\": [";
        for (unsigned int b = 0; b < s.box_reactions.size(); ++b)
          out << (b > 0 ? ", " : "") << json_list(s.box_reactions[b]);
        out << "],\n";
      }
    if (!s.dynamics.integrator.empty())
      {
        const auto &d    = s.dynamics;
        const auto  last = [](const std::vector<double> &v) {
          return v.empty() ? std::numeric_limits<double>::quiet_NaN() :
                              v.back();
        };
        out << "  \"dynamics\": {\"integrator\": \"" << d.integrator
            << "\", \"time_step\": " << json_number(d.time_step)
            << ", \"stable_time_step\": " << json_number(d.stable_time_step)
            << ", \"smallest_time_step\": " << json_number(d.smallest_time_step)
            << ", \"largest_time_step\": " << json_number(d.largest_time_step)
            << ", \"n_steps\": " << d.n_steps
            << ", \"step_cuts\": " << d.step_cuts
            << ", \"final_time\": " << json_number(d.final_time)
            << ", \"kinetic_energy\": " << json_number(last(d.kinetic))
            << ", \"internal_work\": " << json_number(last(d.internal_work))
            << ", \"external_work\": " << json_number(last(d.external_work))
            << ", \"support_work\": " << json_number(last(d.support_work))
            << ", \"energy_balance\": " << json_number(last(d.balance));
        if (!d.plastic_work.empty())
          out << ", \"plastic_work\": " << json_number(d.plastic_work.back());
        out << "},\n";
      }
    if (!s.wall_reaction.empty())
      out << "  \"wall_reaction\": " << json_list(s.wall_reaction)
          << ",\n  \"wall_active_nodes\": " << s.wall_active_nodes
          << ",\n  \"wall_min_gap\": " << json_number(s.wall_min_gap) << ",\n";
    if (!s.node_set_reactions.empty())
      {
        out << "  \"node_set_reactions\": {";
        bool first = true;
        for (const auto &[name, r] : s.node_set_reactions)
          {
            out << (first ? "" : ", ") << "\"" << name
                << "\": " << json_list(r);
            first = false;
          }
        out << "},\n";
      }
    if (!s.eigenvalues.empty())
      out << "  \"max_eigenvalue\": " << json_number(s.max_eigenvalue)
          << ",\n  \"n_zero_eigenvalues\": " << s.n_zero_eigenvalues
          << ",\n  \"eigenvalues\": " << json_list(s.eigenvalues) << ",\n";
    if (!s.inf_sup.N.empty())
      {
        const auto &i = s.inf_sup;
        out << "  \"inf_sup\": {\"pressure_space\": \"" << i.pressure_space
            << "\", \"zero_tolerance\": " << json_number(i.zero_tolerance);
        for (const auto &[name, values] :
             std::vector<std::pair<std::string, const std::vector<double> *>>{
               {"N", &i.N},
               {"n_dofs", &i.n_dofs},
               {"n_free", &i.n_free},
               {"n_pressure", &i.n_pressure},
               {"n_zero", &i.n_zero},
               {"k_pm", &i.k_pm},
               {"beta", &i.beta},
               {"slope", &i.slope},
               {"lambda_max", &i.lambda_max},
               {"largest_zero", &i.largest_zero}})
          out << ",\n    \"" << name << "\": " << json_list(*values);
        out << "},\n";
      }
    if (s.have_errors)
      out << "  \"errors\": {\"L2\": " << json_number(s.L2)
          << ", \"H1\": " << json_number(s.H1)
          << ", \"L2_relative\": " << json_number(s.L2_relative)
          << ", \"H1_relative\": " << json_number(s.H1_relative)
          << ", \"energy\": " << json_number(s.energy)
          << ", \"energy_relative\": " << json_number(s.energy_relative)
          << "},\n";
    if (!s.vc_solver.empty())
      out << "  \"vc_solve\": {\"solver\": \"" << s.vc_solver
          << "\", \"iterations\": " << s.vc_iterations << "},\n";
    const auto &c = s.assembly_cost;
    out << "  \"assembly_cost\": {\"n_assemblies\": " << c.n_assemblies
        << ", \"n_solves\": " << c.n_solves
        << ", \"linear_iterations\": " << c.linear_iterations
        << ", \"amg_builds\": " << c.amg_builds
        << ", \"amg_operator_rejected\": "
        << (c.amg_operator_rejected ? "true" : "false")
        << ", \"fe_seconds\": " << json_number(c.fe_seconds)
        << ", \"family_seconds\": " << json_number(c.family_seconds)
        << ", \"fe_entries\": " << json_number(c.fe_entries)
        << ", \"family_entries\": " << json_number(c.family_entries)
        << ", \"fe_flops\": " << json_number(c.fe_flops)
        << ", \"family_flops\": " << json_number(c.family_flops) << "},\n";
    out << "  \"timing\": {";
    first = true;
    for (const auto &t : s.timing)
      {
        out << (first ? "" : ", ") << "\"" << t.first
            << "\": " << json_number(t.second);
        first = false;
      }
    out << "}\n}\n";
  }



  template std::vector<std::string>
  stress_field_names<2>();
  template std::vector<std::string>
  stress_field_names<3>();
  template void
  stress_field_values<2>(const Materials::Material<2> &,
                         const Tensor<2, 2> &,
                         std::vector<double> &,
                         const double,
                         const ArrayView<const double> &);
  template void
  stress_field_values<3>(const Materials::Material<3> &,
                         const Tensor<2, 3> &,
                         std::vector<double> &,
                         const double,
                         const ArrayView<const double> &);
  template Tensor<2, 3>
  cauchy_stress_or_nan<2>(const Materials::Material<2> &,
                          const Tensor<2, 2> &,
                          const ArrayView<const double> &);
  template Tensor<2, 3>
  cauchy_stress_or_nan<3>(const Materials::Material<3> &,
                          const Tensor<2, 3> &,
                          const ArrayView<const double> &);
  template class StressPostprocessor<2>;
  template class StressPostprocessor<3>;
  template class ParticleOutput<2>;
  template class ParticleOutput<3>;
} // namespace pg
