#include <pg/solvers/time_integrator.h>

#include <algorithm>

namespace pg
{
  Newmark::Newmark(const MassMatrices       &masses,
                   const Parameters::Time   &time,
                   const Parameters::Newton &newton,
                   const ConditionalOStream &out)
    : masses(masses)
    , beta(time.beta)
    , gamma(time.gamma)
    , start_at_last_state(time.newmark_predictor == "last converged state")
    , newton(newton)
    , out(out)
  {}



  bool
  Newmark::is_explicit() const
  {
    return false;
  }



  void
  Newmark::initial_acceleration(MechanicalSystem      &system,
                                LinearAlgebra::Vector &a) const
  {
    a = 0;
    if (Utilities::MPI::sum(masses.massless.n_elements(),
                            system.communicator()) == 0)
      system.solve(masses.condensed, a, system.residual());
    else
      {
        // The pressure unknowns have no mass (a differential-algebraic
        // system): their rows get a unit diagonal and a zero right-hand
        // side, so that a = 0 there and M a = r on the displacement.
        LinearAlgebra::SparseMatrix mass;
        mass.copy_from(masses.condensed);
        LinearAlgebra::Vector r(system.residual());
        for (const auto i : masses.massless)
          {
            mass.set(i, i, 1.);
            r(i) = 0;
          }
        mass.compress(VectorOperation::insert);
        r.compress(VectorOperation::insert);
        system.solve(mass, a, r);
      }
    system.homogeneous_constraints().distribute(a);
  }



  bool
  Newmark::step(MechanicalSystem      &system,
                const double           t_new,
                const double           dt,
                LinearAlgebra::Vector &v,
                LinearAlgebra::Vector &a,
                LinearAlgebra::Vector &f_ext,
                unsigned int          &iterations)
  {
    const double c0 = 1. / (beta * dt * dt);
    system.set_time(t_new);
    system.external_force(f_ext);
    // the predictor u~ = u + dt v + dt^2 (1/2 - beta) a, i.e. a_new = 0;
    // Newton starts there or at the last converged u ('Newmark
    // predictor'), with the new Dirichlet values either way
    LinearAlgebra::Vector &u = system.displacement();
    LinearAlgebra::Vector  u_tilde(u);
    u_tilde.add(dt, v, dt * dt * (0.5 - beta), a);
    if (!start_at_last_state)
      u = u_tilde;
    system.apply_dirichlet_values();
    system.displacement_changed();

    // Newton on the effective residual: the static one plus the inertia
    // M a_new, a_new = c0 (u - u~); the tangent gains c0 M.
    const MPI_Comm        comm = system.communicator();
    LinearAlgebra::Vector a_new(system.locally_owned_dofs(), comm),
      Ma(system.locally_owned_dofs(), comm);
    double                   static_norm = 0;
    NewtonSolver::Operations operations  = system.newton_operations();
    // the static assembly (its failures already reduced over the ranks),
    // then the inertia: M a_new in the residual, c0 M in the tangent
    const auto add_inertia = [&](const std::string &failure,
                                 const bool         with_tangent) {
      if (!failure.empty())
        return failure;
      a_new = u;
      a_new -= u_tilde;
      a_new *= c0;
      masses.consistent.vmult(Ma, a_new);
      static_norm = system.residual().l2_norm();
      system.add_condensed(Ma, -1., system.residual());
      if (with_tangent)
        system.tangent().add(c0, masses.condensed);
      return std::string();
    };
    const auto assemble_static   = operations.assemble;
    const auto assemble_residual = operations.assemble_residual;
    operations.assemble          = [&]() {
      return add_inertia(assemble_static(), true);
    };
    if (assemble_residual)
      operations.assemble_residual = [&]() {
        return add_inertia(assemble_residual(), false);
      };
    system.set_tangent_mass(c0, &masses.condensed);
    operations.reference = [&](const double first) {
      return std::max({first, static_norm, Ma.l2_norm()});
    };
    NewtonSolver::Result result = NewtonSolver(newton).solve(operations);
    // A rigid wall: with the reactions of the converged step (f_int -
    // f_ext + M a_new), hold the nodes behind it, release the tensile ones
    // and solve the step again until the set stays.
    for (unsigned int round = 0; result.converged(); ++round)
      {
        LinearAlgebra::Vector reaction(system.unbalanced_force());
        reaction += Ma;
        const int changed = system.update_contact(reaction, round);
        if (changed == 0)
          break;
        if (changed < 0)
          {
            result.outcome = NewtonSolver::Outcome::too_many_iterations;
            result.failure = "the active set of the rigid wall kept changing";
            break;
          }
        const unsigned int updates = result.updates;
        result                     = NewtonSolver(newton).solve(operations);
        result.updates += updates;
      }
    system.set_tangent_mass(0, nullptr);
    last_residuals = result.residuals;
    last_failure   = result.failure;
    iterations     = result.updates;
    if (!result.converged())
      {
        NewtonSolver::report(result, out);
        return false;
      }
    v.add(dt * (1. - gamma), a, dt * gamma, a_new);
    a = a_new;
    // Massless unknowns (pressure, dilatation) are algebraic: no velocity
    // or acceleration, so that the next predictor keeps their values.
    for (const auto i : masses.massless)
      {
        v(i) = 0;
        a(i) = 0;
      }
    v.compress(VectorOperation::insert);
    a.compress(VectorOperation::insert);
    // nodes held on a rigid wall: at rest
    system.hold_at_wall(v);
    system.hold_at_wall(a);
    return true;
  }
} // namespace pg
