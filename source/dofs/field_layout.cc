#include <pg/dofs/field_layout.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/tria.h>

namespace pg
{
  template <int dim>
  FieldLayout<dim>::FieldLayout(const unsigned int      n_extra_fields,
                                const LinearCells<dim> &cells)
    : n_fields(n_extra_fields)
  {
    AssertThrow(n_extra_fields <= 2,
                ExcMessage("FieldLayout: at most 2 extra nodal fields "
                           "(pressure, dilatation), not " +
                           std::to_string(n_extra_fields)));
    const FiniteElement<dim> &p1 = cells.scalar_element();
    if (n_fields == 0)
      // Exactly the element of Problem: the numbering is that of a plain
      // DoFHandler.
      collection.push_back(FESystem<dim>(p1, dim));
    else
      {
        // FE_Nothing(dominate = false): no continuity requirement at the
        // interface, so the extra fields of interface vertices stay free.
        collection.push_back(
          FESystem<dim>(p1,
                        dim,
                        FE_Nothing<dim>(cells.reference_cell(), 1, false),
                        n_fields));
        collection.push_back(FESystem<dim>(p1, dim, p1, n_fields));
      }
  }



  template <int dim>
  void
  FieldLayout<dim>::distribute_dofs(DoFHandler<dim>         &dof_handler,
                                    const std::vector<bool> &meshfree)
  {
    const Triangulation<dim> &tria = dof_handler.get_triangulation();
    AssertDimension(meshfree.size(), tria.n_active_cells());

    // (set on the owned cells; deal.II sends them to the ghosts)
    if (n_fields > 0)
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          cell->set_active_fe_index(meshfree[cell->active_cell_index()] ?
                                      meshfree_cell_index :
                                      fe_cell_index);
    dof_handler.distribute_dofs(collection);

    const unsigned int n_vertices = tria.n_vertices();
    u_dofs.assign(
      n_vertices,
      std::vector<types::global_dof_index>(dim, numbers::invalid_dof_index));
    field_dofs.assign(
      n_vertices,
      std::vector<types::global_dof_index>(n_fields,
                                           numbers::invalid_dof_index));
    is_field_vertex.assign(n_vertices, false);

    // All DoFs of both elements sit on vertices, ordered vertex by vertex
    // (FESystem numbers by geometric object first).
    std::vector<types::global_dof_index> dofs;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (cell->is_artificial())
          continue;
        const FiniteElement<dim> &fe         = cell->get_fe();
        const unsigned int        per_vertex = fe.n_dofs_per_vertex();
        Assert(fe.n_dofs_per_cell() == per_vertex * cell->n_vertices(),
               ExcInternalError());
        dofs.resize(fe.n_dofs_per_cell());
        cell->get_dof_indices(dofs);
        const bool is_meshfree = meshfree[cell->active_cell_index()];
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            const unsigned int vertex = cell->vertex_index(i / per_vertex);
            const unsigned int component =
              fe.system_to_component_index(i).first;
            auto &entry =
              (component < dim ? u_dofs[vertex][component] :
                                 field_dofs[vertex][component - dim]);
            Assert(entry == numbers::invalid_dof_index || entry == dofs[i],
                   ExcMessage("FieldLayout: a vertex with two global DoFs for "
                              "one component"));
            entry = dofs[i];
          }
        if (is_meshfree)
          for (const unsigned int v : cell->vertex_indices())
            is_field_vertex[cell->vertex_index(v)] = true;
      }

    vertices_with_fields.clear();
    n_u_dofs = 0;
    for (unsigned int v = 0; v < n_vertices; ++v)
      {
        if (is_field_vertex[v])
          vertices_with_fields.push_back(v);
        if (u_dofs[v][0] != numbers::invalid_dof_index)
          n_u_dofs += dim;
      }
  }



  template <int dim>
  void
  FieldLayout<dim>::make_constraints(
    const DoFHandler<dim>     &dof_handler,
    AffineConstraints<double> &constraints) const
  {
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
  }



  template <int dim>
  const hp::FECollection<dim> &
  FieldLayout<dim>::fe_collection() const
  {
    return collection;
  }



  template <int dim>
  unsigned int
  FieldLayout<dim>::n_extra_fields() const
  {
    return n_fields;
  }



  template <int dim>
  unsigned int
  FieldLayout<dim>::n_components() const
  {
    return dim + n_fields;
  }



  template <int dim>
  FEValuesExtractors::Vector
  FieldLayout<dim>::displacement() const
  {
    return FEValuesExtractors::Vector(0);
  }



  template <int dim>
  FEValuesExtractors::Scalar
  FieldLayout<dim>::extra_field(const unsigned int f) const
  {
    return FEValuesExtractors::Scalar(extra_field_component(f));
  }



  template <int dim>
  unsigned int
  FieldLayout<dim>::extra_field_component(const unsigned int f) const
  {
    AssertIndexRange(f, n_fields);
    return dim + f;
  }



  template <int dim>
  ComponentMask
  FieldLayout<dim>::displacement_mask() const
  {
    std::vector<bool> mask(n_components(), false);
    for (unsigned int c = 0; c < dim; ++c)
      mask[c] = true;
    return ComponentMask(mask);
  }



  template <int dim>
  ComponentMask
  FieldLayout<dim>::extra_field_mask(const unsigned int f) const
  {
    std::vector<bool> mask(n_components(), false);
    mask[extra_field_component(f)] = true;
    return ComponentMask(mask);
  }



  template <int dim>
  types::global_dof_index
  FieldLayout<dim>::n_displacement_dofs() const
  {
    return n_u_dofs;
  }



  template <int dim>
  types::global_dof_index
  FieldLayout<dim>::n_extra_field_dofs() const
  {
    return n_fields == 0 ? 0 : vertices_with_fields.size();
  }



  template <int dim>
  types::global_dof_index
  FieldLayout<dim>::displacement_dof(const unsigned int vertex,
                                     const unsigned int c) const
  {
    AssertIndexRange(vertex, u_dofs.size());
    AssertIndexRange(c, dim);
    return u_dofs[vertex][c];
  }



  template <int dim>
  types::global_dof_index
  FieldLayout<dim>::extra_field_dof(const unsigned int vertex,
                                    const unsigned int f) const
  {
    AssertIndexRange(vertex, field_dofs.size());
    AssertIndexRange(f, n_fields);
    return field_dofs[vertex][f];
  }



  template <int dim>
  bool
  FieldLayout<dim>::carries_extra_fields(const unsigned int vertex) const
  {
    AssertIndexRange(vertex, is_field_vertex.size());
    return is_field_vertex[vertex];
  }



  template <int dim>
  const std::vector<unsigned int> &
  FieldLayout<dim>::field_vertices() const
  {
    return vertices_with_fields;
  }



  template class FieldLayout<2>;
  template class FieldLayout<3>;
} // namespace pg
