#ifndef pg_dofs_field_layout_h
#define pg_dofs_field_layout_h

#include <pg/base/global.h>
#include <pg/mesh/linear_cells.h>

#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/lac/affine_constraints.h>

#include <vector>

namespace pg
{
  /**
   * The layout of the nodal fields (doc/field-layout.md): the displacement
   * u (dim Q1 components) at every vertex, plus @p n_extra_fields scalar
   * nodal fields (pressure, dilatation of the mixed families) only at the
   * particles, the vertices of the meshfree cells, interface vertices
   * included.
   *
   * One hp DoFHandler with the hp::FECollection
   * - index 0 (finite element cells): FESystem(FE_Q(1)^dim, FE_Nothing^n),
   * - index 1 (meshfree cells):       FESystem(FE_Q(1)^dim, FE_Q(1)^n).
   * With FE_Nothing(dominate = false) the extra fields of an interface
   * vertex are not constrained: they are free DoFs of the meshfree side,
   * while the displacement DoFs of the two sides are unified (one global DoF
   * per vertex and component).
   *
   * With n_extra_fields = 0 the collection is the single element
   * FESystem(FE_Q(1), dim) and no active FE index is set, which gives
   * exactly the numbering of a plain DoFHandler (the one of Problem).
   *
   * Components: 0 ... dim-1 the displacement, dim + f the extra field f.
   */
  template <int dim>
  class FieldLayout
  {
  public:
    /** FE index of the finite element (Q1) cells. */
    static constexpr unsigned int fe_cell_index = 0;
    /** FE index of the meshfree cells (used only with extra fields). */
    static constexpr unsigned int meshfree_cell_index = 1;

    /**
     * The collection for @p n_extra_fields extra scalar fields (0, 1, 2) on
     * cells of the kind of @p cells: FE_Q(1) above stands for its scalar
     * element (FE_SimplexP(1) on triangles and tetrahedra).
     */
    explicit FieldLayout(const unsigned int      n_extra_fields,
                         const LinearCells<dim> &cells = LinearCells<dim>());

    /**
     * Set the active FE indices of @p dof_handler (already reinit'ed on its
     * triangulation) from @p meshfree (indexed by active_cell_index),
     * distribute the DoFs and build the vertex tables.
     */
    void
    distribute_dofs(DoFHandler<dim>         &dof_handler,
                    const std::vector<bool> &meshfree);

    /**
     * Add the constraints the layout itself needs to @p constraints:
     * DoFTools::make_hanging_node_constraints on the hp DoFHandler. On a
     * conforming mesh deal.II 9.4 generates none at the FE_Q / FE_Nothing
     * (dominate = false) interfaces (doc/field-layout.md); on refined meshes
     * it adds the usual hanging node constraints.
     */
    void
    make_constraints(const DoFHandler<dim>     &dof_handler,
                     AffineConstraints<double> &constraints) const;

    const hp::FECollection<dim> &
    fe_collection() const;

    unsigned int
    n_extra_fields() const;

    /** dim + n_extra_fields(). */
    unsigned int
    n_components() const;

    /** The displacement, components 0 ... dim-1. */
    FEValuesExtractors::Vector
    displacement() const;

    /** Extra field @p f, component dim + f. */
    FEValuesExtractors::Scalar
    extra_field(const unsigned int f) const;

    /** The component of extra field @p f: dim + f. */
    unsigned int
    extra_field_component(const unsigned int f) const;

    /** The components 0 ... dim-1 (for interpolate_boundary_values). */
    ComponentMask
    displacement_mask() const;

    /** Component dim + f only. */
    ComponentMask
    extra_field_mask(const unsigned int f) const;

    /** Number of displacement DoFs: dim * (number of used vertices). */
    types::global_dof_index
    n_displacement_dofs() const;

    /** Number of DoFs of one extra field: the number of particles. */
    types::global_dof_index
    n_extra_field_dofs() const;

    /** The global DoF of displacement component @p c at @p vertex. */
    types::global_dof_index
    displacement_dof(const unsigned int vertex, const unsigned int c) const;

    /**
     * The global DoF of extra field @p f at @p vertex;
     * numbers::invalid_dof_index if the vertex is no particle.
     */
    types::global_dof_index
    extra_field_dof(const unsigned int vertex, const unsigned int f) const;

    /**
     * Whether @p vertex is a vertex of a meshfree cell (a particle), which
     * carries the extra fields if there are any.
     */
    bool
    carries_extra_fields(const unsigned int vertex) const;

    /**
     * The vertices of the meshfree cells in increasing vertex index: the
     * order of ParticleSet, so particle k is field_vertices()[k].
     */
    const std::vector<unsigned int> &
    field_vertices() const;

  private:
    const unsigned int                                n_fields;
    hp::FECollection<dim>                             collection;
    std::vector<std::vector<types::global_dof_index>> u_dofs;
    std::vector<std::vector<types::global_dof_index>> field_dofs;
    std::vector<bool>                                 is_field_vertex;
    std::vector<unsigned int>                         vertices_with_fields;
    types::global_dof_index                           n_u_dofs = 0;
  };
} // namespace pg

#endif
