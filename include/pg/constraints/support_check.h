#ifndef pg_constraints_support_check_h
#define pg_constraints_support_check_h

#include <pg/base/global.h>
#include <pg/constraints/boundary_condition_parameters.h>
#include <pg/families/family_set.h>
#include <pg/mesh/particle_set.h>

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>

#include <string>
#include <vector>

namespace pg
{
  /**
   * Checks that a static problem's boundary conditions can hold the body,
   * before Newton spends iterations on a singular tangent (issue 15,
   * items 1 and 2).
   */
  namespace SupportCheck
  {
    /**
     * Every boundary id named in 'Dirichlet', 'Neumann' and 'Neumann
     * stress' (subsection 'Boundary conditions') must exist in the mesh, and
     * no 'Neumann' or 'Neumann stress' id may also be a 'Dirichlet' id with
     * every component
     * prescribed (the traction would do no work there). Throws
     * ExcBadParameter naming the entry and the ids the mesh has.
     */
    template <int dim>
    void
    check_boundary_ids(const Parameters::BoundaryConditions &conditions,
                       const Triangulation<dim>             &triangulation);

    /**
     * One rigid body mode that the supports leave free, in one connected
     * part of the model: u(X) = t + omega x (X - centre) / radius, with the
     * coefficients (t, omega) (2-D: t_x, t_y, omega_z). The modes of a part
     * are a reduced row echelon basis: each is one translation or one
     * rotation about some axis.
     */
    template <int dim>
    struct FreeMode
    {
      unsigned int        part;
      std::vector<double> coefficients;
      Point<dim>          centre;
      double              radius;
    };

    /**
     * The rigid body modes that @p zero_constraints (the homogeneous
     * constraints of the Newton update) do not remove, per connected part
     * of the model. Parts are made of cells sharing vertices and of the
     * families of the particles (a particle is connected to its
     * neighbours). A mode r is held if some constraint line u_i = sum_j
     * a_ij u_j is violated by it: the free modes are the null space of
     * G^T G, G = (r_i - sum_j a_ij r_j) over all constrained DoFs i. Every
     * rank adds its owned lines; the result is the same on every rank.
     */
    template <int dim>
    std::vector<FreeMode<dim>>
    free_rigid_modes(const DoFHandler<dim>           &dof_handler,
                     const ParticleSet<dim>          &particles,
                     const FamilySet<dim>            &families,
                     const AffineConstraints<double> &zero_constraints,
                     const IndexSet                  &owned_dofs,
                     std::vector<Point<dim>>         &part_centres,
                     std::vector<unsigned int>       &part_sizes);

    /**
     * Throw a message that lists the free rigid body modes of every part
     * (with its size and centre) and the supports that would remove them,
     * if there are any.
     */
    template <int dim>
    void
    check_rigid_body_modes(const DoFHandler<dim>           &dof_handler,
                           const ParticleSet<dim>          &particles,
                           const FamilySet<dim>            &families,
                           const AffineConstraints<double> &zero_constraints,
                           const IndexSet                  &owned_dofs);
  } // namespace SupportCheck
} // namespace pg

#endif
