#include <pg/base/exceptions.h>
#include <pg/mesh/mesh_file.h>
#include <pg/mesh/mesh_generator.h>
#include <pg/mesh/meshfree_region.h>
#include <pg/mesh/simplex_split.h>

#include <deal.II/base/numbers.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_description.h>
#include <deal.II/grid/tria_iterator.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
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
       * Cook's membrane: the colorized rectangle [0,48]x[0,44] (in 3-D the
       * box [0,48]x[0,44]x[0,'Thickness']) mapped so that the bottom edge
       * runs from (0,0) to (48,44) and the top edge from (0,44) to (48,60);
       * z is unchanged. The map is bilinear in x and y, so the
       * straight-sided cells are mapped exactly and later refinement needs
       * no manifold. Boundary ids: 0 left (x = 0), 1 right (x = 48),
       * 2 bottom, 3 top, and in 3-D 4 front (z = 0), 5 back.
       */
      template <int dim>
      void
      create_cook_membrane(const Parameters::Geometry &parameters,
                           Triangulation<dim>         &triangulation)
      {
        Point<dim> upper;
        upper[0] = 48.;
        upper[1] = 44.;
        if (dim == 3)
          upper[dim - 1] = parameters.thickness;
        GridGenerator::subdivided_hyper_rectangle(
          triangulation,
          subdivisions_per_direction<dim>(parameters),
          Point<dim>(),
          upper,
          /*colorize=*/true);

        GridTools::transform(
          [](const Point<dim> &p) {
            const double y_bottom = 44. * p[0] / 48.;
            const double y_top    = 44. + 16. * p[0] / 48.;
            Point<dim>   q        = p;
            q[1]                  = y_bottom + (y_top - y_bottom) * p[1] / 44.;
            return q;
          },
          triangulation);
      }



      /** The radial layers of the coarse plate with a hole. */
      unsigned int
      plate_with_hole_layers(const double L, const double R)
      {
        if (!(R > 0. && R < L))
          return 1;
        return std::max(1,
                        static_cast<int>(std::ceil(
                          std::log(L / R) / std::log(1. + numbers::PI / 4.))));
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

        const unsigned int n_layers = plate_with_hole_layers(L, R);

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
          MeshfreeRegion<dim>::parse(parameters.hole, "Geometry/Hole");
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
        // create_triangulation_with_removed_cells() sets every boundary id
        // to 0: colorize the outer faces again (0: x = min, 1: x = max, ...)
        // and give the faces on the (closed) box id 2*dim.
        const double tolerance = 1e-10 * diameter(triangulation);
        for (const auto &cell : triangulation.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              {
                const Point<dim> c = face->center();
                if (hole.contains_point(c))
                  {
                    face->set_boundary_id(2 * dim);
                    continue;
                  }
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    const double lower = std::min(parameters.lower_corner[d],
                                                  parameters.upper_corner[d]);
                    const double upper = std::max(parameters.lower_corner[d],
                                                  parameters.upper_corner[d]);
                    if (std::abs(c[d] - lower) < tolerance)
                      face->set_boundary_id(2 * d);
                    else if (std::abs(c[d] - upper) < tolerance)
                      face->set_boundary_id(2 * d + 1);
                  }
              }
      }

    } // namespace



    template <int dim>
    MeshSize
    predict_mesh_size(const Parameters::Geometry &parameters)
    {
      const double refined = std::pow(2., parameters.global_refinement);
      // cells per direction after refinement, and the measure
      std::vector<double> n(dim, 1.);
      double              measure = 1.;
      if (parameters.mesh == "plate with hole")
        {
          const double L = parameters.plate_size;
          const double R = parameters.hole_radius;
          n              = std::vector<double>(dim, 1.);
          n[0]           = plate_with_hole_layers(L, R) * refined;
          n[1]           = 2. * refined;
          measure        = L * L - numbers::PI * R * R / 4.;
        }
      else
        {
          Assert(parameters.mesh == "hyper rectangle" ||
                   parameters.mesh == "cook membrane",
                 ExcMessage("predict_mesh_size() of a generated mesh only"));
          const std::vector<unsigned int> s =
            subdivisions_per_direction<dim>(parameters);
          for (unsigned int d = 0; d < dim; ++d)
            n[d] = s[d] * refined;
          if (parameters.mesh == "cook membrane")
            // the tapered panel: 48 wide, 44 high on the left, 16 on the
            // right
            measure =
              48. * (44. + 16.) / 2. * (dim == 3 ? parameters.thickness : 1.);
          else
            for (unsigned int d = 0; d < dim; ++d)
              measure *= (parameters.lower_corner.size() == dim &&
                          parameters.upper_corner.size() == dim) ?
                           std::abs(parameters.upper_corner[d] -
                                    parameters.lower_corner[d]) :
                           1.;
        }
      MeshSize size;
      size.n_cells    = 1.;
      size.n_vertices = 1.;
      for (unsigned int d = 0; d < dim; ++d)
        {
          size.n_cells *= n[d];
          size.n_vertices *= n[d] + 1.;
        }
      size.n_coarse_cells =
        size.n_cells / std::pow(refined, static_cast<double>(dim));
      size.spacing = std::pow(measure / size.n_cells, 1. / dim);
      if (parameters.cells == "simplices")
        predict_split_size<dim>(n, measure, size);
      return size;
    }



    template <int dim>
    MeshSize
    predict_mesh_size(const Parameters::Geometry &parameters,
                      const Triangulation<dim>   &coarse)
    {
      const double refined = std::pow(2., parameters.global_refinement);
      MeshSize     size;
      size.n_coarse_cells = coarse.n_active_cells();
      size.n_cells =
        size.n_coarse_cells * std::pow(refined, static_cast<double>(dim));
      const double n_coarse_vertices = coarse.n_used_vertices();
      size.simplex                   = coarse.n_active_cells() > 0 &&
                     !coarse.all_reference_cells_are_hyper_cube();
      // (GridTools::volume() integrates with QGauss: hypercubes only)
      double volume = 0;
      for (const auto &cell : coarse.active_cell_iterators())
        volume += cell->measure();
      volume = std::abs(volume);
      if (!size.simplex)
        {
          // each refinement adds about one vertex per new cell, plus those
          // of the refined boundary (an upper bound of the exact count)
          size.n_vertices =
            parameters.global_refinement == 0 ?
              n_coarse_vertices :
              size.n_cells + n_coarse_vertices *
                               std::pow(refined, static_cast<double>(dim - 1));
          size.spacing = std::pow(volume / size.n_cells, 1. / dim);
          if (parameters.cells == "simplices")
            {
              // 'Cells = simplices': each cell gives 8 (24) simplices, and
              // there are about 4 times as many vertices (edge midpoints
              // and centres; face centres)
              size.n_cells *= (dim == 2 ? 8. : 24.);
              size.n_vertices *= 4.;
              size.spacing = std::pow(volume / size.n_vertices, 1. / dim);
              size.simplex = true;
              size.edge_neighbours = (dim == 2 ? 6. : 14.);
            }
          return size;
        }

      // simplices: the edges of the coarse mesh
      unsigned int           n_edges = 0;
      std::set<unsigned int> counted;
      for (const auto &cell : coarse.active_cell_iterators())
        for (const unsigned int l : cell->line_indices())
          if (counted.insert(cell->line(l)->index()).second)
            ++n_edges;
      // a refinement adds the midpoint of every edge: exact for one
      // refinement, and the vertices grow by 2^dim per refinement in the
      // limit (the edges per vertex stay about the same)
      const double cells_per_cell = std::pow(2., dim);
      size.n_vertices             = n_coarse_vertices +
                        n_edges *
                          (std::pow(refined, static_cast<double>(dim)) - 1.) /
                          (cells_per_cell - 1.);
      // the spacing of the vertex density
      size.spacing = std::pow(volume / size.n_vertices, 1. / dim);
      if (n_coarse_vertices > 0)
        size.edge_neighbours = 2. * n_edges / n_coarse_vertices;
      return size;
    }



    template <int dim>
    void
    create_mesh(const Parameters::Geometry                       &parameters,
                Triangulation<dim>                               &triangulation,
                std::string                                      *notes,
                const std::function<void(const MeshSize &)>      &check_size,
                std::map<std::string, std::vector<unsigned int>> *node_sets)
    {
      Assert(triangulation.n_cells() == 0,
             ExcMessage("create_mesh() needs an empty triangulation."));

      const std::string &mesh = parameters.mesh;
      // 'Cells = simplices': the hypercube mesh is built, refined and
      // distorted here, then split into the triangulation
      const bool          split = (parameters.cells == "simplices");
      Triangulation<dim>  hypercubes;
      Triangulation<dim> &target = split ? hypercubes : triangulation;
      // before anything is allocated (issue 45, item 1: a typo asked for
      // 2 x 10^10 cells)
      if (check_size && mesh != "file" &&
          (mesh != "plate with hole" || dim == 2))
        check_size(predict_mesh_size<dim>(parameters));
      if (mesh == "hyper rectangle")
        {
          create_hyper_rectangle(parameters, target);
          if (!parameters.hole.empty())
            cut_hole(parameters, target);
        }
      else if (mesh == "cook membrane")
        create_cook_membrane(parameters, target);
      else if (mesh == "plate with hole")
        {
          AssertThrow(dim == 2,
                      ExcBadParameter("Geometry/Mesh",
                                      mesh,
                                      "this mesh is not yet available in "
                                      "3-D; use it with 'Dimension = 2'."));
          if constexpr (dim == 2)
            create_plate_with_hole(parameters, target);
        }
      else if (mesh == "file")
        {
          read_mesh_file(parameters, target, notes, node_sets);
          if (check_size)
            check_size(predict_mesh_size<dim>(parameters, target));
        }
      else
        AssertThrow(false,
                    ExcBadParameter("Geometry/Mesh",
                                    mesh,
                                    "it must be 'hyper rectangle', 'cook "
                                    "membrane', 'plate with hole' or "
                                    "'file'."));

      target.refine_global(parameters.global_refinement);
      if (node_sets != nullptr && parameters.global_refinement > 0)
        refine_node_sets(target, *node_sets);

      if (parameters.distortion > 0.)
        distort(parameters, target);

      if (split)
        {
          // the split numbers the vertices anew
          AssertThrow(
            node_sets == nullptr || node_sets->empty() ||
              !hypercubes.all_reference_cells_are_hyper_cube(),
            ExcBadParameter("Geometry/Cells",
                            "simplices",
                            "the mesh file " + parameters.file_name +
                              " has node sets, which pg does not carry over to "
                              "the split mesh. Use 'Cells = hypercubes', or "
                              "mesh the body with tetrahedra (or triangles) "
                              "and give it the node sets there."));
          if (hypercubes.all_reference_cells_are_hyper_cube())
            {
              split_into_simplices(hypercubes, triangulation);
              if (notes != nullptr)
                *notes +=
                  "  simplices:       split " +
                  std::to_string(hypercubes.n_active_cells()) +
                  (dim == 2 ? " quadrilaterals into " : " hexahedra into ") +
                  std::to_string(triangulation.n_active_cells()) +
                  (dim == 2 ? " triangles" : " tetrahedra") +
                  " ('Cells = simplices')\n";
            }
          else
            // a mesh file of simplices: nothing to split
            triangulation.copy_triangulation(hypercubes);
        }
    }



    template <int dim>
    double
    diameter(const Triangulation<dim> &triangulation)
    {
      const std::vector<Point<dim>> &vertices = triangulation.get_vertices();
      std::vector<bool>              on_boundary(vertices.size(), false);
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            for (const unsigned int v : face->vertex_indices())
              on_boundary[face->vertex_index(v)] = true;

      std::vector<Point<dim>> points;
      for (unsigned int v = 0; v < vertices.size(); ++v)
        if (on_boundary[v])
          points.push_back(vertices[v]);
      if (points.size() < 2)
        return 0;
      Point<dim> lower = points[0], upper = points[0];
      for (const Point<dim> &p : points)
        for (unsigned int d = 0; d < dim; ++d)
          {
            lower[d] = std::min(lower[d], p[d]);
            upper[d] = std::max(upper[d], p[d]);
          }
      // |p - q| <= |p - c(p)| for every q in the box, with c(p) the box
      // corner farthest from p
      std::vector<std::pair<double, unsigned int>> bound(points.size());
      for (unsigned int i = 0; i < points.size(); ++i)
        {
          double square = 0;
          for (unsigned int d = 0; d < dim; ++d)
            square += std::pow(std::max(points[i][d] - lower[d],
                                        upper[d] - points[i][d]),
                               2);
          bound[i] = {square, i};
        }
      std::sort(bound.begin(), bound.end(), std::greater<>());
      double largest = 0;
      for (const auto &[square_bound, i] : bound)
        {
          if (square_bound <= largest)
            break;
          for (const Point<dim> &q : points)
            largest = std::max(largest, points[i].distance_square(q));
        }
      return std::sqrt(largest);
    }



    template <int dim>
    std::vector<bool>
    mark_meshfree_cells(const Parameters::Geometry &parameters,
                        const Triangulation<dim>   &triangulation)
    {
      const MeshfreeRegion<dim> region =
        MeshfreeRegion<dim>::parse(parameters.meshfree_region);

      std::vector<bool> meshfree(triangulation.n_active_cells(), false);
      for (const auto &cell : triangulation.active_cell_iterators())
        meshfree[cell->active_cell_index()] = region.contains(cell);
      // 'none' asks for Q1 everywhere; any other region must hold a cell
      if (Utilities::trim(parameters.meshfree_region) != "none" &&
          std::none_of(meshfree.begin(), meshfree.end(), [](const bool m) {
            return m;
          }))
        {
          const auto box = GridTools::compute_bounding_box(triangulation);
          std::ostringstream corners;
          corners << "(" << box.get_boundary_points().first << ") and ("
                  << box.get_boundary_points().second << ")";
          AssertThrow(false,
                      ExcBadParameter(
                        "Geometry/Meshfree region",
                        parameters.meshfree_region,
                        "it selects no cell of the mesh (no cell centre lies "
                        "inside, or no cell has these material ids), and the "
                        "run would be plain Q1 finite elements. The mesh lies "
                        "between " +
                          corners.str() +
                          "; fix the region, or write 'none' for Q1 "
                          "elements everywhere."));
        }
      return meshfree;
    }



    template MeshSize
    predict_mesh_size<2>(const Parameters::Geometry &);
    template MeshSize
    predict_mesh_size<3>(const Parameters::Geometry &);
    template MeshSize
    predict_mesh_size<2>(const Parameters::Geometry &,
                         const Triangulation<2> &);
    template MeshSize
    predict_mesh_size<3>(const Parameters::Geometry &,
                         const Triangulation<3> &);
    template void
    create_mesh<2>(const Parameters::Geometry &,
                   Triangulation<2> &,
                   std::string *,
                   const std::function<void(const MeshSize &)> &,
                   std::map<std::string, std::vector<unsigned int>> *);
    template void
    create_mesh<3>(const Parameters::Geometry &,
                   Triangulation<3> &,
                   std::string *,
                   const std::function<void(const MeshSize &)> &,
                   std::map<std::string, std::vector<unsigned int>> *);

    template double
    diameter<2>(const Triangulation<2> &);
    template double
    diameter<3>(const Triangulation<3> &);
    template std::vector<bool>
    mark_meshfree_cells<2>(const Parameters::Geometry &,
                           const Triangulation<2> &);
    template std::vector<bool>
    mark_meshfree_cells<3>(const Parameters::Geometry &,
                           const Triangulation<3> &);
  } // namespace Mesh
} // namespace pg
