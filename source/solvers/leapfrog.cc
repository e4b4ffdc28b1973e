#include <pg/base/exceptions.h>
#include <pg/solvers/time_integrator.h>

namespace pg
{
  Leapfrog::Leapfrog(const MassMatrices &masses)
    : masses(masses)
  {}



  bool
  Leapfrog::is_explicit() const
  {
    return true;
  }



  void
  Leapfrog::initial_acceleration(MechanicalSystem      &system,
                                 LinearAlgebra::Vector &a) const
  {
    a = system.residual();
    a.scale(masses.inverse);
  }



  bool
  Leapfrog::step(MechanicalSystem      &system,
                 const double           t_new,
                 const double           dt,
                 LinearAlgebra::Vector &v,
                 LinearAlgebra::Vector &a,
                 LinearAlgebra::Vector &f_ext,
                 unsigned int          &iterations)
  {
    iterations = 0;
    // velocity Verlet: v += dt/2 a; u += dt v; a(u); v += dt/2 a
    LinearAlgebra::Vector &u = system.displacement();
    LinearAlgebra::Vector  u_old(u);
    v.add(0.5 * dt, a);
    u.add(dt, v);
    system.set_time(t_new);
    system.apply_dirichlet_values();
    system.displacement_changed();
    system.external_force(f_ext);
    last_failure = system.assemble_residual(false);
    if (!last_failure.empty())
      return false;
    a = system.residual();
    a.scale(masses.inverse);
    v.add(0.5 * dt, a);
    // the constrained DoFs: the difference quotient
    const auto  &constraints = system.homogeneous_constraints();
    unsigned int i           = 0;
    for (const auto dof : system.locally_owned_dofs())
      {
        if (constraints.is_constrained(dof))
          v.begin()[i] = (u.begin()[i] - u_old.begin()[i]) / dt;
        ++i;
      }
    // nodes held on a rigid wall: at rest (the difference quotient of the
    // step that reached the wall is the approach velocity)
    system.hold_at_wall(v);
    return true;
  }
} // namespace pg
