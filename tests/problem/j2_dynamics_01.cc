// J2 plasticity in dynamics: the energy account with the plastic work, the
// adaptive Newmark step and the stable-step update of leapfrog.
//
// The unit cube on the symmetry planes x = 0, y = 0, z = 0 (necking
// material of §7.3.5, rho_0 = 1: the longest elastic wave period is about
// 4 L / c = 0.28, against a load time of 10) is pulled by the dead traction
// T(t) = 0.6 sin(pi t / 10) on x = 1 and let go again: T rises above the
// yield stress 0.45 and returns to 0. Nearly quasi-static, so the motion is
// nearly homogeneous: every point reaches the same alpha, and at t = 10 the
// cube is unloaded. Checked:
//  1. the plastic work from the state, sum_q w_q int_0^alpha sigma_y da,
//     against V int_0^alpha_max sigma_y da of the largest alpha in the body
//     (V = 1: the weights integrate the body, alpha nearly uniform);
//  2. at t = 10, the work of the internal forces (trapezoidal rule over the
//     steps) against the plastic work: the rest is the elastic energy left
//     in the unloaded, vibrating cube;
//  3. the energy balance E_kin + W_int - W_ext against W_ext;
//  4. Newmark 'adaptive' from dt = 0.5 with at most 3 Newton iterations:
//     the steps that fail are cut (and grow again), the run reaches t = 10,
//     and checks 2 and 3 hold across the cuts (alpha_max itself depends on
//     the steps: large Newmark steps of a sudden load rate overshoot);
//  5. leapfrog with 'Stable step update interval': the estimate after the
//     cube has yielded (the committed state gives the elastic tangent)
//     equals the initial one within the change of the geometry (1 %), where
//     the plastic tangent would raise it.
// For FEM (Q1 cells), VCBCPBG V5sn Unl (family tables) and VCBCPBG V5sn
// Unl+P1C (nodal-pressure families).

#include <pg/materials/material.h>

#include "../tests.h"
#include "problem_fixture.h"

#include <cmath>
#include <sstream>

using namespace pg;

/** int_0^a sigma_y da of the necking material. */
double
plastic_work_density(const double a)
{
  return 0.45 * a + 0.5 * 0.13 * a * a +
         (1.165 - 0.45) * (a - (1. - std::exp(-16.93 * a)) / 16.93);
}

RunSummary
run(const std::string &code,
    const std::string &time_text,
    const std::string &newton_text,
    std::ostream      &screen)
{
  const std::string text = R"(
set Dimension = 3
subsection Geometry
  set Mesh          = hyper rectangle
  set Lower corner  = 0, 0, 0
  set Upper corner  = 1, 1, 1
  set Subdivisions  = 2, 2, 2
end
subsection Discretization
  set Formulation = )" + code +
                           R"(
end
subsection Material
  set Model                    = J2 plasticity
  set Young's modulus          = 206.9
  set Poisson's ratio          = 0.29
  set Initial yield stress     = 0.45
  set Saturation yield stress  = 1.165
  set Linear hardening modulus = 0.13
  set Saturation exponent      = 16.93
  set Density                  = 1
end
subsection Boundary conditions
  set Symmetry = 0, 2, 4
  set Neumann  = 1
  subsection Traction
    set Function constants  = pi=3.141592653589793
    set Function expression = 0.6 * sin(pi * t / 10); 0; 0
  end
end
subsection Time
  set End time        = 10
  set Output interval = 1
)" + time_text + R"(
end
subsection Newton
  set Relative tolerance = 1e-12
  set Absolute tolerance = 1e-13
)" + newton_text + R"(
end
subsection Output
  set Directory = output_)" +
                           std::to_string(code.size()) + R"(
  set VTU       = false
end
)";
  return run_problem<3>(text, screen);
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  for (const std::string code :
       {"FEM", "VCBCPBG V5sn Unl", "VCBCPBG V5sn Unl+P1C"})
    {
      deallog << code << std::endl;
      std::ostringstream screen;
      const RunSummary   fixed = run(code,
                                   "  set Integrator = newmark\n"
                                     "  set Time step  = 0.25\n",
                                   "",
                                   screen);
      const auto        &d     = fixed.dynamics;
      const double       alpha =
        fixed.state_output_maxima.at(0).second; // equivalent_plastic_strain
      const double W_p = d.plastic_work.back();
      deallog << "  newmark dt = 0.25: " << d.n_steps
              << " steps, t = " << d.final_time << std::endl;
      print_rounded("  alpha_max", alpha, 3);
      // alpha_max bounds every point's alpha, and the motion is nearly
      // homogeneous
      const double ratio = W_p / plastic_work_density(alpha);
      deallog << "  0.95 <= W_plastic / (V int_0^alpha_max sigma_y da) <= 1: "
              << (ratio >= 0.95 && ratio <= 1. ? "yes" : "NO") << std::endl;
      print_bound("  |W_int / W_plastic - 1| at t = 10",
                  d.internal_work.back() / W_p - 1.,
                  1e-2);
      double balance = 0;
      for (unsigned int i = 0; i < d.balance.size(); ++i)
        balance =
          std::max(balance, std::abs(d.balance[i]) / d.external_work.back());
      print_bound("  max |E_kin + W_int - W_ext| / W_ext(10)", balance, 1e-3);

      // the adaptive steps: a cut that left anything of the failed step
      // (the velocity, the acceleration, the point history, the external
      // force) would break the balance or the plastic work
      const RunSummary adaptive = run(code,
                                      "  set Integrator        = newmark\n"
                                      "  set Time step         = 0.5\n"
                                      "  set Time step control = adaptive\n",
                                      "  set Maximum iterations = 3\n",
                                      screen);
      const auto      &a        = adaptive.dynamics;
      deallog << "  adaptive from dt = 0.5: t = " << a.final_time
              << ", step cuts > 0: " << (a.step_cuts > 0 ? "yes" : "NO")
              << std::endl;
      print_bound("  |W_int / W_plastic - 1| at t = 10",
                  a.internal_work.back() / a.plastic_work.back() - 1.,
                  1e-2);
      balance = 0;
      for (unsigned int i = 0; i < a.balance.size(); ++i)
        balance =
          std::max(balance, std::abs(a.balance[i]) / a.external_work.back());
      print_bound("  max |E_kin + W_int - W_ext| / W_ext(10)", balance, 1e-3);
    }

  // leapfrog (Q1 cells): the stable step after yielding against the
  // initial one (a run of one output interval, before the cube yields)
  {
    std::ostringstream screen;
    const RunSummary   initial =
      run("FEM",
          "  set Integrator = leapfrog\n  set End time = 0.1\n",
          "",
          screen);
    const RunSummary leapfrog =
      run("FEM",
          "  set Integrator                  = leapfrog\n"
          "  set End time                    = 5\n"
          "  set Stable step update interval = 50\n",
          "",
          screen);
    const auto &d = leapfrog.dynamics;
    deallog << "leapfrog to t = " << d.final_time << ": yielded "
            << (leapfrog.state_output_maxima.at(0).second > 1e-3 ? "yes" : "NO")
            << std::endl;
    print_bound("  |stable step at t = 5 / initial one - 1|",
                d.stable_time_step / initial.dynamics.stable_time_step - 1.,
                1e-2);
  }
}
