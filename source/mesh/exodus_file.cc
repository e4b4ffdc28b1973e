#include <pg/base/exceptions.h>
#include <pg/mesh/exodus_file.h>

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/reference_cell.h>

#include <algorithm>
#include <array>
#include <cctype>

#ifdef PG_WITH_NETCDF
#  include <netcdf.h>
#endif

namespace pg
{
  namespace Mesh
  {
    bool
    exodus_support()
    {
#ifdef PG_WITH_NETCDF
      return true;
#else
      return false;
#endif
    }



#ifdef PG_WITH_NETCDF
    namespace ExodusReader
    {
      /** An element type pg reads: its vertex count and numbering maps. */
      struct ElementType
      {
        unsigned int n_vertices;
        /** deal.II vertex i is the file's local node permutation[i]. */
        std::vector<unsigned int> permutation;
        /** The file's local nodes of side s (1-based s, 0-based nodes),
         * in deal.II's vertex order of the face. */
        std::vector<std::vector<unsigned int>> sides;
      };



      /**
       * The element type of an Exodus name (case-insensitive, with the
       * usual aliases), or nullptr for a type pg does not read.
       */
      const ElementType *
      element_type(std::string name, const int dim)
      {
        std::transform(name.begin(), name.end(), name.begin(), [](char c) {
          return std::toupper(static_cast<unsigned char>(c));
        });
        // Exodus numbers the vertices of a quadrilateral face (and a
        // hexahedron's bottom and top) counterclockwise; deal.II
        // lexicographically. The faces are given in deal.II's order.
        static const ElementType quad{4,
                                      {0, 1, 3, 2},
                                      {{0, 1}, {1, 2}, {2, 3}, {3, 0}}};
        static const ElementType tri{3, {0, 1, 2}, {{0, 1}, {1, 2}, {2, 0}}};
        static const ElementType hex{8,
                                     {0, 1, 3, 2, 4, 5, 7, 6},
                                     {{0, 1, 4, 5},
                                      {1, 2, 5, 6},
                                      {2, 3, 6, 7},
                                      {0, 4, 3, 7},
                                      {0, 3, 1, 2},
                                      {4, 5, 7, 6}}};
        static const ElementType
          tet{4, {0, 1, 2, 3}, {{0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {0, 2, 1}}};
        const auto is = [&](std::initializer_list<const char *> names) {
          return std::find(names.begin(), names.end(), name) != names.end();
        };
        if (dim == 2 && is({"QUAD", "QUAD4", "SHELL", "SHELL4"}))
          return &quad;
        if (dim == 2 && is({"TRI", "TRI3", "TRIANGLE", "TRISHELL"}))
          return &tri;
        if (dim == 3 && is({"HEX", "HEX8", "HEXAHEDRON"}))
          return &hex;
        if (dim == 3 && is({"TETRA", "TETRA4", "TET", "TET4"}))
          return &tet;
        return nullptr;
      }



      /** An open netCDF file, closed on destruction. */
      class File
      {
      public:
        explicit File(const std::string &file_name)
          : file_name(file_name)
        {
          const int status = nc_open(file_name.c_str(), NC_NOWRITE, &id);
          AssertThrow(status == NC_NOERR,
                      ExcMessage(message(std::string("netCDF reports: ") +
                                           nc_strerror(status),
                                         "Check the path (relative paths "
                                         "start in the working directory) "
                                         "and that it is an Exodus II file "
                                         "(ncdump -h shows its header).")));
        }

        ~File()
        {
          nc_close(id);
        }

        File(const File &) = delete;
        File &
        operator=(const File &) = delete;

        /** The message for a file pg cannot read. */
        std::string
        message(const std::string &reason, const std::string &hint) const
        {
          return "The Exodus II mesh file " + file_name +
                 " given as 'File name' in subsection 'Geometry' cannot be "
                 "read: " +
                 reason + ". " + hint;
        }

        /** The length of dimension @p name, or 0 if the file has none. */
        std::size_t
        dimension(const std::string &name) const
        {
          int dim_id;
          if (nc_inq_dimid(id, name.c_str(), &dim_id) != NC_NOERR)
            return 0;
          std::size_t length = 0;
          nc_inq_dimlen(id, dim_id, &length);
          return length;
        }

        bool
        has_variable(const std::string &name) const
        {
          int var_id;
          return nc_inq_varid(id, name.c_str(), &var_id) == NC_NOERR;
        }

        /** Variable @p name as @p size values of type T. */
        template <typename T>
        std::vector<T>
        variable(const std::string &name, const std::size_t size) const
        {
          int var_id;
          AssertThrow(nc_inq_varid(id, name.c_str(), &var_id) == NC_NOERR,
                      ExcMessage(message("it has no variable '" + name + "'",
                                         "It is not an Exodus II mesh, or "
                                         "an incomplete one.")));
          std::vector<T> values(size);
          int            status = NC_NOERR;
          if (size > 0)
            {
              if constexpr (std::is_same_v<T, double>)
                status = nc_get_var_double(id, var_id, values.data());
              else if constexpr (std::is_same_v<T, int>)
                status = nc_get_var_int(id, var_id, values.data());
              else
                status = nc_get_var_text(id, var_id, values.data());
            }
          AssertThrow(status == NC_NOERR,
                      ExcMessage(message("netCDF cannot read '" + name +
                                           "': " + nc_strerror(status),
                                         "Check the file.")));
          return values;
        }

        /** The text attribute @p attribute of variable @p name. */
        std::string
        text_attribute(const std::string &name,
                       const std::string &attribute) const
        {
          int         var_id;
          std::size_t length = 0;
          if (nc_inq_varid(id, name.c_str(), &var_id) != NC_NOERR ||
              nc_inq_attlen(id, var_id, attribute.c_str(), &length) != NC_NOERR)
            return "";
          std::string text(length, '\0');
          nc_get_att_text(id, var_id, attribute.c_str(), text.data());
          return std::string(text.c_str()); // up to the first NUL
        }

        /**
         * The names of an entity kind ('eb_names', 'ns_names'): @p n
         * strings, empty where the file has none.
         */
        std::vector<std::string>
        names(const std::string &name, const std::size_t n) const
        {
          std::vector<std::string> result(n);
          const std::size_t        length = dimension("len_string");
          if (!has_variable(name) || length == 0)
            return result;
          const std::vector<char> text = variable<char>(name, n * length);
          for (std::size_t i = 0; i < n; ++i)
            result[i] = std::string(text.data() + i * length).substr(0, length);
          return result;
        }

        const std::string file_name;

      private:
        int id = -1;
      };
    } // namespace ExodusReader
#endif



    template <int dim>
    ExodusMesh<dim>
    read_exodus_file(const std::string &file_name)
    {
#ifndef PG_WITH_NETCDF
      AssertThrow(false,
                  ExcMessage("The mesh file " + file_name +
                             " given as 'File name' in subsection 'Geometry' "
                             "is an Exodus II file, and this build of pg "
                             "reads Exodus II through the netCDF library, "
                             "which was not found when pg was configured. "
                             "Install it (Debian: apt-get install "
                             "libnetcdf-dev) and configure and build pg "
                             "again, or convert the mesh to Gmsh."));
      return {};
#else
      using namespace ExodusReader;
      const File file(file_name);

      const std::size_t file_dim = file.dimension("num_dim");
      AssertThrow(file_dim == static_cast<std::size_t>(dim),
                  ExcMessage(file.message(
                    "it is a mesh of dimension " + std::to_string(file_dim) +
                      " (num_dim), and the run is in " + std::to_string(dim) +
                      "-D",
                    "Set 'Dimension = " + std::to_string(file_dim) +
                      "' at the top level of the parameter file.")));

      ExodusMesh<dim>   mesh;
      const std::size_t n_nodes = file.dimension("num_nodes");
      AssertThrow(n_nodes > 0,
                  ExcMessage(file.message("it has no nodes (num_nodes)",
                                          "Check the file.")));
      mesh.vertices.resize(n_nodes);
      if (file.has_variable("coordx"))
        {
          const char *names[3] = {"coordx", "coordy", "coordz"};
          for (unsigned int d = 0; d < dim; ++d)
            {
              const auto x = file.variable<double>(names[d], n_nodes);
              for (std::size_t i = 0; i < n_nodes; ++i)
                mesh.vertices[i][d] = x[i];
            }
        }
      else
        {
          // the older layout: coord(num_dim, num_nodes)
          const auto x = file.variable<double>("coord", dim * n_nodes);
          for (unsigned int d = 0; d < dim; ++d)
            for (std::size_t i = 0; i < n_nodes; ++i)
              mesh.vertices[i][d] = x[d * n_nodes + i];
        }

      // Element blocks. Side sets name elements by their global number
      // (1-based, the blocks in order), so keep each one's type.
      const std::size_t n_blocks  = file.dimension("num_el_blk");
      const auto        block_ids = file.has_variable("eb_prop1") ?
                                      file.variable<int>("eb_prop1", n_blocks) :
                                      std::vector<int>();
      std::vector<const ElementType *> type_of_element;
      for (std::size_t b = 0; b < n_blocks; ++b)
        {
          const std::string suffix = std::to_string(b + 1);
          const std::size_t n_elements =
            file.dimension("num_el_in_blk" + suffix);
          const int block_id =
            block_ids.empty() ? static_cast<int>(b + 1) : block_ids[b];
          if (n_elements == 0)
            continue;
          const std::size_t n_per_element =
            file.dimension("num_nod_per_el" + suffix);
          const std::string type_name =
            file.text_attribute("connect" + suffix, "elem_type");
          const ElementType *type = element_type(type_name, dim);
          const std::string  kinds =
            dim == 2 ? "QUAD4 or TRI3" : "HEX8 or TETRA4";
          AssertThrow(type != nullptr && type->n_vertices == n_per_element,
                      ExcMessage(file.message(
                        "element block " + std::to_string(block_id) +
                          " holds elements of type '" + type_name + "' with " +
                          std::to_string(n_per_element) +
                          " nodes, and pg reads linear " +
                          (dim == 2 ? "quadrilaterals and triangles " :
                                      "hexahedra and tetrahedra ") +
                          "(" + kinds + ") in " + std::to_string(dim) +
                          "-D: their vertices are the particles or the "
                          "finite element nodes" +
                          (type_name == "SPHERE" || type_name == "sphere" ?
                             ". A SPHERE block is a particle cloud without "
                             "cells, which pg cannot turn into meshfree "
                             "cells" :
                             ""),
                        "Export the body meshed with " + kinds +
                          " elements (e.g. from Cubit or Gmsh).")));
          AssertThrow(
            block_id >= 0,
            ExcMessage(file.message("element block id " +
                                      std::to_string(block_id) + " is negative",
                                    "Number the blocks from 0 or 1 on.")));
          const auto connectivity =
            file.variable<int>("connect" + suffix, n_elements * n_per_element);
          for (std::size_t e = 0; e < n_elements; ++e)
            {
              CellData<dim> cell(type->n_vertices);
              for (unsigned int v = 0; v < type->n_vertices; ++v)
                {
                  const int node =
                    connectivity[e * n_per_element + type->permutation[v]];
                  AssertThrow(
                    node >= 1 && static_cast<std::size_t>(node) <= n_nodes,
                    ExcMessage(file.message(
                      "element " + std::to_string(e + 1) + " of block " +
                        std::to_string(block_id) + " refers to node " +
                        std::to_string(node) + ", and the file has " +
                        std::to_string(n_nodes) + " nodes",
                      "Check the file.")));
                  cell.vertices[v] = node - 1;
                }
              cell.material_id = block_id;
              mesh.cells.push_back(cell);
              type_of_element.push_back(type);
            }
        }
      AssertThrow(!mesh.cells.empty(),
                  ExcMessage(
                    file.message("it has no elements", "Check the file.")));

      // Side sets: faces with the side set's id as boundary id.
      const std::size_t n_side_sets  = file.dimension("num_side_sets");
      const auto        side_set_ids = file.has_variable("ss_prop1") ?
                                         file.variable<int>("ss_prop1", n_side_sets) :
                                         std::vector<int>();
      for (std::size_t s = 0; s < n_side_sets; ++s)
        {
          const std::string suffix  = std::to_string(s + 1);
          const std::size_t n_sides = file.dimension("num_side_ss" + suffix);
          const int         id =
            side_set_ids.empty() ? static_cast<int>(s + 1) : side_set_ids[s];
          if (n_sides == 0)
            continue;
          const auto elements = file.variable<int>("elem_ss" + suffix, n_sides);
          const auto sides    = file.variable<int>("side_ss" + suffix, n_sides);
          for (std::size_t i = 0; i < n_sides; ++i)
            {
              const int element = elements[i] - 1;
              AssertThrow(
                element >= 0 &&
                  static_cast<std::size_t>(element) < mesh.cells.size(),
                ExcMessage(file.message(
                  "side set " + std::to_string(id) + " refers to element " +
                    std::to_string(elements[i]) + ", and the file has " +
                    std::to_string(mesh.cells.size()) + " elements",
                  "Check the file.")));
              const ElementType &type = *type_of_element[element];
              AssertThrow(sides[i] >= 1 && static_cast<std::size_t>(sides[i]) <=
                                             type.sides.size(),
                          ExcMessage(file.message(
                            "side set " + std::to_string(id) + " names side " +
                              std::to_string(sides[i]) + " of element " +
                              std::to_string(elements[i]),
                            "Check the file.")));
              // the file's local node n is deal.II's vertex inverse[n]
              std::vector<unsigned int> face;
              for (const unsigned int n : type.sides[sides[i] - 1])
                {
                  const auto position = std::find(type.permutation.begin(),
                                                  type.permutation.end(),
                                                  n) -
                                        type.permutation.begin();
                  face.push_back(mesh.cells[element].vertices[position]);
                }
              CellData<dim - 1> boundary_face(face.size());
              boundary_face.vertices    = face;
              boundary_face.boundary_id = id;
              if constexpr (dim == 2)
                mesh.subcelldata.boundary_lines.push_back(boundary_face);
              else
                mesh.subcelldata.boundary_quads.push_back(boundary_face);
            }
        }

      // Node sets
      const std::size_t n_node_sets    = file.dimension("num_node_sets");
      const auto        node_set_ids   = file.has_variable("ns_prop1") ?
                                           file.variable<int>("ns_prop1", n_node_sets) :
                                           std::vector<int>();
      const auto        node_set_names = file.names("ns_names", n_node_sets);
      for (std::size_t s = 0; s < n_node_sets; ++s)
        {
          const std::string suffix = std::to_string(s + 1);
          const int         id =
            node_set_ids.empty() ? static_cast<int>(s + 1) : node_set_ids[s];
          const std::string          name = node_set_names[s].empty() ?
                                              "nodelist_" + std::to_string(id) :
                                              node_set_names[s];
          const std::size_t          n = file.dimension("num_nod_ns" + suffix);
          std::vector<unsigned int> &set = mesh.node_sets[name];
          for (const int node : file.variable<int>("node_ns" + suffix, n))
            {
              AssertThrow(
                node >= 1 && static_cast<std::size_t>(node) <= n_nodes,
                ExcMessage(
                  file.message("node set " + name + " refers to node " +
                                 std::to_string(node) + ", and the file has " +
                                 std::to_string(n_nodes) + " nodes",
                               "Check the file.")));
              set.push_back(node - 1);
            }
        }
      return mesh;
#endif
    }



    template ExodusMesh<2>
    read_exodus_file<2>(const std::string &);
    template ExodusMesh<3>
    read_exodus_file<3>(const std::string &);
  } // namespace Mesh
} // namespace pg
