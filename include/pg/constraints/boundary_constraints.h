#ifndef pg_constraints_boundary_constraints_h
#define pg_constraints_boundary_constraints_h

#include <pg/base/global.h>
#include <pg/constraints/boundary_condition_parameters.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/parsed_function.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>

#include <map>
#include <string>
#include <vector>

namespace pg
{
  /**
   * The constraints of subsection 'Boundary conditions' on the vertex DoFs:
   * 'Dirichlet' faces, 'Fixed points', 'Dirichlet boxes', 'Dirichlet node
   * sets' (in this order: the
   * first condition on a DoF wins) with the values of 'Prescribed
   * displacement' at its current time, then 'Symmetry' (n . u = 0 on planar
   * boundaries, where no Dirichlet condition holds the normal component).
   * Built from all cells on every rank (parallel::shared::Triangulation
   * knows them all), so every rank has the constraints of every DoF its
   * families touch. Then the held DoFs of a rigid wall (RigidWall).
   */
  template <int dim>
  class BoundaryConstraints
  {
  public:
    /**
     * @p mesh_diameter is the scale of the geometric tolerances (fixed
     * points: 1e-8 of it, boxes: 1e-10).
     */
    BoundaryConstraints(
      const DoFHandler<dim>                &dof_handler,
      const Parameters::BoundaryConditions &boundary_conditions,
      const Functions::ParsedFunction<dim> &prescribed_displacement,
      const double                          mesh_diameter,
      const std::map<std::string, std::vector<unsigned int>> &node_sets = {});

    /**
     * Clear @p c, make it over @p relevant_dofs and close it; with
     * @p homogeneous the prescribed values are zero (Newton updates).
     * Throws ExcBadParameter naming the entry for a fixed point off the mesh,
     * an empty box, a non-planar or missing symmetry boundary, and a NaN or
     * inf prescribed value. The @p extra_values (the held DoFs of a
     * RigidWall and their values) are added last, on the DoFs that are
     * still free.
     */
    void
    make(
      const IndexSet                                  &relevant_dofs,
      const bool                                       homogeneous,
      AffineConstraints<double>                       &c,
      const std::map<types::global_dof_index, double> &extra_values = {}) const;

  private:
    const DoFHandler<dim>                &dof_handler;
    const Parameters::BoundaryConditions &boundary_conditions;
    const Functions::ParsedFunction<dim> &prescribed_displacement;
    const double                          mesh_diameter;
    const std::map<std::string, std::vector<unsigned int>> &node_sets;
  };

  /**
   * The vertex indices of the node set @p name of @p node_sets (those of
   * an Exodus II mesh file, Discretization::node_sets). Throws
   * ExcBadParameter for 'Boundary conditions/Dirichlet node sets', listing
   * the node sets there are, if the mesh has none of this name.
   */
  /**
   * For every vertex of the triangulation of @p dof_handler, an active cell
   * that has it and its index there (invalid_unsigned_int for unused
   * vertices): how the DoFs of the vertices of a node set are found.
   */
  template <int dim>
  std::vector<
    std::pair<typename DoFHandler<dim>::active_cell_iterator, unsigned int>>
  vertex_cells(const DoFHandler<dim> &dof_handler);

  const std::vector<unsigned int> &
  node_set_vertices(
    const std::string                                      &name,
    const std::map<std::string, std::vector<unsigned int>> &node_sets);
} // namespace pg

#endif
