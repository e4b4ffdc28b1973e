#include <pg/base/exceptions.h>
#include <pg/mesh/exodus_file.h>
#include <pg/mesh/mesh_file.h>

#include <deal.II/base/point.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_description.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <map>
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
      /** The message for a mesh file that GridIn cannot read. */
      std::string
      unreadable_file_message(const std::string &file_name,
                              const std::string &reason,
                              const std::string &hint =
                                "Check the path (relative paths start in "
                                "the working directory).")
      {
        return "The mesh file " + file_name +
               " given as 'File name' in subsection 'Geometry' cannot be "
               "read: " +
               reason + ". " + hint;
      }



      /**
       * The Gmsh element type N of GridIn's message "The Element Identifier
       * <N> is not supported", or 0.
       */
      unsigned int
      gmsh_element_type(const std::string &message)
      {
        const std::string            key = "Element Identifier <";
        const std::string::size_type p   = message.find(key);
        if (p == std::string::npos)
          return 0;
        return std::atoi(message.c_str() + p + key.size());
      }



      /**
       * Gmsh's second- and higher-order element types (lines, triangles,
       * quadrilaterals, tetrahedra, hexahedra, prisms, pyramids of order 2
       * to 5 and their serendipity forms).
       */
      bool
      is_higher_order(const unsigned int type)
      {
        return (type >= 8 && type <= 14) || (type >= 16 && type <= 31) ||
               (type >= 36 && type <= 39);
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
          {
            const ReferenceCell kind =
              ReferenceCell::n_vertices_to_type(dim, cell.vertices.size());
            for (const unsigned int f : kind.face_indices())
              {
                std::vector<unsigned int> face;
                for (unsigned int v = 0;
                     v < kind.face_reference_cell(f).n_vertices();
                     ++v)
                  face.push_back(
                    cell.vertices[kind.face_to_cell_vertices(f, v, 1)]);
                std::sort(face.begin(), face.end());
                ++face_count[face];
              }
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
              {
                // (a quadrilateral or a triangle)
                const ReferenceCell kind =
                  ReferenceCell::n_vertices_to_type(2, q.vertices.size());
                for (const unsigned int l : kind.face_indices())
                  {
                    const unsigned int a =
                      q.vertices[kind.face_to_cell_vertices(l, 0, 1)];
                    const unsigned int b =
                      q.vertices[kind.face_to_cell_vertices(l, 1, 1)];
                    edges.emplace(std::min(a, b), std::max(a, b));
                  }
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

        if (triangulation.all_reference_cells_are_hyper_cube())
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
      /**
       * Fill @p triangulation from the Gmsh, Abaqus or UCD file
       * @p file_name with GridIn; GridIn's message, made readable, on
       * failure.
       */
      template <int dim>
      void
      read_with_grid_in(const std::string                 &file_name,
                        const typename GridIn<dim>::Format format,
                        Triangulation<dim>                &triangulation)
      {
        std::ifstream input(file_name);
        AssertThrow(input.good(),
                    ExcMessage(unreadable_file_message(
                      file_name,
                      "it does not exist or cannot be opened")));

        // GridIn's own message says what is wrong inside the file.
        std::string reason;
        try
          {
            GridIn<dim> grid_in;
            grid_in.attach_triangulation(triangulation);
            grid_in.read(input, format);
          }
        catch (const std::exception &exc)
          {
            reason = "deal.II's GridIn reports: " + user_message(exc);
            const unsigned int type = gmsh_element_type(reason);
            AssertThrow(format != GridIn<dim>::msh || !is_higher_order(type),
                        ExcMessage(unreadable_file_message(
                          file_name,
                          "it contains second- or higher-order elements "
                          "(Gmsh element type " +
                            std::to_string(type) +
                            "), and pg reads linear cells only (their "
                            "vertices are the particles or the Q1 nodes)",
                          "Mesh it with first-order elements (Gmsh: "
                          "'Mesh.ElementOrder = 1', or 'gmsh -order 1').")));
          }
        while (!reason.empty() && reason.back() == '.')
          reason.pop_back();
        const std::string contents_hint =
          "Check the file's format and contents (Gmsh and ParaView open it).";
        AssertThrow(reason.empty(),
                    ExcMessage(unreadable_file_message(file_name,
                                                       reason,
                                                       contents_hint)));
      }



      /**
       * Fill @p triangulation from the Exodus II file @p file_name
       * (material id = element block id, boundary id = side set id) and
       * return its node sets as positions in @p node_sets (the vertices
       * are renumbered when coincident ones are merged).
       */
      template <int dim>
      void
      read_exodus(const std::string                              &file_name,
                  Triangulation<dim>                             &triangulation,
                  std::map<std::string, std::vector<Point<dim>>> &node_sets)
      {
        ExodusMesh<dim> mesh = read_exodus_file<dim>(file_name);
        for (const auto &[name, nodes] : mesh.node_sets)
          {
            std::vector<Point<dim>> &points = node_sets[name];
            for (const unsigned int n : nodes)
              points.push_back(mesh.vertices[n]);
          }
        // As GridIn does for the other formats: a positive orientation,
        // then the hexahedra's faces oriented consistently
        bool hypercubes = true;
        for (const CellData<dim> &cell : mesh.cells)
          hypercubes = hypercubes && cell.vertices.size() == (1u << dim);
        if (hypercubes)
          {
            GridTools::invert_all_negative_measure_cells(mesh.vertices,
                                                         mesh.cells);
            try
              {
                GridTools::consistently_order_cells(mesh.cells);
              }
            catch (const ExceptionBase &)
              {
                // 3-D meshes that cannot be ordered: deal.II handles the
                // face orientations itself
              }
          }
        triangulation.create_triangulation(mesh.vertices,
                                           mesh.cells,
                                           mesh.subcelldata);
      }



      /**
       * The vertex index of each node set position (within @p tolerance),
       * by a sort of the vertices along x. Throws if a position has no
       * vertex (it cannot happen unless the mesh was changed in between).
       */
      template <int dim>
      std::map<std::string, std::vector<unsigned int>>
      node_set_vertices(
        const std::map<std::string, std::vector<Point<dim>>> &node_sets,
        const std::vector<Point<dim>>                        &vertices,
        const double                                          tolerance)
      {
        std::vector<unsigned int> order(vertices.size());
        for (unsigned int i = 0; i < order.size(); ++i)
          order[i] = i;
        std::sort(order.begin(),
                  order.end(),
                  [&](const unsigned int a, const unsigned int b) {
                    return vertices[a][0] < vertices[b][0];
                  });
        std::map<std::string, std::vector<unsigned int>> result;
        for (const auto &[name, points] : node_sets)
          {
            std::set<unsigned int> indices;
            for (const Point<dim> &p : points)
              {
                auto it =
                  std::lower_bound(order.begin(),
                                   order.end(),
                                   p[0] - tolerance,
                                   [&](const unsigned int v, const double x) {
                                     return vertices[v][0] < x;
                                   });
                bool found = false;
                for (; it != order.end() &&
                       vertices[*it][0] <= p[0] + tolerance && !found;
                     ++it)
                  if (vertices[*it].distance(p) <= tolerance)
                    {
                      indices.insert(*it);
                      found = true;
                    }
                AssertThrow(found,
                            ExcInternalError("node set " + name +
                                             ": no vertex at " +
                                             format_point(p)));
              }
            result[name].assign(indices.begin(), indices.end());
          }
        return result;
      }
    } // namespace



    template <int dim>
    void
    read_mesh_file(const Parameters::Geometry &parameters,
                   Triangulation<dim>         &triangulation,
                   std::string                *notes,
                   std::map<std::string, std::vector<unsigned int>> *node_sets)
    {
      const std::string &file_name = parameters.file_name;

      const std::string::size_type dot = file_name.find_last_of('.');
      std::string                  extension =
        (dot == std::string::npos ? "" : file_name.substr(dot + 1));
      std::transform(extension.begin(),
                     extension.end(),
                     extension.begin(),
                     [](const unsigned char c) { return std::tolower(c); });

      const bool exodus =
        (extension == "g" || extension == "e" || extension == "exo");
      typename GridIn<dim>::Format format = GridIn<dim>::Default;
      if (extension == "msh")
        format = GridIn<dim>::msh;
      else if (extension == "inp")
        format = GridIn<dim>::abaqus;
      else if (extension == "ucd")
        format = GridIn<dim>::ucd;
      else
        AssertThrow(exodus,
                    ExcBadParameter("Geometry/File name",
                                    file_name,
                                    "its extension must be .msh (Gmsh), "
                                    ".inp (Abaqus), .ucd (UCD) or .g, .e, "
                                    ".exo (Exodus II); these are the "
                                    "formats pg reads."));

      // Exodus II node sets, as positions until the vertices are final
      std::map<std::string, std::vector<Point<dim>>> node_set_points;
      if (exodus)
        read_exodus(file_name, triangulation, node_set_points);
      else
        read_with_grid_in(file_name, format, triangulation);

      const std::string contents_hint =
        "Check the file's format and contents (Gmsh and ParaView open it).";
      AssertThrow(triangulation.n_active_cells() > 0,
                  ExcMessage(unreadable_file_message(
                    file_name,
                    "it contains no cells of dimension " + std::to_string(dim),
                    contents_hint)));
      // Quadrilaterals (hexahedra): Q1 elements or meshfree cells;
      // triangles (tetrahedra): P1 elements or meshfree cells; one kind per
      // mesh
      const std::string kinds =
        dim == 2 ? "quadrilaterals or triangles" : "hexahedra or tetrahedra";
      AssertThrow(triangulation.all_reference_cells_are_hyper_cube() ||
                    triangulation.all_reference_cells_are_simplex(),
                  ExcMessage(unreadable_file_message(
                    file_name,
                    std::string("it contains ") +
                      (dim == 2 ? "both quadrilaterals and triangles" :
                                  "prisms, pyramids or both hexahedra and "
                                  "tetrahedra") +
                      ", and pg reads meshes of one kind of cell only: " +
                      kinds + " (mixed meshes are not supported)",
                    "Mesh the body with " + kinds +
                      " alone (Gmsh: 'Mesh.RecombineAll = 1' with "
                      "'Mesh.SubdivisionAlgorithm = " +
                      (dim == 2 ? "1" : "2") + "' for " +
                      (dim == 2 ? "quadrilaterals" : "hexahedra") +
                      "; no recombination for " +
                      (dim == 2 ? "triangles" : "tetrahedra") + ").")));
      handle_coincident_vertices(parameters, triangulation, notes);

      // A cell without area (volume) has no shape function gradients; the
      // assembly would stop in Newton with det F = NaN.
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          const double measure = cell->measure();
          // the start of both messages (built only when one is thrown)
          const auto this_cell = [&]() {
            return "Cell " + std::to_string(cell->active_cell_index()) +
                   " of the mesh file " + file_name +
                   " (given as 'File name' in subsection 'Geometry'), "
                   "with its centre at " +
                   format_point(cell->center());
          };
          // GridIn renumbers inverted cells of a file; a negative measure
          // here is a cell it could not fix
          AssertThrow(measure > -1e-12 * std::pow(cell->diameter(), dim),
                      ExcMessage(
                        this_cell() + ", is inverted: " +
                        (dim == 2 ? "its area" : "its volume") + " is " +
                        std::to_string(measure) +
                        ". Fix the numbering of its vertices in the mesh."));
          AssertThrow(measure > 1e-12 * std::pow(cell->diameter(), dim),
                      ExcMessage(
                        this_cell() + ", has " +
                        (dim == 2 ? "an area" : "a volume") + " of " +
                        std::to_string(measure) + ": its vertices lie " +
                        (dim == 2 ? "on a line" : "in a plane") +
                        " or coincide. Fix the cell in the mesh: pg needs "
                        "cells of positive " +
                        (dim == 2 ? "area." : "volume.")));
        }

      if (node_sets != nullptr)
        {
          node_sets->clear();
          if (!node_set_points.empty())
            {
              const auto &vertices = triangulation.get_vertices();
              Point<dim>  lower = vertices[0], upper = vertices[0];
              for (const Point<dim> &p : vertices)
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    lower[d] = std::min(lower[d], p[d]);
                    upper[d] = std::max(upper[d], p[d]);
                  }
              // merged vertices lie within 1e-10 of the diagonal in every
              // coordinate
              *node_sets = node_set_vertices(node_set_points,
                                             vertices,
                                             1e-9 * lower.distance(upper));
            }
        }
      if (exodus && notes != nullptr)
        {
          std::set<types::material_id> blocks;
          for (const auto &cell : triangulation.active_cell_iterators())
            blocks.insert(cell->material_id());
          std::string text = "  mesh file:       Exodus II, element blocks "
                             "(material ids)";
          for (const types::material_id id : blocks)
            text += " " + std::to_string(id);
          text += "; node sets";
          if (node_set_points.empty())
            text += ": none";
          for (const auto &[name, points] : node_set_points)
            text +=
              " " + name + " (" +
              std::to_string(node_sets != nullptr ? node_sets->at(name).size() :
                                                    points.size()) +
              " vertices)";
          *notes += text + "\n";
        }
    }



    template <int dim>
    void
    refine_node_sets(
      const Triangulation<dim>                         &triangulation,
      std::map<std::string, std::vector<unsigned int>> &node_sets)
    {
      for (auto &[name, vertices] : node_sets)
        {
          std::vector<bool> in(triangulation.n_vertices(), false);
          for (const unsigned int v : vertices)
            in[v] = true;
          const auto all_in = [&](const auto &object) {
            for (const unsigned int v : object->vertex_indices())
              if (!in[object->vertex_index(v)])
                return false;
            return true;
          };
          for (unsigned int level = 0; level + 1 < triangulation.n_levels();
               ++level)
            for (const auto &cell :
                 triangulation.cell_iterators_on_level(level))
              if (cell->has_children())
                {
                  for (const unsigned int l : cell->line_indices())
                    if (cell->line(l)->has_children() && all_in(cell->line(l)))
                      in[cell->line(l)->child(0)->vertex_index(1)] = true;
                  if constexpr (dim == 3)
                    for (const unsigned int f : cell->face_indices())
                      if (cell->face(f)->n_vertices() == 4 &&
                          cell->face(f)->has_children() &&
                          all_in(cell->face(f)))
                        in[cell->face(f)->child(0)->vertex_index(3)] = true;
                  if (cell->reference_cell().is_hyper_cube() && all_in(cell))
                    in[cell->child(0)->vertex_index(
                      GeometryInfo<dim>::vertices_per_cell - 1)] = true;
                }
          vertices.clear();
          for (unsigned int v = 0; v < in.size(); ++v)
            if (in[v])
              vertices.push_back(v);
        }
    }



    template void
    refine_node_sets<2>(const Triangulation<2> &,
                        std::map<std::string, std::vector<unsigned int>> &);
    template void
    refine_node_sets<3>(const Triangulation<3> &,
                        std::map<std::string, std::vector<unsigned int>> &);


    template void
    read_mesh_file<2>(const Parameters::Geometry &,
                      Triangulation<2> &,
                      std::string *,
                      std::map<std::string, std::vector<unsigned int>> *);
    template void
    read_mesh_file<3>(const Parameters::Geometry &,
                      Triangulation<3> &,
                      std::string *,
                      std::map<std::string, std::vector<unsigned int>> *);
  } // namespace Mesh
} // namespace pg
