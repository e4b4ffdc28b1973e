#include <pg/postprocess/postprocessors.h>
#include <pg/postprocess/run_summary.h>

namespace pg
{
  namespace Postprocess
  {
    template <int dim>
    void
    PointValues<dim>::execute(const ProblemView<dim> &view,
                              const Step &,
                              TableHandler &,
                              RunSummary &summary)
    {
      // Point values from the Q1 interpolant (the nodal values at vertices).
      const auto &locations = *view.point_locations;
      summary.points.clear();
      // the points lie in any cell: from the gathered displacement (the
      // same points on every rank)
      const Vector<double> u_all =
        locations.empty() ? Vector<double>() : view.gather_displacement();
      for (unsigned int i = 0; i < locations.size(); ++i)
        summary.points.emplace_back(view.parameters->output.points[i].first,
                                    view.displacement_at(locations[i].first,
                                                         locations[i].second,
                                                         u_all));
    }



    template <int dim>
    void
    PointValues<dim>::finalize(const ProblemView<dim> &view,
                               const Step &,
                               TableHandler &,
                               RunSummary &summary)
    {
      const ConditionalOStream &pcout = *view.pcout;
      for (const auto &[name, value] : summary.points)
        {
          pcout << "  point " << name << ": u =";
          for (const double v : value)
            pcout << " " << v;
          pcout << std::endl;
        }
    }



    template class PointValues<2>;
    template class PointValues<3>;
  } // namespace Postprocess
} // namespace pg
