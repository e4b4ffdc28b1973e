#ifndef pg_postprocess_sample_locations_h
#define pg_postprocess_sample_locations_h

#include <pg/base/global.h>
#include <pg/postprocess/output_parameters.h>
#include <pg/postprocess/problem_view.h>

#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>

#include <string>
#include <utility>
#include <vector>

namespace pg
{
  namespace Postprocess
  {
    /**
     * The cell and reference coordinates of each of @p points ('Output/
     * Points': name and dim coordinates), in their order, for PointValues.
     * Every rank knows all cells (shared triangulation), so each rank finds
     * every point. Throws ExcBadParameter naming the point if it lies
     * outside the mesh.
     */
    template <int dim>
    std::vector<
      std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>>>
    locate_points(
      const DoFHandler<dim> &dof_handler,
      const std::vector<std::pair<std::string, std::vector<double>>> &points);

    /**
     * The samples of @p lines ('Output/Lines') for LineSamples: @p n_samples
     * equidistant points per line, both ends included, with their arc
     * length from the start; samples outside the mesh (in a hole) are left
     * out.
     */
    template <int dim>
    std::vector<LineSampleLocation<dim>>
    locate_line_samples(const DoFHandler<dim> &dof_handler,
                        const std::vector<Parameters::Output::Line> &lines,
                        const unsigned int                           n_samples);
  } // namespace Postprocess
} // namespace pg

#endif
