#include <pg/base/exceptions.h>
#include <pg/constraints/boundary_constraints.h>

#include <deal.II/grid/grid_tools.h>

#include <array>
#include <cmath>
#include <sstream>

namespace pg
{
  namespace
  {
    /** Unit normal of a planar face from its vertices (sign irrelevant). */
    template <typename CellIterator>
    auto
    planar_face_normal(const CellIterator &cell, const unsigned int f)
    {
      constexpr int  dim  = CellIterator::AccessorType::dimension;
      const auto     face = cell->face(f);
      Tensor<1, dim> n;
      if constexpr (dim == 2)
        {
          const Tensor<1, dim> e = face->vertex(1) - face->vertex(0);
          n[0]                   = e[1];
          n[1]                   = -e[0];
        }
      else
        n = cross_product_3d(face->vertex(1) - face->vertex(0),
                             face->vertex(2) - face->vertex(0));
      return n / n.norm();
    }
  } // namespace



  template <int dim>
  BoundaryConstraints<dim>::BoundaryConstraints(
    const DoFHandler<dim>                &dof_handler,
    const Parameters::BoundaryConditions &boundary_conditions,
    const Functions::ParsedFunction<dim> &prescribed_displacement,
    const double                          mesh_diameter,
    const std::map<std::string, std::vector<unsigned int>> &node_sets)
    : dof_handler(dof_handler)
    , boundary_conditions(boundary_conditions)
    , prescribed_displacement(prescribed_displacement)
    , mesh_diameter(mesh_diameter)
    , node_sets(node_sets)
  {}



  template <int dim>
  std::vector<
    std::pair<typename DoFHandler<dim>::active_cell_iterator, unsigned int>>
  vertex_cells(const DoFHandler<dim> &dof_handler)
  {
    std::vector<
      std::pair<typename DoFHandler<dim>::active_cell_iterator, unsigned int>>
      result(dof_handler.get_triangulation().n_vertices(),
             {dof_handler.end(), numbers::invalid_unsigned_int});
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (result[cell->vertex_index(v)].second ==
            numbers::invalid_unsigned_int)
          result[cell->vertex_index(v)] = {cell, v};
    return result;
  }



  const std::vector<unsigned int> &
  node_set_vertices(
    const std::string                                      &name,
    const std::map<std::string, std::vector<unsigned int>> &node_sets)
  {
    const auto it = node_sets.find(name);
    if (it == node_sets.end())
      {
        std::string available;
        for (const auto &[set_name, vertices] : node_sets)
          available += (available.empty() ? "" : ", ") + set_name + " (" +
                       std::to_string(vertices.size()) + " vertices)";
        AssertThrow(
          false,
          ExcBadParameter("Boundary conditions/Dirichlet node sets",
                          name,
                          node_sets.empty() ?
                            "the mesh has no node sets: they come from Exodus "
                            "II mesh files (.g, .e, .exo as 'File name' in "
                            "subsection 'Geometry'). Use 'Dirichlet' (boundary "
                            "ids) or 'Dirichlet boxes' instead." :
                            "the mesh file has no node set of this name; its "
                            "node sets are " +
                              available + "."));
      }
    return it->second;
  }



  template <int dim>
  void
  BoundaryConstraints<dim>::make(
    const IndexSet                                  &relevant_dofs,
    const bool                                       homogeneous,
    AffineConstraints<double>                       &c,
    const std::map<types::global_dof_index, double> &extra_values) const
  {
    const auto &triangulation = dof_handler.get_triangulation();
    // Built from all cells on every rank (parallel::shared::Triangulation
    // knows them all), for the DoFs in @p relevant_dofs: every DoF that this
    // rank's families and cells touch. A vertex's DoFs are all relevant or
    // none, and each decision below reads only its own vertex's lines, so
    // the lines kept are the same as with all DoFs.
    c.clear();
    c.reinit(relevant_dofs);

    // The components in @p mask of vertex v of @p object (a cell or a face
    // of @p cell) take the prescribed values, unless they are constrained
    // already. (The FE index: with extra nodal fields the DoFHandler is an
    // hp one, dofs/field_layout.h.)
    const auto prescribe = [&](const auto              &cell,
                               const auto              &object,
                               const unsigned int       v,
                               const std::vector<bool> &mask) {
      for (unsigned int comp = 0; comp < dim; ++comp)
        if (mask[comp])
          {
            const types::global_dof_index dof =
              object->vertex_dof_index(v, comp, cell->active_fe_index());
            if (!relevant_dofs.is_element(dof) || c.is_constrained(dof))
              continue;
            c.add_line(dof);
            if (!homogeneous)
              {
                const double value =
                  prescribed_displacement.value(object->vertex(v), comp);
                if (!std::isfinite(value))
                  {
                    std::ostringstream where;
                    where << object->vertex(v);
                    AssertThrow(
                      false,
                      ExcMessage(
                        "The 'Prescribed displacement' function "
                        "of subsection 'Boundary conditions' is "
                        "NaN or inf at (" +
                        where.str() + "), component " +
                        std::string(1, "xyz"[comp]) + ", load factor " +
                        std::to_string(prescribed_displacement.get_time()) +
                        "."));
                  }
                c.set_inhomogeneity(dof, value);
              }
          }
    };

    // Dirichlet first: where a Dirichlet and a symmetry condition meet, the
    // Dirichlet value wins.
    for (const auto &[id, mask] : boundary_conditions.dirichlet)
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == id)
            for (const unsigned int v : cell->face(f)->vertex_indices())
              prescribe(cell, cell->face(f), v, mask);

    for (const auto &[coordinates, mask] : boundary_conditions.fixed_points)
      {
        Point<dim> p;
        for (unsigned int d = 0; d < dim; ++d)
          p[d] = coordinates[d];
        const unsigned int vertex =
          GridTools::find_closest_vertex(dof_handler, p);
        const double tolerance = 1e-8 * mesh_diameter;
        AssertThrow(
          triangulation.get_vertices()[vertex].distance(p) <= tolerance,
          ExcBadParameter(
            "Boundary conditions/Fixed points",
            std::to_string(p[0]) + ", " + std::to_string(p[1]) +
              (dim == 3 ? ", " + std::to_string(p[2]) : std::string()),
            "no mesh vertex lies at this point; the "
            "nearest one is at distance " +
              std::to_string(triangulation.get_vertices()[vertex].distance(p)) +
              "."));
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
            if (cell->vertex_index(v) == vertex)
              {
                prescribe(cell, cell, v, mask);
                break;
              }
      }

    const double box_tolerance = 1e-10 * mesh_diameter;
    for (const auto &box : boundary_conditions.dirichlet_boxes)
      {
        const auto inside = [&](const Point<dim> &p) {
          for (unsigned int d = 0; d < dim; ++d)
            if (p[d] < box.lower[d] - box_tolerance ||
                p[d] > box.upper[d] + box_tolerance)
              return false;
          return true;
        };
        bool found = false;
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
            if (inside(cell->vertex(v)))
              {
                found = true;
                prescribe(cell, cell, v, box.components);
              }
        std::string corners;
        for (const auto *corner : {&box.lower, &box.upper})
          {
            corners += corners.empty() ? "" : " : ";
            for (unsigned int d = 0; d < dim; ++d)
              corners += (d ? ", " : "") + std::to_string((*corner)[d]);
          }
        AssertThrow(found,
                    ExcBadParameter("Boundary conditions/Dirichlet boxes",
                                    corners,
                                    "a box holds no mesh vertex; enlarge it "
                                    "or check its corners against the "
                                    "geometry."));
      }

    if (!boundary_conditions.dirichlet_node_sets.empty())
      {
        const auto vertex_cell = vertex_cells(dof_handler);
        for (const auto &[name, mask] : boundary_conditions.dirichlet_node_sets)
          for (const unsigned int vertex : node_set_vertices(name, node_sets))
            {
              const auto &[cell, v] = vertex_cell[vertex];
              Assert(v != numbers::invalid_unsigned_int, ExcInternalError());
              prescribe(cell, cell, v, mask);
            }
      }

    for (const types::boundary_id id : boundary_conditions.symmetry)
      {
        // The plane's normal, checked to be the same on every face.
        Tensor<1, dim> normal;
        bool           found = false;
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == id)
              {
                const Tensor<1, dim> n = planar_face_normal(cell, f);
                if (!found)
                  normal = n, found = true;
                AssertThrow(
                  std::abs(std::abs(n * normal) - 1.) < 1e-8,
                  ExcBadParameter("Boundary conditions/Symmetry",
                                  std::to_string(id),
                                  "a symmetry boundary must be planar, but the "
                                  "faces of this boundary id have different "
                                  "normals."));
              }
        AssertThrow(found,
                    ExcBadParameter("Boundary conditions/Symmetry",
                                    std::to_string(id),
                                    "no boundary face has this id."));
        // n . u = 0: solve for the component with the largest |n_c| that
        // is still free.
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == id)
              for (const unsigned int v : cell->face(f)->vertex_indices())
                {
                  std::array<types::global_dof_index, dim> dofs;
                  for (unsigned int comp = 0; comp < dim; ++comp)
                    dofs[comp] =
                      cell->face(f)->vertex_dof_index(v,
                                                      comp,
                                                      cell->active_fe_index());
                  if (!relevant_dofs.is_element(dofs[0]))
                    continue;
                  int pivot = -1;
                  for (unsigned int comp = 0; comp < dim; ++comp)
                    if (!c.is_constrained(dofs[comp]) &&
                        std::abs(normal[comp]) > 1e-12 &&
                        (pivot < 0 ||
                         std::abs(normal[comp]) > std::abs(normal[pivot])))
                      pivot = comp;
                  bool already = false;
                  for (unsigned int comp = 0; comp < dim; ++comp)
                    if (std::abs(normal[comp]) > 1e-12 &&
                        c.is_constrained(dofs[comp]) &&
                        std::abs(normal[comp]) > 1. - 1e-12)
                      already = true;
                  if (pivot < 0 || already)
                    continue;
                  c.add_line(dofs[pivot]);
                  for (unsigned int comp = 0; comp < dim; ++comp)
                    if (static_cast<int>(comp) != pivot &&
                        std::abs(normal[comp]) > 1e-12)
                      c.add_entry(dofs[pivot],
                                  dofs[comp],
                                  -normal[comp] / normal[pivot]);
                }
      }
    // the rigid wall's held DoFs, where no other condition holds them
    for (const auto &[dof, value] : extra_values)
      if (relevant_dofs.is_element(dof) && !c.is_constrained(dof))
        {
          c.add_line(dof);
          if (!homogeneous)
            c.set_inhomogeneity(dof, value);
        }
    c.close();
  }



  template class BoundaryConstraints<2>;
  template class BoundaryConstraints<3>;
  template std::vector<
    std::pair<typename DoFHandler<2>::active_cell_iterator, unsigned int>>
  vertex_cells(const DoFHandler<2> &);
  template std::vector<
    std::pair<typename DoFHandler<3>::active_cell_iterator, unsigned int>>
  vertex_cells(const DoFHandler<3> &);
} // namespace pg
