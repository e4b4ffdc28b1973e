// Time integration of the vibrating bar of prm/vibrating_bar.prm (a 1-D
// bar, E = rho = 1, length 1, fixed at x = 0, started at rest in its first
// mode u_x = A sin(pi x/2)): the exact tip displacement is A cos(omega t)
// with omega = pi/2, period T = 4.
//
// (1) Frequency: at t = T/4 the exact tip displacement is 0, and a relative
// frequency error eps gives u_tip = -A sin(pi/2 eps) ~ -A pi/2 eps, so
// eps = -2 u_tip/(pi A) is measured for leapfrog (lumped mass: the
// discrete frequency is too low by about (kh)^2/24), Newmark (consistent
// mass: too high) and a PG discretisation (VCBCPBG Unl, lumped particle
// masses rho V^k).
// (2) Energy over 10 periods: leapfrog's balance E_kin + W_int - E_kin(0)
// oscillates boundedly (O((omega dt)^2) at the output steps) without drift;
// the average acceleration rule conserves it exactly for a linear problem
// (to the solver's round-off).

#include "../tests.h"
#include "problem_fixture.h"

#include <algorithm>

namespace
{
  std::string
  time_settings(const std::string &integrator,
                const double       end_time,
                const double       time_step)
  {
    return "subsection Time\n  set Integrator = " + integrator +
           "\n  set End time = " + std::to_string(end_time) +
           "\n  set Time step = " + std::to_string(time_step) +
           "\n  set Output interval = 0.05\nend\n";
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const std::string base = read_file(SOURCE_DIR "/../../prm/vibrating_bar.prm");
  const double      A = 0.01, pi = numbers::PI;
  std::ostringstream screen;

  // (1) the frequency error at t = T/4
  for (const auto &[name, settings] :
       std::vector<std::pair<std::string, std::string>>{
         {"FEM leapfrog", time_settings("leapfrog", 1., 0.)},
         {"FEM newmark", time_settings("newmark", 1., 0.01)},
         {"VCBCPBG Unl leapfrog",
          time_settings("leapfrog", 1., 0.) +
            "subsection Discretization\n  set Formulation = VCBCPBG Unl\n"
            "end\n"}})
    {
      const pg::RunSummary s   = run_problem<2>(base + settings, screen);
      const double         eps = -2. * s.points[0].second[0] / (pi * A);
      deallog << name << ": " << s.dynamics.n_steps << " steps, dt <= "
              << "2/omega_max: "
              << (s.dynamics.time_step <= s.dynamics.stable_time_step ||
                      name == "FEM newmark" ?
                    "yes" :
                    "NO")
              << std::endl;
      print_bound("  |relative frequency error|", eps, 3e-3);
      deallog << "  frequency " << (eps < 0 ? "too low" : "too high")
              << std::endl;
    }

  // The stable step of the lumped Q1 chain of N = 16 elements fixed at
  // one end: omega_max = (2c/h) sin((2N-1) pi/(4N)), so 2/omega_max =
  // h/(c sin(31 pi/64)), slightly above h/c; the power iteration must find
  // it (from above: its omega_max estimate converges from below).
  {
    const pg::RunSummary s =
      run_problem<2>(base + time_settings("leapfrog", 0.1, 0.), screen);
    const double exact = (1. / 16.) / std::sin(31. * pi / 64.);
    print_bound("FEM stable step estimate / exact - 1",
                s.dynamics.stable_time_step / exact - 1.,
                1e-4);
  }

  // (2) energy over 10 periods
  for (const std::string integrator : {"leapfrog", "newmark"})
    {
      const pg::RunSummary s = run_problem<2>(
        base +
          time_settings(integrator, 40., integrator == "newmark" ? 0.05 : 0.),
        screen);
      const auto  &d = s.dynamics;
      const double E_max =
        *std::max_element(d.kinetic.begin(), d.kinetic.end());
      double       max_balance = 0, first = 0, last = 0;
      unsigned int n_first = 0, n_last = 0;
      for (unsigned int i = 0; i < d.time.size(); ++i)
        {
          max_balance = std::max(max_balance, std::abs(d.balance[i]));
          if (d.time[i] <= 4.)
            first += d.balance[i], ++n_first;
          if (d.time[i] > 36.)
            last += d.balance[i], ++n_last;
        }
      deallog << integrator << ", 10 periods, " << d.n_steps
              << " steps:" << std::endl;
      print_bound("  max |E balance| / max E_kin",
                  max_balance / E_max,
                  integrator == "newmark" ? 1e-10 : 5e-3);
      print_bound("  drift of the period-averaged balance / max E_kin",
                  (last / n_last - first / n_first) / E_max,
                  integrator == "newmark" ? 1e-10 : 1e-4);
      print_bound("  E_kin at t = 40 (= 0 exactly) / max E_kin",
                  d.kinetic.back() / E_max,
                  integrator == "newmark" ? 2e-2 : 2e-2);
    }
}
