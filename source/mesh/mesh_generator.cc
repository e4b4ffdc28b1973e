#include <pg/base/exceptions.h>
#include <pg/mesh/mesh_generator.h>

#include <deal.II/base/numbers.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_description.h>
#include <deal.II/grid/tria_iterator.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace pg
{
  namespace Mesh
  {
    namespace
    {
      /** "a, b, c" from a list of values, to quote a value in a message. */
      template <typename Number>
      std::string
      join(const std::vector<Number> &values)
      {
        std::ostringstream s;
        for (unsigned int i = 0; i < values.size(); ++i)
          s << (i > 0 ? ", " : "") << values[i];
        return s.str();
      }



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



      /** A point from the dim values of the entry @p entry. */
      template <int dim>
      Point<dim>
      to_point(const std::vector<double> &values, const std::string &entry)
      {
        AssertThrow(values.size() == dim,
                    ExcBadParameter(entry,
                                    join(values),
                                    "it must have " + std::to_string(dim) +
                                      " comma-separated coordinates, one "
                                      "per space dimension."));
        Point<dim> point;
        for (unsigned int d = 0; d < dim; ++d)
          point[d] = values[d];
        return point;
      }



      /** 'Subdivisions' as dim values: one value counts for every direction. */
      template <int dim>
      std::vector<unsigned int>
      subdivisions_per_direction(const Parameters::Geometry &parameters)
      {
        const std::vector<unsigned int> &values = parameters.subdivisions;
        AssertThrow(values.size() == 1 || values.size() == dim,
                    ExcBadParameter("Geometry/Subdivisions",
                                    join(values),
                                    "it must have one value (used in every "
                                    "direction) or " +
                                      std::to_string(dim) +
                                      " values, one per space dimension."));
        return values.size() == 1 ? std::vector<unsigned int>(dim, values[0]) :
                                    values;
      }



      template <int dim>
      void
      create_hyper_rectangle(const Parameters::Geometry &parameters,
                             Triangulation<dim>         &triangulation)
      {
        const Point<dim> lower =
          to_point<dim>(parameters.lower_corner, "Geometry/Lower corner");
        const Point<dim> upper =
          to_point<dim>(parameters.upper_corner, "Geometry/Upper corner");
        for (unsigned int d = 0; d < dim; ++d)
          AssertThrow(lower[d] != upper[d],
                      ExcBadParameter("Geometry/Upper corner",
                                      join(parameters.upper_corner),
                                      "it must differ from 'Lower corner' in "
                                      "every coordinate, else the box is "
                                      "flat."));

        GridGenerator::subdivided_hyper_rectangle(
          triangulation,
          subdivisions_per_direction<dim>(parameters),
          lower,
          upper,
          /*colorize=*/true);
      }



      /**
       * Cook's membrane: the colorized rectangle [0,48]x[0,44] mapped so that
       * the bottom edge runs from (0,0) to (48,44) and the top edge from
       * (0,44) to (48,60). The map is bilinear, so the straight-sided cells
       * are mapped exactly and later refinement needs no manifold.
       */
      void
      create_cook_membrane(const Parameters::Geometry &parameters,
                           Triangulation<2>           &triangulation)
      {
        GridGenerator::subdivided_hyper_rectangle(triangulation,
                                                  subdivisions_per_direction<2>(
                                                    parameters),
                                                  Point<2>(0., 0.),
                                                  Point<2>(48., 44.),
                                                  /*colorize=*/true);

        GridTools::transform(
          [](const Point<2> &p) {
            const double y_bottom = 44. * p[0] / 48.;
            const double y_top    = 44. + 16. * p[0] / 48.;
            return Point<2>(p[0], y_bottom + (y_top - y_bottom) * p[1] / 44.);
          },
          triangulation);
      }



      /**
       * The quarter plate [0,L]^2 minus the disk of radius R at the origin.
       * Two halves, split at the 45-degree diagonal, each cut into layers
       * along the rays at 0, 45 and 90 degrees. The inner layers are bounded
       * by chords of circles (isosceles trapezoids, angles 67.5 and 112.5
       * degrees) whose radii grow geometrically, so that the radial size of
       * a cell stays close to its tangential size (about 0.77 r); the outer
       * layer makes the transition to the straight edges. No angle exceeds
       * 112.5 degrees, so the cells tolerate a random 'Distortion'.
       * The hole gets a PolarManifold, the cells a transfinite interpolation
       * of their boundary, so refinement puts new hole vertices on the circle
       * and interior vertices where they belong.
       */
      void
      create_plate_with_hole(const Parameters::Geometry &parameters,
                             Triangulation<2>           &triangulation)
      {
        const double L = parameters.plate_size;
        const double R = parameters.hole_radius;
        AssertThrow(R > 0. && R < L,
                    ExcBadParameter("Geometry/Hole radius",
                                    join(std::vector<double>{R}),
                                    "it must be positive and smaller than "
                                    "'Plate size' in subsection 'Geometry'."));

        const unsigned int n_layers =
          std::max(1,
                   static_cast<int>(std::ceil(
                     std::log(L / R) / std::log(1. + numbers::PI / 4.))));

        // The unit directions of the rays and their ends on the outer edges,
        // written out rather than computed from angles so that the vertices
        // on the symmetry lines x = 0 and y = 0 lie exactly on them.
        const double                s         = std::sqrt(0.5);
        const std::vector<Point<2>> direction = {Point<2>(1., 0.),
                                                 Point<2>(s, s),
                                                 Point<2>(0., 1.)};
        const std::vector<Point<2>> outer     = {Point<2>(L, 0.),
                                                 Point<2>(L, L),
                                                 Point<2>(0., L)};

        std::vector<Point<2>> vertices;
        for (unsigned int ray = 0; ray < 3; ++ray)
          {
            for (unsigned int k = 0; k < n_layers; ++k)
              vertices.push_back(R * std::pow(L / R, 1. * k / n_layers) *
                                 direction[ray]);
            vertices.push_back(outer[ray]);
          }

        // Local x runs outward along the ray, local y counter-clockwise to
        // the next ray: this orientation has a positive Jacobian.
        std::vector<CellData<2>> cells;
        for (unsigned int half = 0; half < 2; ++half)
          for (unsigned int k = 0; k < n_layers; ++k)
            {
              CellData<2> cell;
              cell.vertices    = {half * (n_layers + 1) + k,
                                  half * (n_layers + 1) + k + 1,
                                  (half + 1) * (n_layers + 1) + k,
                                  (half + 1) * (n_layers + 1) + k + 1};
              cell.material_id = 0;
              cells.push_back(cell);
            }
        triangulation.create_triangulation(vertices, cells, SubCellData());

        // Boundary ids from the face centres; every boundary face that is not
        // on a straight edge is on the hole.
        const types::manifold_id polar_manifold_id = 0;
        const types::manifold_id tfi_manifold_id   = 1;
        triangulation.set_all_manifold_ids(tfi_manifold_id);
        const double tolerance = 1e-10 * L;
        for (const auto &cell : triangulation.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              {
                const Point<2>     c = face->center();
                types::boundary_id id;
                if (std::abs(c[0]) < tolerance)
                  id = 1;
                else if (std::abs(c[1]) < tolerance)
                  id = 2;
                else if (std::abs(c[0] - L) < tolerance)
                  id = 3;
                else if (std::abs(c[1] - L) < tolerance)
                  id = 4;
                else
                  id = 0;
                face->set_boundary_id(id);
                face->set_manifold_id(id == 0 ? polar_manifold_id :
                                                numbers::flat_manifold_id);
              }

        triangulation.set_manifold(polar_manifold_id,
                                   PolarManifold<2>(Point<2>()));
        TransfiniteInterpolationManifold<2> tfi_manifold;
        tfi_manifold.initialize(triangulation);
        triangulation.set_manifold(tfi_manifold_id, tfi_manifold);
      }



      /** The message for a mesh file that GridIn cannot read. */
      std::string
      unreadable_file_message(const std::string &file_name,
                              const std::string &reason)
      {
        return "The mesh file " + file_name +
               " given as 'File name' in subsection 'Geometry' cannot be "
               "read: " +
               reason +
               ". Check the path (relative paths start in the working "
               "directory).";
      }



      /** "(x, y, z)" for messages. */
      template <int dim>
      std::string
      format_point(const Point<dim> &p)
      {
        std::ostringstream s;
        s << std::setprecision(8) << "(";
        for (unsigned int d = 0; d < dim; ++d)
          s << (d ? ", " : "") << p[d];
        s << ")";
        return s.str();
      }



      /**
       * Distinct vertices of the file's mesh at the same position (within
       * 1e-10 x the bounding-box diagonal in every coordinate) disconnect
       * the cells there: Q1 elements on either side do not share DoFs (a
       * singular system) and the particles coincide (NaN in the shape
       * functions). 'Coincident vertices = merge' rebuilds the coarse mesh
       * with one vertex per position; 'reject' stops naming the positions.
       * Faces that the merge makes interior lose their boundary data.
       */
      template <int dim>
      void
      handle_coincident_vertices(const Parameters::Geometry &parameters,
                                 Triangulation<dim>         &triangulation,
                                 std::string                *notes)
      {
        auto [vertices, cells, subcelldata] =
          GridTools::get_coarse_mesh_description(triangulation);
        const unsigned int n_vertices = vertices.size();
        if (n_vertices == 0)
          return;
        Point<dim> lower = vertices[0], upper = vertices[0];
        for (const Point<dim> &p : vertices)
          for (unsigned int d = 0; d < dim; ++d)
            {
              lower[d] = std::min(lower[d], p[d]);
              upper[d] = std::max(upper[d], p[d]);
            }
        const double tolerance = 1e-10 * lower.distance(upper);

        // Pairs within the tolerance, by a sweep over x.
        std::vector<unsigned int> order(n_vertices);
        for (unsigned int i = 0; i < n_vertices; ++i)
          order[i] = i;
        std::sort(order.begin(),
                  order.end(),
                  [&](const unsigned int a, const unsigned int b) {
                    return vertices[a][0] < vertices[b][0];
                  });
        std::vector<std::pair<unsigned int, unsigned int>> pairs;
        for (unsigned int a = 0; a < n_vertices; ++a)
          for (unsigned int b = a + 1;
               b < n_vertices &&
               vertices[order[b]][0] - vertices[order[a]][0] <= tolerance;
               ++b)
            {
              bool same = true;
              for (unsigned int d = 1; d < dim; ++d)
                same = same && std::abs(vertices[order[b]][d] -
                                        vertices[order[a]][d]) <= tolerance;
              if (same)
                pairs.emplace_back(order[a], order[b]);
            }
        if (pairs.empty())
          return;

        std::set<unsigned int> involved;
        for (const auto &[a, b] : pairs)
          involved.insert({a, b});
        std::string            positions;
        std::set<unsigned int> listed;
        for (const auto &[a, b] : pairs)
          if (listed.size() < 5 && listed.insert(a).second)
            positions +=
              (positions.empty() ? "" : ", ") + format_point(vertices[a]);
        if (parameters.coincident_vertices == "keep")
          {
            if (notes != nullptr)
              *notes += "  mesh file:       kept " +
                        std::to_string(involved.size()) +
                        " coincident vertices (Coincident vertices = keep): "
                        "the cells on either side are not connected, e.g. "
                        "at " +
                        positions + "\n";
            return;
          }
        std::ostringstream tolerance_text;
        tolerance_text << std::setprecision(3) << tolerance;
        AssertThrow(parameters.coincident_vertices == "merge",
                    ExcMessage(
                      "The mesh file " + parameters.file_name + " has " +
                      std::to_string(involved.size()) +
                      " vertices that coincide with another one (" +
                      std::to_string(pairs.size()) + " pairs closer than " +
                      tolerance_text.str() + " in every coordinate), e.g. at " +
                      positions +
                      (listed.size() < involved.size() ? ", ..." : "") +
                      ". The cells on either side of them are not "
                      "connected (blocks of the mesh generator not merged). "
                      "Set 'Coincident vertices = merge' in subsection "
                      "'Geometry' to merge them, or merge them in the mesh "
                      "generator."));

        std::vector<unsigned int> considered(involved.begin(), involved.end());
        GridTools::delete_duplicated_vertices(vertices,
                                              cells,
                                              subcelldata,
                                              considered,
                                              tolerance);
        GridTools::delete_unused_vertices(vertices, cells, subcelldata);
        const unsigned int n_merged = n_vertices - vertices.size();

        // Boundary data of faces (and, in 3-D, edges) that are now interior.
        std::map<std::vector<unsigned int>, unsigned int> face_count;
        for (const CellData<dim> &cell : cells)
          for (const unsigned int f : GeometryInfo<dim>::face_indices())
            {
              std::vector<unsigned int> face;
              for (unsigned int v = 0; v < GeometryInfo<dim>::vertices_per_face;
                   ++v)
                face.push_back(
                  cell
                    .vertices[GeometryInfo<dim>::face_to_cell_vertices(f, v)]);
              std::sort(face.begin(), face.end());
              ++face_count[face];
            }
        const auto on_boundary = [&](const auto &face_data) {
          std::vector<unsigned int> face(face_data.vertices.begin(),
                                         face_data.vertices.end());
          std::sort(face.begin(), face.end());
          const auto it = face_count.find(face);
          return it != face_count.end() && it->second == 1;
        };
        if constexpr (dim == 2)
          {
            auto &lines = subcelldata.boundary_lines;
            lines.erase(std::remove_if(lines.begin(),
                                       lines.end(),
                                       [&](const CellData<1> &l) {
                                         return !on_boundary(l);
                                       }),
                        lines.end());
          }
        else
          {
            auto &quads = subcelldata.boundary_quads;
            quads.erase(std::remove_if(quads.begin(),
                                       quads.end(),
                                       [&](const CellData<2> &q) {
                                         return !on_boundary(q);
                                       }),
                        quads.end());
            std::set<std::pair<unsigned int, unsigned int>> edges;
            for (const CellData<2> &q : quads)
              for (const unsigned int l : GeometryInfo<2>::face_indices())
                {
                  const unsigned int a =
                    q.vertices[GeometryInfo<2>::face_to_cell_vertices(l, 0)];
                  const unsigned int b =
                    q.vertices[GeometryInfo<2>::face_to_cell_vertices(l, 1)];
                  edges.emplace(std::min(a, b), std::max(a, b));
                }
            auto &lines = subcelldata.boundary_lines;
            lines.erase(std::remove_if(lines.begin(),
                                       lines.end(),
                                       [&](const CellData<1> &l) {
                                         return edges.count(
                                                  {std::min(l.vertices[0],
                                                            l.vertices[1]),
                                                   std::max(l.vertices[0],
                                                            l.vertices[1])}) ==
                                                0;
                                       }),
                        lines.end());
          }

        try
          {
            GridTools::consistently_order_cells(cells);
          }
        catch (const ExceptionBase &)
          {
            // 3-D meshes that cannot be ordered: deal.II handles the face
            // orientations itself
          }
        triangulation.clear();
        triangulation.create_triangulation(vertices, cells, subcelldata);

        if (notes != nullptr)
          *notes += "  mesh file:       merged " + std::to_string(n_merged) +
                    " coincident vertices (" + std::to_string(n_vertices) +
                    " -> " + std::to_string(vertices.size()) + "), e.g. at " +
                    positions + "\n";
      }



      template <int dim>
      void
      read_mesh_file(const Parameters::Geometry &parameters,
                     Triangulation<dim>         &triangulation,
                     std::string                *notes)
      {
        const std::string &file_name = parameters.file_name;

        const std::string::size_type dot = file_name.find_last_of('.');
        std::string                  extension =
          (dot == std::string::npos ? "" : file_name.substr(dot + 1));
        std::transform(extension.begin(),
                       extension.end(),
                       extension.begin(),
                       [](const unsigned char c) { return std::tolower(c); });

        typename GridIn<dim>::Format format;
        if (extension == "msh")
          format = GridIn<dim>::msh;
        else if (extension == "inp")
          format = GridIn<dim>::abaqus;
        else if (extension == "ucd")
          format = GridIn<dim>::ucd;
        else
          AssertThrow(false,
                      ExcBadParameter("Geometry/File name",
                                      file_name,
                                      "its extension must be .msh (Gmsh), "
                                      ".inp (Abaqus) or .ucd (UCD); these "
                                      "are the formats pg reads."));

        std::ifstream input(file_name);
        AssertThrow(input.good(),
                    ExcMessage(unreadable_file_message(
                      file_name,
                      "it does not exist or cannot be opened")));

        // GridIn's own message says what is wrong inside the file; print_info
        // gives it without the source location that what() adds.
        std::string reason;
        try
          {
            GridIn<dim> grid_in;
            grid_in.attach_triangulation(triangulation);
            grid_in.read(input, format);
          }
        catch (const ExceptionBase &exc)
          {
            std::ostringstream s;
            exc.print_info(s);
            reason = "deal.II's GridIn reports: " + Utilities::trim(s.str());
          }
        catch (const std::exception &exc)
          {
            reason = "deal.II's GridIn reports: " +
                     Utilities::trim(std::string(exc.what()));
          }
        while (!reason.empty() && reason.back() == '.')
          reason.pop_back();
        AssertThrow(reason.empty(),
                    ExcMessage(unreadable_file_message(file_name, reason)));
        AssertThrow(triangulation.n_active_cells() > 0,
                    ExcMessage(unreadable_file_message(
                      file_name,
                      "it contains no cells of dimension " +
                        std::to_string(dim))));
        handle_coincident_vertices(parameters, triangulation, notes);
      }



      /**
       * Whether a cell is inverted, from the Jacobian of its multilinear map
       * at each vertex (spanned by the edges that leave the vertex). For
       * quadrilaterals this is exact: the determinant is affine in the
       * reference coordinates, so positive at the vertices means positive
       * everywhere; for hexahedra it is the usual necessary check.
       */
      template <int dim>
      bool
      is_inverted(const typename Triangulation<dim>::active_cell_iterator &cell)
      {
        if (!cell->reference_cell().is_hyper_cube())
          return !(cell->measure() > 0.);

        // Lexicographic vertex numbering: the neighbour of vertex v along
        // reference direction d differs from v in bit d.
        for (const unsigned int v : cell->vertex_indices())
          {
            Tensor<2, dim> jacobian;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const Tensor<1, dim> edge =
                  cell->vertex(v ^ (1U << d)) - cell->vertex(v);
                const double sign = ((v & (1U << d)) != 0 ? -1. : 1.);
                for (unsigned int e = 0; e < dim; ++e)
                  jacobian[e][d] = sign * edge[e];
              }
            if (!(determinant(jacobian) > 0.))
              return true;
          }
        return false;
      }



      /**
       * 'Distortion': GridTools::distort_random() moves every interior vertex
       * by 'Distortion' times its shortest adjacent edge, in a random
       * direction. Where that makes a cell non-convex (cells with angles
       * well above 90 degrees, as near the corners of the plate with a
       * hole), the vertices of that cell are drawn again from their
       * original positions, up to the same distance, until every cell is
       * convex (at most 100 rounds; then the error names the cell). The
       * random engines are seeded by 'Random seed' and visit the vertices
       * in their global order; for a parallel::shared::Triangulation every
       * rank moves every vertex, so all ranks end up with the same mesh.
       */
      template <int dim>
      void
      distort(const Parameters::Geometry &parameters,
              Triangulation<dim>         &triangulation)
      {
        const std::vector<Point<dim>> original = triangulation.get_vertices();
        std::vector<double>           shortest_edge(original.size(),
                                          std::numeric_limits<double>::max());
        std::vector<bool>             on_boundary(original.size(), false);
        for (const auto &cell : triangulation.active_cell_iterators())
          {
            for (const unsigned int l : cell->line_indices())
              for (const unsigned int v : {0U, 1U})
                shortest_edge[cell->line(l)->vertex_index(v)] =
                  std::min(shortest_edge[cell->line(l)->vertex_index(v)],
                           cell->line(l)->diameter());
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary())
                for (const unsigned int v : cell->face(f)->vertex_indices())
                  on_boundary[cell->face(f)->vertex_index(v)] = true;
          }

        GridTools::distort_random(parameters.distortion,
                                  triangulation,
                                  /*keep_boundary=*/true,
                                  parameters.random_seed);

        std::mt19937                           engine(parameters.random_seed);
        std::uniform_real_distribution<double> uniform(-1., 1.);
        for (unsigned int round = 0;; ++round)
          {
            std::vector<bool> redrawn(original.size(), false);
            typename Triangulation<dim>::active_cell_iterator inverted;
            bool                                              found = false;
            for (const auto &cell : triangulation.active_cell_iterators())
              if (is_inverted<dim>(cell))
                {
                  inverted = cell;
                  found    = true;
                  if (round == 100)
                    break;
                  for (const unsigned int v : cell->vertex_indices())
                    {
                      const unsigned int i = cell->vertex_index(v);
                      if (on_boundary[i] || redrawn[i])
                        continue;
                      // a uniform point of the ball of the allowed radius
                      Tensor<1, dim> shift;
                      do
                        for (unsigned int d = 0; d < dim; ++d)
                          shift[d] = uniform(engine);
                      while (shift.norm_square() > 1.);
                      cell->vertex(v) = original[i] + parameters.distortion *
                                                        shortest_edge[i] *
                                                        shift;
                      redrawn[i] = true;
                    }
                }
            if (!found)
              return;
            if (round == 100)
              {
                std::ostringstream centre;
                centre << inverted->center();
                AssertThrow(false,
                            ExcBadParameter(
                              "Geometry/Distortion",
                              join(std::vector<double>{parameters.distortion}),
                              "it leaves the cell with centre (" +
                                centre.str() +
                                ") of this mesh non-convex even after "
                                "100 new random draws of its vertices; use "
                                "a smaller value in subsection "
                                "'Geometry'."));
              }
          }
      }



      /** A parsed 'Meshfree region'. */
      template <int dim>
      struct MeshfreeRegion
      {
        enum class Kind
        {
          all,
          none,
          material_ids,
          box,
          ball
        };

        Kind                            kind = Kind::all;
        std::vector<types::material_id> material_ids;
        Point<dim>                      lower;
        Point<dim>                      upper;
        Point<dim>                      centre;
        double                          radius = 0.;

        /**
         * Whether the centre of @p cell is in the region. Box and ball are
         * closed, with a tolerance of 1e-10 of their size, so that centres on
         * their boundary count despite round-off.
         */
        bool
        contains(
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

        /** Whether @p p lies in the box or ball (closed, as above). */
        bool
        contains_point(const Point<dim> &p) const
        {
          if (kind == Kind::ball)
            return p.distance(centre) <= radius * (1. + 1e-10);
          const double tolerance = 1e-10 * lower.distance(upper);
          for (unsigned int d = 0; d < dim; ++d)
            if (p[d] < lower[d] - tolerance || p[d] > upper[d] + tolerance)
              return false;
          return true;
        }
      };



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



      template <int dim>
      MeshfreeRegion<dim>
      parse_meshfree_region(
        const std::string &text,
        const std::string &entry = "Geometry/Meshfree region")
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
          region.kind = MeshfreeRegion<dim>::Kind::all;
        else if (trimmed == "none")
          region.kind = MeshfreeRegion<dim>::Kind::none;
        else if (starts_with(trimmed, "material ids", rest))
          {
            region.kind = MeshfreeRegion<dim>::Kind::material_ids;
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
            region.kind = MeshfreeRegion<dim>::Kind::box;
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
            region.kind = MeshfreeRegion<dim>::Kind::ball;
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



      /**
       * 'Hole': remove the coarse cells whose centres lie in the box; the
       * faces of the hole get boundary id 2*dim.
       */
      template <int dim>
      void
      cut_hole(const Parameters::Geometry &parameters,
               Triangulation<dim>         &triangulation)
      {
        const MeshfreeRegion<dim> hole =
          parse_meshfree_region<dim>(parameters.hole, "Geometry/Hole");
        AssertThrow(hole.kind == MeshfreeRegion<dim>::Kind::box,
                    ExcBadParameter("Geometry/Hole",
                                    parameters.hole,
                                    "it must read 'box x0,y0 : x1,y1' (or be "
                                    "empty)."));
        Triangulation<dim> full;
        full.copy_triangulation(triangulation);
        std::set<typename Triangulation<dim>::active_cell_iterator> removed;
        for (const auto &cell : full.active_cell_iterators())
          if (hole.contains(cell))
            removed.insert(cell);
        AssertThrow(!removed.empty() && removed.size() < full.n_active_cells(),
                    ExcBadParameter("Geometry/Hole",
                                    parameters.hole,
                                    "it must contain the centres of some, but "
                                    "not all, cells of the coarse mesh "
                                    "('Subdivisions')."));
        triangulation.clear();
        GridGenerator::create_triangulation_with_removed_cells(full,
                                                               removed,
                                                               triangulation);
        // the new boundary: faces on the (closed) box
        for (const auto &cell : triangulation.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && hole.contains_point(face->center()))
              face->set_boundary_id(2 * dim);
      }
    } // namespace



    template <int dim>
    void
    create_mesh(const Parameters::Geometry &parameters,
                Triangulation<dim>         &triangulation,
                std::string                *notes)
    {
      Assert(triangulation.n_cells() == 0,
             ExcMessage("create_mesh() needs an empty triangulation."));

      const std::string &mesh = parameters.mesh;
      if (mesh == "hyper rectangle")
        {
          create_hyper_rectangle(parameters, triangulation);
          if (!parameters.hole.empty())
            cut_hole(parameters, triangulation);
        }
      else if (mesh == "cook membrane" || mesh == "plate with hole")
        {
          AssertThrow(dim == 2,
                      ExcBadParameter("Geometry/Mesh",
                                      mesh,
                                      "this mesh is not yet available in "
                                      "3-D; use it with 'Dimension = 2'."));
          if constexpr (dim == 2)
            {
              if (mesh == "cook membrane")
                create_cook_membrane(parameters, triangulation);
              else
                create_plate_with_hole(parameters, triangulation);
            }
        }
      else if (mesh == "file")
        read_mesh_file(parameters, triangulation, notes);
      else
        AssertThrow(false,
                    ExcBadParameter("Geometry/Mesh",
                                    mesh,
                                    "it must be 'hyper rectangle', 'cook "
                                    "membrane', 'plate with hole' or "
                                    "'file'."));

      triangulation.refine_global(parameters.global_refinement);

      if (parameters.distortion > 0.)
        distort(parameters, triangulation);
    }



    template <int dim>
    std::vector<bool>
    mark_meshfree_cells(const Parameters::Geometry &parameters,
                        const Triangulation<dim>   &triangulation)
    {
      const MeshfreeRegion<dim> region =
        parse_meshfree_region<dim>(parameters.meshfree_region);

      std::vector<bool> meshfree(triangulation.n_active_cells(), false);
      for (const auto &cell : triangulation.active_cell_iterators())
        meshfree[cell->active_cell_index()] = region.contains(cell);
      return meshfree;
    }



    template void
    create_mesh<2>(const Parameters::Geometry &,
                   Triangulation<2> &,
                   std::string *);
    template void
    create_mesh<3>(const Parameters::Geometry &,
                   Triangulation<3> &,
                   std::string *);

    template std::vector<bool>
    mark_meshfree_cells<2>(const Parameters::Geometry &,
                           const Triangulation<2> &);
    template std::vector<bool>
    mark_meshfree_cells<3>(const Parameters::Geometry &,
                           const Triangulation<3> &);
  } // namespace Mesh
} // namespace pg
