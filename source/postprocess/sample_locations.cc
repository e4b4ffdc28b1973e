#include <pg/base/exceptions.h>
#include <pg/mesh/linear_cells.h>
#include <pg/postprocess/sample_locations.h>

#include <deal.II/grid/grid_tools.h>

namespace pg
{
  namespace Postprocess
  {
    namespace
    {
      /**
       * The active cell around @p p and the reference coordinates of @p p
       * in it, or an invalid iterator if @p p lies outside the mesh.
       * deal.II 9.4's GridTools::find_active_cell_around_point() tests the
       * reference point against the unit square (cube) also for triangles
       * and tetrahedra, so on a simplex mesh it can return a cell that does
       * not contain @p p (most often for a point on an edge or face; the
       * value there is then extrapolated from the wrong cell; deal.II
       * issue 14704, fixed in 9.5.2 by a brute-force search). On simplex
       * meshes its answer is therefore checked with the reference cell,
       * and if it fails every cell is tried (P1 cells map affinely, so the
       * reference point is exact).
       */
      template <int dim>
      std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>>
      find_cell(const Mapping<dim>    &mapping,
                const DoFHandler<dim> &dof_handler,
                const Point<dim>      &p,
                const bool             simplex)
      {
        const double tolerance = 1e-10;
        std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>>
          found;
        try
          {
            found =
              GridTools::find_active_cell_around_point(mapping, dof_handler, p);
            if (found.first.state() == IteratorState::valid &&
                (!simplex ||
                 found.first->reference_cell().contains_point(found.second,
                                                              tolerance)))
              return found;
          }
        catch (...)
          {
            // outside the mesh, or (on simplices) not found
          }
        found.first = typename DoFHandler<dim>::active_cell_iterator();
        if (simplex)
          for (const auto &cell : dof_handler.active_cell_iterators())
            {
              Point<dim> unit;
              try
                {
                  unit = mapping.transform_real_to_unit_cell(cell, p);
                }
              catch (...)
                {
                  continue;
                }
              if (cell->reference_cell().contains_point(unit, tolerance))
                return {cell, unit};
            }
        return found;
      }
    } // namespace



    template <int dim>
    std::vector<
      std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>>>
    locate_points(
      const DoFHandler<dim> &dof_handler,
      const std::vector<std::pair<std::string, std::vector<double>>> &points)
    {
      const LinearCells<dim> cells(dof_handler.get_triangulation());
      const Mapping<dim>    &mapping = cells.mapping();
      std::vector<
        std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>>>
        locations;
      for (const auto &[name, coordinates] : points)
        {
          Point<dim> p;
          for (unsigned int d = 0; d < dim; ++d)
            p[d] = coordinates[d];
          const auto found =
            find_cell(mapping, dof_handler, p, cells.is_simplex());
          AssertThrow(found.first.state() == IteratorState::valid,
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
      const LinearCells<dim> cells(dof_handler.get_triangulation());
      const Mapping<dim>    &mapping = cells.mapping();
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
              // outside the mesh: no sample
              const auto found =
                find_cell(mapping, dof_handler, p, cells.is_simplex());
              if (found.first.state() == IteratorState::valid)
                locations.push_back(
                  {l, p.distance(start), p, found.first, found.second});
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
