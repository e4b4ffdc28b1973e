#include <pg/base/exceptions.h>
#include <pg/mesh/meshfree_region.h>

#include <deal.II/base/numbers.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace pg
{
  namespace Mesh
  {
    namespace
    {
      /**
       * The whole of @p text as one number. Utilities::string_to_double()
       * accepts trailing garbage such as '1x', which should be an error here.
       */
      bool
      read_number(const std::string &text, double &value)
      {
        std::istringstream s(text);
        s >> value;
        if (s.fail())
          return false;
        s >> std::ws;
        return s.eof();
      }



      /** Whether @p text starts with @p word; @p rest gets the remainder. */
      bool
      starts_with(const std::string &text,
                  const std::string &word,
                  std::string       &rest)
      {
        if (text.compare(0, word.size(), word) != 0)
          return false;
        rest = text.substr(word.size());
        return true;
      }
    } // namespace



    template <int dim>
    MeshfreeRegion<dim>
    MeshfreeRegion<dim>::parse(const std::string &text,
                               const std::string &entry)
    {
      const ExcBadParameter bad_region(
        entry,
        text,
        "it must read 'all', 'none', 'material ids 1,2', 'box x0,y0 : "
        "x1,y1' or 'ball cx,cy : r' with " +
          std::to_string(dim) + " coordinates per point.");

      // dim comma-separated numbers
      const auto read_point = [&](const std::string &words) {
        const std::vector<std::string> coordinates =
          Utilities::split_string_list(words, ',');
        AssertThrow(coordinates.size() == dim, bad_region);
        Point<dim> point;
        for (unsigned int d = 0; d < dim; ++d)
          AssertThrow(read_number(coordinates[d], point[d]), bad_region);
        return point;
      };

      MeshfreeRegion<dim> region;
      const std::string   trimmed = Utilities::trim(text);
      std::string         rest;
      if (trimmed == "all")
        region.kind = Kind::all;
      else if (trimmed == "none")
        region.kind = Kind::none;
      else if (starts_with(trimmed, "material ids", rest))
        {
          region.kind = Kind::material_ids;
          for (const std::string &word :
               Utilities::split_string_list(rest, ','))
            {
              double id;
              AssertThrow(read_number(word, id) && id >= 0. &&
                            id < numbers::invalid_material_id &&
                            id == std::floor(id),
                          bad_region);
              region.material_ids.push_back(
                static_cast<types::material_id>(id));
            }
          AssertThrow(!region.material_ids.empty(), bad_region);
        }
      else if (starts_with(trimmed, "box", rest))
        {
          region.kind = Kind::box;
          const std::vector<std::string> corners =
            Utilities::split_string_list(rest, ':');
          AssertThrow(corners.size() == 2, bad_region);
          const Point<dim> a = read_point(corners[0]);
          const Point<dim> b = read_point(corners[1]);
          for (unsigned int d = 0; d < dim; ++d)
            {
              region.lower[d] = std::min(a[d], b[d]);
              region.upper[d] = std::max(a[d], b[d]);
            }
        }
      else if (starts_with(trimmed, "ball", rest))
        {
          region.kind = Kind::ball;
          const std::vector<std::string> parts =
            Utilities::split_string_list(rest, ':');
          AssertThrow(parts.size() == 2, bad_region);
          region.centre = read_point(parts[0]);
          AssertThrow(read_number(parts[1], region.radius) &&
                        region.radius >= 0.,
                      bad_region);
        }
      else
        AssertThrow(false, bad_region);

      return region;
    }



    template <int dim>
    bool
    MeshfreeRegion<dim>::contains(
      const typename Triangulation<dim>::active_cell_iterator &cell) const
    {
      switch (kind)
        {
          case Kind::all:
            return true;
          case Kind::none:
            return false;
          case Kind::material_ids:
            return std::find(material_ids.begin(),
                             material_ids.end(),
                             cell->material_id()) != material_ids.end();
          case Kind::box:
          case Kind::ball:
            return contains_point(cell->center());
        }
      return false;
    }



    template <int dim>
    bool
    MeshfreeRegion<dim>::contains_point(const Point<dim> &p) const
    {
      if (kind == Kind::ball)
        return p.distance(centre) <= radius * (1. + 1e-10);
      const double tolerance = 1e-10 * lower.distance(upper);
      for (unsigned int d = 0; d < dim; ++d)
        if (p[d] < lower[d] - tolerance || p[d] > upper[d] + tolerance)
          return false;
      return true;
    }



    template struct MeshfreeRegion<2>;
    template struct MeshfreeRegion<3>;
  } // namespace Mesh
} // namespace pg
