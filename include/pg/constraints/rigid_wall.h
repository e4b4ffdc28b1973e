#ifndef pg_constraints_rigid_wall_h
#define pg_constraints_rigid_wall_h

#include <pg/base/global.h>
#include <pg/base/linear_algebra.h>
#include <pg/constraints/boundary_condition_parameters.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>

#include <map>
#include <vector>

namespace pg
{
  /**
   * The rigid, frictionless wall of 'Boundary conditions/Rigid wall': the
   * plane n . (x - p) = 0 with n = s e_c (normal to coordinate axis c,
   * s = +-1, pointing into the body's side), and its active set, the
   * vertices (nodes, particles) held on it.
   *
   * A held vertex has its displacement component c prescribed, u_c = p_c -
   * X_c, so that n . (X + u - p) = 0; its other components are free
   * (frictionless). The constraint lines are added to those of
   * BoundaryConstraints (values()), where Dirichlet and symmetry lines on
   * the same DoF win. update() changes the set: a free vertex whose
   * position would cross the plane, n . (x - p) < 0, becomes active; an
   * active vertex whose reaction n . (f_int - f_ext) (the force the wall
   * exerts on it, positive in compression) is negative is released
   * ('Contact = unilateral'; 'two-sided' keeps it).
   *
   * Every rank keeps the vertices of its relevant DoFs and decides with
   * ghosted vectors, so that the ranks agree on shared vertices.
   */
  template <int dim>
  class RigidWall
  {
  public:
    /**
     * The wall of @p parameters (enabled) on the vertices of
     * @p dof_handler whose DoFs are in @p relevant_dofs. Throws
     * ExcBadParameter for 'Boundary conditions/Rigid wall/Point', naming
     * the vertex and its position, if a vertex lies behind the plane by
     * more than 1e-10 @p mesh_diameter. With @p hold_touching the
     * vertices that touch the plane (within that distance) start held:
     * quasi-static runs, where a body pressed onto the wall by a load
     * alone needs this support in its first solve.
     */
    RigidWall(const Parameters::BoundaryConditions::RigidWall &parameters,
              const DoFHandler<dim>                           &dof_handler,
              const IndexSet                                  &relevant_dofs,
              const IndexSet                                  &owned_dofs,
              const double                                     mesh_diameter,
              const MPI_Comm                                   comm,
              const bool hold_touching = false);

    /**
     * The prescribed values of the held DoFs: p_c - X_c, or zero if
     * @p homogeneous.
     */
    std::map<types::global_dof_index, double>
    values(const bool homogeneous) const;

    /**
     * Update the active set: activate the free vertices with n . (X + u -
     * p) < 0 at @p u (ghosted), whose DoF @p other_constraints (Dirichlet,
     * symmetry: the constraints without the wall's lines) leaves free;
     * release (unilateral) the active ones with n . @p force < 0 (f_int -
     * f_ext, owned entries; not checked if @p release is false). Returns
     * the numbers of vertices activated and released, summed over the
     * ranks (owned DoFs).
     */
    std::pair<unsigned int, unsigned int>
    update(const LinearAlgebra::Vector     &u,
           const LinearAlgebra::Vector     &force,
           const AffineConstraints<double> &other_constraints,
           const bool                       release);

    /** Zero the entries of the held DoFs in @p v (owned entries). */
    void
    hold(LinearAlgebra::Vector &v) const;

    /**
     * The wall's force on the body, sum over the held vertices of
     * (f_int - f_ext)_c e_c, from @p force (owned entries; collective).
     */
    Tensor<1, dim>
    reaction(const LinearAlgebra::Vector &force) const;

    /** Number of held vertices (collective). */
    unsigned int
    n_active() const;

    /** Which nodes are held (in the order of the wall's nodes). */
    const std::vector<bool> &
    active_set() const
    {
      return active;
    }

    /**
     * Hold the nodes of @p active_set, as active_set() returned it (a step
     * cut restores the set of the last accepted step); the caller rebuilds
     * the constraints.
     */
    void
    set_active_set(const std::vector<bool> &active_set)
    {
      AssertDimension(active_set.size(), active.size());
      active = active_set;
    }

    /** min n . (X + u - p) over all vertices, @p u ghosted (collective). */
    double
    min_gap(const LinearAlgebra::Vector &u) const;

  private:
    struct Node
    {
      Point<dim>              position;
      types::global_dof_index dof;
      bool                    owned;
    };
    std::vector<Node> nodes;
    std::vector<bool> active;
    unsigned int      component;
    double            sign;
    Point<dim>        point;
    bool              unilateral;
    MPI_Comm          comm;

    /** n . (X + u - p) of node @p i at its displacement @p u_c. */
    double
    gap(const unsigned int i, const double u_c) const
    {
      return sign * (nodes[i].position[component] + u_c - point[component]);
    }
  };
} // namespace pg

#endif
