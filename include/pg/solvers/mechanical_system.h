#ifndef pg_solvers_mechanical_system_h
#define pg_solvers_mechanical_system_h

#include <pg/base/global.h>
#include <pg/base/linear_algebra.h>
#include <pg/solvers/newton_solver.h>

#include <deal.II/base/index_set.h>
#include <deal.II/lac/affine_constraints.h>

#include <optional>
#include <string>
#include <vector>

namespace pg
{
  /**
   * The masses of the time integrators: the lumped mass rho_0 int N_i of
   * every DoF (rho_0 V^k at a particle), the inverse of its diagonal
   * condensed with the homogeneous constraints (0 at constrained DoFs),
   * and, for Newmark, the consistent Q1 mass on finite element cells with
   * the particles' lumped one, unconstrained and condensed. The nodal
   * pressure and dilatation of U2P1C, Unl+P1C and the family pressure of
   * IUnlP0 carry no mass (a differential-algebraic system): their rows are
   * zero in every mass, and @p massless lists them.
   */
  struct MassMatrices
  {
    LinearAlgebra::Vector       lumped, inverse;
    LinearAlgebra::SparseMatrix consistent, condensed;
    /** The locally owned DoFs without mass (the extra nodal fields). */
    IndexSet massless;
  };

  /**
   * What the time integrators and the time stepper see of a discretized
   * problem (Problem implements it): the displacement, its constraints at
   * a time, the residual and tangent, the external force and the linear
   * solver. Vectors are distributed over the locally owned DoFs.
   */
  class MechanicalSystem
  {
  public:
    virtual ~MechanicalSystem() = default;

    virtual MPI_Comm
    communicator() const = 0;

    virtual const IndexSet &
    locally_owned_dofs() const = 0;

    /** The displacement u (owned entries). */
    virtual LinearAlgebra::Vector &
    displacement() = 0;

    /** To be called after every change of displacement(). */
    virtual void
    displacement_changed() = 0;

    /**
     * Set the time of the load and boundary functions to @p t and, if the
     * Dirichlet values depend on it, rebuild the constraints.
     */
    virtual void
    set_time(const double t) = 0;

    /** Impose the current Dirichlet values on displacement(). */
    virtual void
    apply_dirichlet_values() = 0;

    virtual const AffineConstraints<double> &
    homogeneous_constraints() const = 0;

    /**
     * Assemble residual() (and tangent() if @p with_matrix); the failure
     * on this rank, or an empty string.
     */
    virtual std::string
    assemble_residual(const bool with_matrix) = 0;

    /** -(f_int - f_ext), condensed (zero at constrained DoFs). */
    virtual LinearAlgebra::Vector &
    residual() = 0;

    /** f_int - f_ext, unconstrained (the reactions at constrained DoFs). */
    virtual const LinearAlgebra::Vector &
    unbalanced_force() const = 0;

    virtual LinearAlgebra::SparseMatrix &
    tangent() = 0;

    /**
     * Newmark: the tangent gains @p factor times @p mass (condensed) from
     * now on; the matrix an AMG hierarchy is built from ('Linear
     * solver/AMG operator = Q1 cells') gains it, too. nullptr: none. A
     * system without such a matrix ignores it.
     */
    virtual void
    set_tangent_mass(const double /*factor*/,
                     const LinearAlgebra::SparseMatrix * /*mass*/)
    {}

    /** f_ext at the current time (the loads are dead). */
    virtual void
    external_force(LinearAlgebra::Vector &f_ext) = 0;

    /** x = A^{-1} b with the solver of subsection 'Linear solver'. */
    virtual void
    solve(const LinearAlgebra::SparseMatrix &A,
          LinearAlgebra::Vector             &x,
          const LinearAlgebra::Vector       &b) = 0;

    /**
     * @p target += @p factor C^T y, with C the homogeneous constraints.
     */
    virtual void
    add_condensed(const LinearAlgebra::Vector &y,
                  const double                 factor,
                  LinearAlgebra::Vector       &target) const = 0;

    /** Newton's operations on the static residual. */
    virtual NewtonSolver::Operations
    newton_operations() = 0;

    /**
     * The plastic work of the committed state, integrated over the body
     * (energy units; collective), or nothing if the material does not
     * dissipate (Materials::Material::plastic_work_density()).
     */
    virtual std::optional<double>
    plastic_work() const
    {
      return {};
    }

    /**
     * Zero the entries of @p v (a velocity or acceleration) at the DoFs
     * held on a rigid wall (none by default).
     */
    virtual void
    hold_at_wall(LinearAlgebra::Vector &v) const
    {
      (void)v;
    }

    /**
     * The state of the contact conditions (the rigid wall's active set;
     * empty by default), to be restored by set_contact_state() when a
     * step is redone.
     */
    virtual std::vector<bool>
    contact_state() const
    {
      return {};
    }

    /** Restore what contact_state() returned, constraints included. */
    virtual void
    set_contact_state(const std::vector<bool> &state)
    {
      (void)state;
    }

    /**
     * After the converged Newton solve number @p round (0, 1, ...) of an
     * implicit time step: update the active set of a rigid wall with the
     * nodal reactions @p reaction (f_int - f_ext + M a) and, if it
     * changed, impose the new constraints on displacement(). Returns 0 if
     * the set stayed (none by default), 1 if it changed and the step is to
     * be solved again, -1 if it changed too often (the step fails).
     */
    virtual int
    update_contact(const LinearAlgebra::Vector &reaction,
                   const unsigned int           round)
    {
      (void)reaction;
      (void)round;
      return 0;
    }
  };
} // namespace pg

#endif
