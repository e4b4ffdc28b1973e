#ifndef pg_solvers_time_integrator_h
#define pg_solvers_time_integrator_h

#include <pg/base/global.h>
#include <pg/base/parameters.h>
#include <pg/solvers/mechanical_system.h>
#include <pg/solvers/newton_solver.h>

#include <deal.II/base/conditional_ostream.h>

#include <memory>
#include <string>

namespace pg
{
  /**
   * One step of a time integrator for M a + f_int(u) - f_ext(t) = 0, from
   * (u, v, a) at t to t_new = t + dt. On success the system's displacement,
   * @p v and @p a hold the new state and @p f_ext the new external force.
   */
  class TimeIntegrator
  {
  public:
    virtual ~TimeIntegrator() = default;

    /** Does it need the consistent mass (implicit) or the lumped one? */
    virtual bool
    is_explicit() const = 0;

    /** The acceleration at the start from the residual of the system. */
    virtual void
    initial_acceleration(MechanicalSystem      &system,
                         LinearAlgebra::Vector &a) const = 0;

    /**
     * One step; false if it failed (Newmark: Newton did not converge;
     * leapfrog: the assembly failed), with the reason in last_failure. May
     * throw if a load cannot be evaluated.
     */
    virtual bool
    step(MechanicalSystem      &system,
         const double           t_new,
         const double           dt,
         LinearAlgebra::Vector &v,
         LinearAlgebra::Vector &a,
         LinearAlgebra::Vector &f_ext,
         unsigned int          &iterations) = 0;

    /** The Newton residuals of the last step (empty for explicit ones). */
    std::vector<double> last_residuals;
    /** Why the last step failed. */
    std::string last_failure;
  };

  /** 'Time/Integrator = leapfrog': velocity Verlet with the lumped mass. */
  class Leapfrog : public TimeIntegrator
  {
  public:
    explicit Leapfrog(const MassMatrices &masses);

    bool
    is_explicit() const override;

    void
    initial_acceleration(MechanicalSystem      &system,
                         LinearAlgebra::Vector &a) const override;

    bool
    step(MechanicalSystem      &system,
         const double           t_new,
         const double           dt,
         LinearAlgebra::Vector &v,
         LinearAlgebra::Vector &a,
         LinearAlgebra::Vector &f_ext,
         unsigned int          &iterations) override;

  private:
    const MassMatrices &masses;
  };

  /**
   * 'Time/Integrator = newmark': implicit Newmark (beta, gamma), Newton's
   * method (NewtonSolver) on M a(u) + f_int(u) - f_ext = 0 with the
   * effective tangent K + M / (beta dt^2). Newton starts each step at the
   * Newmark predictor u~ = u + dt v + dt^2 (1/2 - beta) a (a_new = 0) or,
   * with 'Newmark predictor = last converged state', at u (the converged
   * state of the last step); both with the new Dirichlet values.
   */
  class Newmark : public TimeIntegrator
  {
  public:
    Newmark(const MassMatrices       &masses,
            const Parameters::Time   &time,
            const Parameters::Newton &newton,
            const ConditionalOStream &out);

    bool
    is_explicit() const override;

    void
    initial_acceleration(MechanicalSystem      &system,
                         LinearAlgebra::Vector &a) const override;

    bool
    step(MechanicalSystem      &system,
         const double           t_new,
         const double           dt,
         LinearAlgebra::Vector &v,
         LinearAlgebra::Vector &a,
         LinearAlgebra::Vector &f_ext,
         unsigned int          &iterations) override;

  private:
    const MassMatrices &masses;
    const double        beta, gamma;
    /** 'Newmark predictor = last converged state' */
    const bool                start_at_last_state;
    const Parameters::Newton &newton;
    const ConditionalOStream &out;
  };
} // namespace pg

#endif
