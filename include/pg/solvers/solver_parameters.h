#ifndef pg_solvers_solver_parameters_h
#define pg_solvers_solver_parameters_h

#include <pg/base/global.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <utility>
#include <vector>

// The parameters of the solvers: load stepping (subsection "Loading"),
// the Newton iteration ("Newton"), the linear solver ("Linear solver")
// and the time integrators ("Time").

namespace pg
{
  namespace Parameters
  {
    /** Subsection "Loading". */
    struct Loading
    {
      unsigned int load_steps;
      unsigned int maximum_step_cuts;
      /**
       * A cut step grows again (doubles, up to the load step) after a
       * sub-step that converged in at most this many Newton iterations.
       */
      unsigned int easy_iterations;
      /**
       * Start each step with a linearized predictor for the Dirichlet
       * increment ('Predictor = linearized') instead of setting the new
       * boundary values alone.
       */
      bool linearized_predictor = false;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** Subsection "Newton". */
    struct Newton
    {
      unsigned int maximum_iterations;
      double       relative_tolerance;
      double       absolute_tolerance;
      /** See NewtonSolver: the round-off stagnation test (0: off). */
      double stagnation_tolerance;
      /**
       * 'Condensed fields': true (linearized, the default) keeps the
       * condensed p and Theta of mixed elements as Newton iterates;
       * false recomputes them from u at every iterate (closed form).
       */
      bool linearized_condensed_fields;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** Subsection "Linear solver". */
    struct LinearSolver
    {
      /** direct | cg | gmres */
      std::string type;
      double      tolerance;
      /** ML's near-null space: rigid body modes | translations */
      std::string near_null_space;
      /** Keep ML's hierarchy between solves (entry 'Reuse AMG'). */
      bool reuse_amg;
      /** The matrix of ML's hierarchy: automatic | tangent | Q1 cells. */
      std::string amg_operator;
      /** The VC correction system: automatic | direct */
      std::string vc_solver;
      /**
       * ML parameters that replace pg's (entry 'AMG parameters'), as
       * (name, value) in the order given; the values are still text.
       */
      std::vector<std::pair<std::string, std::string>> amg_parameters;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /**
     * Subsection "Time": quasi-static load stepping (the default) or
     * dynamics with an explicit or implicit time integrator. The initial
     * conditions are in AllParameters.
     */
    struct Time
    {
      /** none | leapfrog | newmark */
      std::string integrator;
      double      end_time;
      /** 0: the stable time step estimate times 'Safety factor'. */
      double time_step;
      double safety_factor;
      /** 0: every step. */
      double output_interval;
      double beta;
      double gamma;
      /** fixed | adaptive (Newmark: cut on failure, grow after easy steps) */
      std::string step_control;
      /** 0: 1e-3 times the initial step. */
      double minimum_time_step;
      /** 0: the initial step. */
      double maximum_time_step;
      /** A step is easy if Newton converged in at most so many updates. */
      unsigned int easy_step_iterations;
      double       step_growth_factor;
      /** Leapfrog: re-estimate 2 / omega_max every so many steps (0: never). */
      unsigned int stable_step_update_interval;
      /** newmark | last converged state: where Newton starts a step */
      std::string newmark_predictor;

      /** Is an integrator selected (not quasi-static load stepping)? */
      bool
      dynamic() const;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace pg

#endif
