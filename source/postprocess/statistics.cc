#include <pg/postprocess/postprocessors.h>
#include <pg/postprocess/run_summary.h>

namespace pg
{
  namespace Postprocess
  {
    template <int dim>
    void
    Statistics<dim>::execute(const ProblemView<dim> &view,
                             const Step             &step,
                             TableHandler           &statistics,
                             RunSummary             &summary)
    {
      const bool dynamic = view.parameters->time.dynamic();
      statistics.add_value("step", step.number);
      statistics.add_value(dynamic ? "time" : "load factor", step.time);
      statistics.add_value("Newton iterations", step.newton_iterations);
      statistics.add_value("residual",
                           summary.newton_residuals_last_step.empty() ?
                             0. :
                             summary.newton_residuals_last_step.back());
      if (dynamic)
        view.add_dynamic_statistics(step.time);
      for (const auto &[name, value] : summary.points)
        for (unsigned int c = 0; c < dim; ++c)
          statistics.add_value(name + "_u" + std::string(1, "xyz"[c]),
                               value[c]);
      // The reaction of each Dirichlet boundary id (computed by Reactions,
      // which runs before) and the largest value of each state output of a
      // material with history (J2 plasticity: the equivalent plastic
      // strain), per step: force-displacement curves and the growth of the
      // plastic strain (benchmark B-13)
      for (const auto &[id, reaction] : summary.reactions)
        for (unsigned int c = 0; c < reaction.size(); ++c)
          {
            const std::string name =
              "reaction_" + std::to_string(id) + "_" + std::string(1, "xyz"[c]);
            statistics.add_value(name, reaction[c]);
            statistics.set_scientific(name, true);
            statistics.set_precision(name, 8);
          }
      const std::vector<std::string> state_names =
        view.material->state_output_names();
      if (!state_names.empty())
        {
          const std::vector<double> maxima = view.maximum_state_outputs();
          for (unsigned int i = 0; i < state_names.size(); ++i)
            {
              statistics.add_value("max_" + state_names[i], maxima[i]);
              statistics.set_scientific("max_" + state_names[i], true);
              statistics.set_precision("max_" + state_names[i], 8);
            }
        }
      if (summary.have_errors)
        {
          statistics.add_value("L2 error", summary.L2);
          statistics.add_value("H1 error", summary.H1);
        }
      statistics.add_value("wall time", view.total_timer->wall_time());
      statistics.set_scientific("residual", true);
    }



    template <int dim>
    void
    Statistics<dim>::finalize(const ProblemView<dim> &view,
                              const Step &,
                              TableHandler &,
                              RunSummary &summary)
    {
      *view.pcout << "  total Newton iterations: " << summary.newton_iterations
                  << std::endl;
      const auto &cost = summary.assembly_cost;
      if (cost.amg_builds > 0)
        *view.pcout << "  linear solves: " << cost.n_solves << " with "
                    << cost.linear_iterations << " Krylov iterations and "
                    << cost.amg_builds << " ML hierarchies"
                    << (cost.amg_operator_rejected ?
                          " (AMG operator: the tangent's hierarchy, faster "
                          "than the Q1 cells' in a trial solve)" :
                          "")
                    << std::endl;
    }



    template class Statistics<2>;
    template class Statistics<3>;
  } // namespace Postprocess
} // namespace pg
