#include <pg/base/exceptions.h>
#include <pg/mesh/linear_cells.h>
#include <pg/postprocess/sample_locations.h>

#include <deal.II/grid/grid_tools.h>

namespace pg
{
  namespace Postprocess
  {
    template <int dim>
    std::vector<
      std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>>>
    locate_points(
      const DoFHandler<dim> &dof_handler,
      const std::vector<std::pair<std::string, std::vector<double>>> &points)
    {
      const Mapping<dim> &mapping =
        LinearCells<dim>(dof_handler.get_triangulation()).mapping();
      std::vector<
        std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>>>
        locations;
      for (const auto &[name, coordinates] : points)
        {
          Point<dim> p;
          for (unsigned int d = 0; d < dim; ++d)
            p[d] = coordinates[d];
          std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>>
               found;
          bool inside = true;
          try
            {
              found  = GridTools::find_active_cell_around_point(mapping,
                                                               dof_handler,
                                                               p);
              inside = (found.first.state() == IteratorState::valid);
            }
          catch (...)
            {
              inside = false;
            }
          AssertThrow(inside,
                      ExcBadParameter("Output/Points",
                                      name,
                                      "this point lies outside the mesh."));
          locations.push_back(found);
        }
      return locations;
    }



    template <int dim>
    std::vector<LineSampleLocation<dim>>
    locate_line_samples(const DoFHandler<dim> &dof_handler,
                        const std::vector<Parameters::Output::Line> &lines,
                        const unsigned int                           n_samples)
    {
      const Mapping<dim> &mapping =
        LinearCells<dim>(dof_handler.get_triangulation()).mapping();
      std::vector<LineSampleLocation<dim>> locations;
      for (unsigned int l = 0; l < lines.size(); ++l)
        {
          Point<dim> start, end;
          for (unsigned int d = 0; d < dim; ++d)
            {
              start[d] = lines[l].start[d];
              end[d]   = lines[l].end[d];
            }
          for (unsigned int i = 0; i < n_samples; ++i)
            {
              const Point<dim> p =
                start + (end - start) * (1. * i / (n_samples - 1));
              try
                {
                  const auto found =
                    GridTools::find_active_cell_around_point(mapping,
                                                             dof_handler,
                                                             p);
                  if (found.first.state() == IteratorState::valid)
                    locations.push_back(
                      {l, p.distance(start), p, found.first, found.second});
                }
              catch (...)
                {
                  // outside the mesh: no sample
                }
            }
        }
      return locations;
    }



    template std::vector<
      std::pair<typename DoFHandler<2>::active_cell_iterator, Point<2>>>
    locate_points(
      const DoFHandler<2> &,
      const std::vector<std::pair<std::string, std::vector<double>>> &);
    template std::vector<
      std::pair<typename DoFHandler<3>::active_cell_iterator, Point<3>>>
    locate_points(
      const DoFHandler<3> &,
      const std::vector<std::pair<std::string, std::vector<double>>> &);
    template std::vector<LineSampleLocation<2>>
    locate_line_samples(const DoFHandler<2> &,
                        const std::vector<Parameters::Output::Line> &,
                        const unsigned int);
    template std::vector<LineSampleLocation<3>>
    locate_line_samples(const DoFHandler<3> &,
                        const std::vector<Parameters::Output::Line> &,
                        const unsigned int);
  } // namespace Postprocess
} // namespace pg
