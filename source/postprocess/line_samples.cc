#include <pg/postprocess/postprocessors.h>
#include <pg/postprocess/run_summary.h>

#include <fstream>
#include <iomanip>

namespace pg
{
  namespace Postprocess
  {
    template <int dim>
    void
    LineSamples<dim>::execute(const ProblemView<dim> &view,
                              const Step             &step,
                              TableHandler &,
                              RunSummary &summary)
    {
      const auto &prm       = *view.parameters;
      const auto &locations = *view.line_locations;
      summary.line_samples.clear();
      // the samples lie in any cell: from the gathered displacement (the
      // same locations on every rank)
      const Vector<double> u_all =
        locations.empty() ? Vector<double>() : view.gather_displacement();
      for (const auto &sample : locations)
        summary.line_samples.push_back(
          {prm.output.lines[sample.line].name,
           sample.arc_length,
           std::vector<double>(sample.position.begin_raw(),
                               sample.position.end_raw()),
           view.displacement_at(sample.cell, sample.reference, u_all)});
      if (view.root && !locations.empty())
        {
          std::ofstream table(prm.output.directory +
                              "/displacement_along_lines.txt");
          table << "# displacement along 'Output/Lines' at "
                << (prm.time.dynamic() ? "time " : "load factor ") << step.time
                << "\n# line s x y" << (dim == 3 ? " z" : "") << " u_x u_y"
                << (dim == 3 ? " u_z" : "") << "\n"
                << std::setprecision(10);
          for (const auto &sample : summary.line_samples)
            {
              table << sample.line << " " << sample.arc_length;
              for (const double x : sample.position)
                table << " " << x;
              for (const double u : sample.displacement)
                table << " " << u;
              table << "\n";
            }
        }
    }



    template class LineSamples<2>;
    template class LineSamples<3>;
  } // namespace Postprocess
} // namespace pg
