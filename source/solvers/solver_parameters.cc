#include <pg/base/exceptions.h>
#include <pg/solvers/linear_solver.h>
#include <pg/solvers/solver_parameters.h>

#include <deal.II/base/utilities.h>

#include <Teuchos_ParameterList.hpp>

#include <sstream>
#include <string>

namespace pg
{
  namespace Parameters
  {
    void
    Loading::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Loading");
      {
        prm.declare_entry("Load steps",
                          "1",
                          Patterns::Integer(1),
                          "Number of equal load steps; the load factor t "
                          "runs from 0 to 1.");
        prm.declare_entry("Maximum step cuts",
                          "5",
                          Patterns::Integer(0, 30),
                          "A load step whose Newton iteration diverges is "
                          "halved and repeated, at most this often per load "
                          "step. A step whose residual stalls on its "
                          "round-off floor before and after a cut stops the "
                          "run at once (see 'Newton/Stagnation tolerance').");
        prm.declare_entry("Easy step iterations",
                          "4",
                          Patterns::Integer(0),
                          "After a cut, a sub-step that converges in at most "
                          "this many Newton iterations doubles the next "
                          "sub-step again (never beyond the rest of the load "
                          "step). 0: a cut step stays small.");
        prm.declare_entry(
          "Predictor",
          "boundary values",
          Patterns::Selection("boundary values|linearized"),
          "How a load step starts. 'boundary values': the new Dirichlet "
          "values are set on their nodes and Newton starts there, the rest "
          "at the last converged state (a large step can invert the cells "
          "next to a moved boundary before the first iteration). "
          "'linearized': the first iteration solves the tangent system of "
          "the last converged state for the Dirichlet increment (an "
          "inhomogeneous constraint, as in deal.II's step-44), so the whole "
          "body follows the boundary; it costs one assembly and one solve "
          "more per step.");
      }
      prm.leave_subsection();
    }



    void
    Loading::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Loading");
      {
        load_steps           = prm.get_integer("Load steps");
        maximum_step_cuts    = prm.get_integer("Maximum step cuts");
        easy_iterations      = prm.get_integer("Easy step iterations");
        linearized_predictor = (prm.get("Predictor") == "linearized");
      }
      prm.leave_subsection();
    }



    void
    Newton::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Newton");
      {
        prm.declare_entry("Maximum iterations",
                          "20",
                          Patterns::Integer(1),
                          "Newton iterations per load step before the step "
                          "counts as diverged.");
        prm.declare_entry("Relative tolerance",
                          "1e-10",
                          Patterns::Double(0.),
                          "Converged when |R| <= this x |R| of the first "
                          "iteration of the step, ...");
        prm.declare_entry("Absolute tolerance",
                          "1e-12",
                          Patterns::Double(0.),
                          "... or when |R| <= this (force units).");
        prm.declare_entry(
          "Stagnation tolerance",
          "1e-6",
          Patterns::Double(0., 1.),
          "Also converged (at round-off) when the residual has stalled below "
          "this x |R| of the first iteration: the last update reduced |R| by "
          "less than a factor 2 and its energy |du . R| was below the square "
          "of this x that of the first update. The assembly and the linear "
          "solver leave a floor of eps times the element forces, which "
          "near-incompressible materials raise far above 'Relative "
          "tolerance' (Cook's membrane at nu = 0.4999: 1e-9 to 1e-7). 0 "
          "switches the test off.");
        prm.declare_entry(
          "Condensed fields",
          "linearized",
          Patterns::Selection("linearized|equilibrium"),
          "How the mixed formulations (UnlP0, U2P1, FEM Q1P0/H1P0) treat "
          "their condensed pressure p and dilatation Theta between Newton "
          "iterations. 'linearized': p and Theta are unknowns of Newton's "
          "method, updated after each global solve by the linearized local "
          "equations (the dissertation's local update, pg-methods section "
          "12.2; deal.II's step-44); Newton then solves the three-field "
          "system, whose convergence does not degrade as nu -> 0.5. "
          "'equilibrium': p and Theta are recomputed from the displacement "
          "at every iterate (Theta = mean J, p = W_vol'(Theta)): the same "
          "solution, but Newton's method then sees a penalty term K (J - "
          "1) and needs load steps that shrink with mu/K. Explicit "
          "dynamics always uses 'equilibrium'.");
      }
      prm.leave_subsection();
    }



    void
    Newton::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Newton");
      {
        maximum_iterations   = prm.get_integer("Maximum iterations");
        relative_tolerance   = prm.get_double("Relative tolerance");
        absolute_tolerance   = prm.get_double("Absolute tolerance");
        stagnation_tolerance = prm.get_double("Stagnation tolerance");
        linearized_condensed_fields =
          (prm.get("Condensed fields") == "linearized");
      }
      prm.leave_subsection();
    }



    void
    LinearSolver::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      {
        prm.declare_entry("Type",
                          "direct",
                          Patterns::Selection("direct|cg|gmres"),
                          "direct: Trilinos Amesos with MUMPS (KLU if "
                          "Trilinos lacks MUMPS). cg (symmetric "
                          "tangents only: FEM and PBG with hyperelastic "
                          "materials) or gmres, both preconditioned by "
                          "Trilinos ML algebraic multigrid.");
        prm.declare_entry("Tolerance",
                          "1e-10",
                          Patterns::Double(0.),
                          "Relative residual reduction of cg and gmres.");
        prm.declare_entry(
          "AMG near-null space",
          "rigid body modes",
          Patterns::Selection("rigid body modes|translations"),
          "The near-null space that ML's smoothed aggregation interpolates "
          "exactly on every coarse level (cg and gmres): 'rigid body modes' "
          "(dim translations and the rotations about the centroid of the "
          "mesh, 3 in 2-D, 6 in 3-D, from the vertex and particle "
          "positions), or 'translations' (dim constant modes, deal.II's "
          "default for vector problems).");
        prm.declare_entry(
          "Reuse AMG",
          "true",
          Patterns::Bool(),
          "cg and gmres: keep ML's multigrid hierarchy from one linear "
          "solve to the next (Newton iterations and load steps) and apply "
          "it to the new tangent, instead of building it for every solve. "
          "It is rebuilt when a solve needs more than 1.5 times (plus 5) "
          "the Krylov iterations of the first solve with it, when a solve "
          "with it does not converge (that solve is then repeated with a "
          "new hierarchy), and when the sparsity pattern changes. The "
          "solution is the same to the 'Tolerance'; only the iteration "
          "counts differ. Saves the ML set-up, up to half of a solve on "
          "wide PG stencils (doc/benchmarks/scaling.md).");
        prm.declare_entry(
          "AMG operator",
          "automatic",
          Patterns::Selection("automatic|tangent|Q1 cells"),
          "cg and gmres: the matrix ML builds its multigrid hierarchy from. "
          "tangent: the Newton tangent. Q1 cells: the tangent of Q1 "
          "elements (Q1P0 / H1P0 for the mixed codes; P1 elements on "
          "triangle and tetrahedron meshes) on every cell of the "
          "mesh, at the same displacement and on the same DoFs (the "
          "particles are the vertices of the meshfree cells), with "
          "Newmark's c0 M added: the FE tangent on the particles, "
          "about 3 times sparser than a PG tangent at 1.51 h in 3-D and "
          "close to it in energy. The Krylov method still solves with the "
          "PG tangent; only the preconditioner comes from the sparser "
          "matrix. CG needs about twice the iterations, each cheaper; GMRES "
          "on PPG tangents often fewer: Peridigm's tensile bar, BCPBG Unl, "
          "solve 14.7 s -> 5.0 s; 3-D cantilever, VCBCPPG V3sn Unl, 56,355 "
          "DoFs, 16.2 s -> 9.9 s; implicit Newmark, VCBCPPG V3sn Unl, "
          "13,122 DoFs, 161 s -> 6.5 s (doc/benchmarks/amg_operator.md). "
          "Where a Q1 cell fails at "
          "the current displacement (inverted), or where CG/GMRES with the "
          "Q1 hierarchy does not converge in 1000 iterations, the hierarchy "
          "is built from the tangent (and the solve repeated). automatic: Q1 cells for the PG displacement codes "
          "(Unl, U2, U1SIG, U1SUnl; PBG and PPG) with particles from 10,000 "
          "DoFs on; the tangent otherwise: FE everywhere; small systems, "
          "where the tangent's hierarchy needs a fifth of the iterations; "
          "mixed codes, where the Q1P0 / H1P0 hierarchy needs 2 to 4 times "
          "the iterations at nu = 0.49; the classical correspondence (U1, "
          "with hourglass force: 1.7 times slower), CPD, and triangle and "
          "tetrahedron meshes, where the P1 hierarchy needed 4 to 8 times "
          "the tangent's iterations (18,818 DoFs on triangles). With "
          "automatic, a first solve that needs more than 250 iterations with "
          "the Q1 hierarchy is repeated once with the tangent's, and the "
          "faster of the two (wall time) is kept for the run: on B-12's "
          "irregular particles (3-D Cook, 29,403 DoFs) the Q1 hierarchy "
          "needed 486 CG iterations per solve and the tangent's 85, 1.9 "
          "times faster.");
        prm.declare_entry(
          "VC solver",
          "automatic",
          Patterns::Selection("automatic|ilu|amg|direct"),
          "How the VC correction system (the factors alpha, section 5.3.2; "
          "VC codes only) is solved, once per total Lagrangian set-up. "
          "automatic: GMRES to |b - A alpha| <= 1e-13 |b| where the system "
          "is regular (meshfree everywhere, or coupled without a free "
          "surface of the meshfree region, or option p), preconditioned by "
          "ILU(0) below 100,000 unknowns and from there first by ML AMG "
          "(non-symmetric smoothed aggregation, ILU smoothing), which gives "
          "way to ILU(0) (with a note) if it has not reached 1e-4 |b| after "
          "100 iterations or its true residual misses; the direct solver "
          "where the system is singular (FE coupling plus a free surface: "
          "GMRES would return factors with an arbitrary null-space part) "
          "and where GMRES does not converge in 2000 iterations (with a "
          "note). ilu, amg: GMRES with that preconditioner where the system "
          "is regular, at every size. On the 3-D cantilever ILU(0) needs "
          "99 / 241 iterations and AMG 32 / 53 at 56,355 / 421,443 unknowns "
          "(20.9 against 12.5 s at the larger); on the 3-D Cook membrane "
          "the AMG breaks down. direct: "
          "always KLU on one MPI rank, MUMPS on more, with "
          "iterative refinement of a slightly shifted factorization; its "
          "cost grows like a 3-D factorization (the VC set-up of a 3-D "
          "cantilever at 56,355 DoFs: 147 s, with GMRES 2.5 s). "
          "summary.json 'vc_solve' says which one ran.");
        prm.declare_entry(
          "AMG parameters",
          "",
          Patterns::Anything(),
          "Parameters of Trilinos ML (cg and gmres) that replace pg's, as "
          "'name = value' pairs separated by ';', e.g. 'smoother: sweeps "
          "= 3; aggregation: type = METIS; aggregation: nodes per "
          "aggregate = 64'. The names are ML's (ML user's guide, chapter "
          "6), and each value must have the type ML reads (int, "
          "double, bool or string). pg's own list is deal.II's smoothed aggregation "
          "(Chebyshev smoother, 2 sweeps, aggregation threshold 1e-4, "
          "coarse size 2000) with the near-null space above. A name that "
          "ML does not know stops the run before the set-up.");
      }
      prm.leave_subsection();
    }



    void
    LinearSolver::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      {
        type            = prm.get("Type");
        tolerance       = prm.get_double("Tolerance");
        near_null_space = prm.get("AMG near-null space");
        reuse_amg       = prm.get_bool("Reuse AMG");
        amg_operator    = prm.get("AMG operator");
        vc_solver       = prm.get("VC solver");
        amg_parameters.clear();
        const std::string list = prm.get("AMG parameters");
        for (const std::string &item : Utilities::split_string_list(list, ';'))
          {
            if (item.empty())
              continue;
            const auto        equals = item.find('=');
            const std::string name   = Utilities::trim(item.substr(0, equals));
            const std::string value =
              (equals == std::string::npos ?
                 std::string() :
                 Utilities::trim(item.substr(equals + 1)));
            AssertThrow(
              equals != std::string::npos && !name.empty() && !value.empty(),
              ExcBadParameter("Linear solver/AMG parameters",
                              list,
                              "every item must read 'name = value' (items "
                              "separated by ';'), e.g. 'smoother: sweeps = 3'; "
                              "the item <" +
                                item + "> does not."));
            // the name and the type of the value, before the set-up
            Teuchos::ParameterList check;
            set_ml_parameter(check, name, value);
            amg_parameters.emplace_back(name, value);
          }
      }
      prm.leave_subsection();
    }



    bool
    Time::dynamic() const
    {
      return integrator != "none";
    }



    void
    Time::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time");
      {
        prm.declare_entry(
          "Integrator",
          "none",
          Patterns::Selection("none|leapfrog|newmark"),
          "'none': quasi-static load stepping (subsection 'Loading'); the "
          "variable t of the boundary-condition and load functions is the "
          "load factor from 0 to 1. 'leapfrog': explicit central differences "
          "(velocity Verlet) with the lumped mass, rho_0 times the integral "
          "of N_k over all cells (= rho_0 V^k at a particle); one residual "
          "assembly per step, no matrix. 'newmark': implicit Newmark with "
          "'Newmark beta' and 'Newmark gamma', Newton's method on the "
          "effective tangent K + M / (beta dt^2) with the consistent Q1 mass "
          "on finite element cells and rho_0 V^k at the particles "
          "(subsections 'Newton' and 'Linear solver' apply). With an "
          "integrator, t in the boundary-condition and load functions is the "
          "time (time units) from 0 to 'End time', 'Loading' is ignored, "
          "and statistics.txt holds the energies: kinetic 1/2 v.M v, the "
          "work of the internal forces, of the external loads and of the "
          "supports (the reactions of the constrained DoFs, inertia "
          "included), each accumulated with the trapezoidal rule, and their "
          "balance (0 for exact energy conservation).");
        prm.declare_entry("End time",
                          "1",
                          Patterns::Double(),
                          "The run ends at this time (> 0). Units: time.");
        prm.declare_entry(
          "Time step",
          "0",
          Patterns::Double(),
          "dt (>= 0). 0: the stable step of central differences, 2 / "
          "omega_max, times 'Safety factor', with omega_max^2 the largest "
          "eigenvalue of M^-1 K (power iteration with the lumped mass and "
          "the tangent of the initial state), shortened so that the steps "
          "end at 'End time'. Leapfrog rejects a step above 2 / omega_max. "
          "The mixed codes with pressure unknowns (U2P1C, Unl+P1C, IUnlP0) "
          "have no mass on them and need a step > 0 (and 'newmark'). "
          "Units: time.");
        prm.declare_entry("Safety factor",
                          "0.8",
                          Patterns::Double(),
                          "Automatic time step: this fraction (0 < f <= 1) "
                          "of the stable step estimate.");
        prm.declare_entry("Output interval",
                          "0",
                          Patterns::Double(),
                          "Statistics, VTU files and a progress line (t, "
                          "step, energies) every so much time (the first "
                          "step at or after each multiple). 0: every step. "
                          "Units: time.");
        prm.declare_entry("Newmark beta",
                          "0.25",
                          Patterns::Double(),
                          "beta of Newmark's method (0 < beta <= 0.5); 1/4 "
                          "with gamma = 1/2 is the average acceleration "
                          "rule, unconditionally stable and energy "
                          "conserving for linear problems.");
        prm.declare_entry("Newmark gamma",
                          "0.5",
                          Patterns::Double(),
                          "gamma of Newmark's method (0.5 <= gamma <= 1); "
                          "gamma > 1/2 adds numerical damping.");
        prm.declare_entry(
          "Time step control",
          "fixed",
          Patterns::Selection("fixed|adaptive"),
          "'fixed': every step has the same size (leapfrog: unless 'Stable "
          "step update interval' changes it) and a failed step ends the run. "
          "'adaptive' (newmark only): a step whose Newton iteration (or "
          "assembly) fails is redone from the last accepted state with half "
          "the step, down to 'Minimum time step'; after two consecutive "
          "steps that converged in at most 'Easy step iterations' Newton "
          "updates the step grows by 'Step growth factor', up to 'Maximum "
          "time step'. Steps are shortened to end at the output times and "
          "at 'End time'. The run fails when a step of 'Minimum time step' "
          "fails (the failure rule of the dissertation's dynamic torsion: "
          "Newton fails for a further 0.1 degree step).");
        prm.declare_entry("Minimum time step",
                          "0",
                          Patterns::Double(0.),
                          "The smallest step: 'adaptive' fails when a step "
                          "of this size fails; leapfrog with 'Stable step "
                          "update interval' stops when the automatic step "
                          "falls below it (the stable step collapsed). 0: "
                          "1e-3 times the initial step. Units: time.");
        prm.declare_entry("Maximum time step",
                          "0",
                          Patterns::Double(0.),
                          "'adaptive': the step grows up to this size. 0: "
                          "the initial step ('Time step', or the automatic "
                          "one). Units: time.");
        prm.declare_entry("Easy step iterations",
                          "4",
                          Patterns::Integer(1),
                          "'adaptive': a step that converged in at most so "
                          "many Newton updates counts as easy.");
        prm.declare_entry("Step growth factor",
                          "1.5",
                          Patterns::Double(1.),
                          "'adaptive': the factor (>= 1) by which the step "
                          "grows after two consecutive easy steps.");
        prm.declare_entry(
          "Stable step update interval",
          "0",
          Patterns::Integer(0),
          "Leapfrog: every so many steps, estimate 2 / omega_max again from "
          "the tangent of the current state (the committed plastic state "
          "gives the elastic tangent there, which sets the speed of "
          "unloading waves) by power iteration; an automatic step ('Time "
          "step = 0') becomes 'Safety factor' times the new estimate (a "
          "change of the step is reported), a fixed 'Time step' above it "
          "stops the run with the results kept. Needed where the stiffness "
          "or the spacing of the nodes changes a lot (an impact compresses "
          "the cells along the axis); each estimate costs one tangent "
          "assembly and a few hundred products with it. 0: only the "
          "initial estimate.");
        prm.declare_entry(
          "Newmark predictor",
          "newmark",
          Patterns::Selection("newmark|last converged state"),
          "Where Newton's method starts a Newmark step. 'newmark': at "
          "u + dt v + dt^2 (1/2 - beta) a (the new acceleration 0). "
          "'last converged state': at the displacement of the last step, "
          "as a quasi-static step with 'Loading/Predictor = boundary values' "
          "does (only the nodes with Dirichlet values move). Both with the "
          "new Dirichlet values on their DoFs; the converged step is the "
          "same, the number of Newton iterations and the largest step that "
          "converges are not. 'Loading/Predictor' applies to quasi-static "
          "load steps only.");
      }
      prm.leave_subsection();
    }



    void
    Time::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time");
      {
        integrator           = prm.get("Integrator");
        end_time             = prm.get_double("End time");
        time_step            = prm.get_double("Time step");
        safety_factor        = prm.get_double("Safety factor");
        output_interval      = prm.get_double("Output interval");
        beta                 = prm.get_double("Newmark beta");
        gamma                = prm.get_double("Newmark gamma");
        step_control         = prm.get("Time step control");
        minimum_time_step    = prm.get_double("Minimum time step");
        maximum_time_step    = prm.get_double("Maximum time step");
        easy_step_iterations = prm.get_integer("Easy step iterations");
        step_growth_factor   = prm.get_double("Step growth factor");
        stable_step_update_interval =
          prm.get_integer("Stable step update interval");
        newmark_predictor = prm.get("Newmark predictor");
      }
      prm.leave_subsection();

      if (!dynamic())
        return;
      const auto text = [](const double x) {
        std::ostringstream s;
        s << x;
        return s.str();
      };
      AssertThrow(end_time > 0.,
                  ExcBadParameter("Time/End time",
                                  text(end_time),
                                  "it must be positive."));
      AssertThrow(time_step >= 0.,
                  ExcBadParameter("Time/Time step",
                                  text(time_step),
                                  "it must be positive, or 0 for the "
                                  "automatic (stable) step."));
      AssertThrow(safety_factor > 0. && safety_factor <= 1.,
                  ExcBadParameter("Time/Safety factor",
                                  text(safety_factor),
                                  "it must lie in (0, 1]."));
      AssertThrow(output_interval >= 0.,
                  ExcBadParameter("Time/Output interval",
                                  text(output_interval),
                                  "it must be >= 0 (0: every step)."));
      AssertThrow(beta > 0. && beta <= 0.5,
                  ExcBadParameter("Time/Newmark beta",
                                  text(beta),
                                  "it must lie in (0, 0.5]."));
      AssertThrow(gamma >= 0.5 && gamma <= 1.,
                  ExcBadParameter("Time/Newmark gamma",
                                  text(gamma),
                                  "it must lie in [0.5, 1]."));
      AssertThrow(step_control == "fixed" || integrator == "newmark",
                  ExcBadParameter("Time/Time step control",
                                  step_control,
                                  "an adaptive step needs 'Integrator = "
                                  "newmark': the step of leapfrog is set by "
                                  "stability, not by Newton's method (see "
                                  "'Stable step update interval')."));
      AssertThrow(maximum_time_step == 0. || time_step == 0. ||
                    maximum_time_step >= time_step,
                  ExcBadParameter("Time/Maximum time step",
                                  text(maximum_time_step),
                                  "it is smaller than 'Time step' (" +
                                    text(time_step) +
                                    "), the first step: use at least that, "
                                    "or 0."));
      AssertThrow(minimum_time_step == 0. ||
                    ((time_step == 0. || minimum_time_step <= time_step) &&
                     (maximum_time_step == 0. ||
                      minimum_time_step <= maximum_time_step)),
                  ExcBadParameter("Time/Minimum time step",
                                  text(minimum_time_step),
                                  "it exceeds 'Time step' or 'Maximum time "
                                  "step': use a smaller value, or 0."));
      AssertThrow(stable_step_update_interval == 0 || integrator == "leapfrog",
                  ExcBadParameter("Time/Stable step update interval",
                                  std::to_string(stable_step_update_interval),
                                  "it applies to 'Integrator = leapfrog' "
                                  "only (the explicit step limit). Use 0."));
    }
  } // namespace Parameters
} // namespace pg
