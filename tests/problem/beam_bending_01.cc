// Ganzenmueller's simply supported beam (benchmark G-2,
// prm/beam_bending.prm): 8 mm x 1 mm, 32 x 4 regular lattice, SVK with
// E = 100 GPa, nu = 0.3, pinned at the lower corners, the mid cross-section
// pulled down slowly (10 periods of the first bending mode) to 8 mm.
//
// (a) Classical correspondence (PBG U1, WTE1) with leapfrog, as in the
//     source: the pairing indicator ('disorder', the deviation of each
//     particle from the linear fit of its neighbours over the RMS
//     displacement) stays at the level of the smooth bending field (below
//     0.06) from u_y = 0.1 mm (before, the pulled cross-section alone has
//     moved) up to u_y ~ 2.5 mm and then grows past 0.15 before u_y = 5.5 mm
//     (t = 0.6 T): particle pairs that do not follow the beam. The Debug
//     build stops there; doc/benchmarks/beam_bending.sh runs on to 8 mm.
// (b) VCBCPBG Unl, with Newmark steps of T/100 (the same path
//     quasi-statically; leapfrog gives the same indicator, 0.0498 at 8 mm,
//     but is too slow for a Debug test): the indicator stays below 0.06 all
//     the way to 8 mm and the internal energy equals the work of the
//     supports.

#include "../tests.h"
#include "problem_fixture.h"

#include <algorithm>

pg::RunSummary
run_beam(const std::string &overrides)
{
  std::ostringstream screen;
  return run_problem<2>(read_file(SOURCE_DIR "/../../prm/beam_bending.prm") +
                          overrides,
                        screen);
}



/** @p x with one decimal. */
std::string
one_decimal(const double x)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(1) << x;
  return s.str();
}



/** The load: u_y of the mid cross-section (mm, downwards) at time t. */
double
deflection(const double t)
{
  const double tau = t / 4.47;
  return 8 * (tau - std::sin(2 * numbers::PI * tau) / (2 * numbers::PI));
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  {
    const pg::RunSummary s =
      run_beam("subsection Discretization\n set Formulation = PBG U1\nend\n"
               "subsection Time\n set End time = 2.682\nend\n");
    const auto &d = s.dynamics;
    // from u_y = 0.1 mm on: before, only the mid cross-section has moved
    double       early = 0;
    unsigned int i     = 0;
    for (; i < d.time.size() && deflection(d.time[i]) <= 2.5; ++i)
      if (deflection(d.time[i]) >= 0.1)
        early = std::max(early, d.disorder[i]);
    double late = 0;
    for (; i < d.time.size(); ++i)
      late = std::max(late, d.disorder[i]);
    deallog << "(a) PBG U1, leapfrog, up to u_y = "
            << one_decimal(deflection(d.time.back())) << " mm" << std::endl;
    print_bound("  max pairing indicator for u_y = 0.1 ... 2.5 mm",
                early,
                0.06);
    deallog << "  max pairing indicator after: "
            << (late > 0.15 ? "above 0.15" : "NOT above 0.15") << std::endl;
  }

  {
    const pg::RunSummary s =
      run_beam("subsection Time\n set Integrator = newmark\n"
               " set Time step = 0.0447\nend\n");
    const auto &d = s.dynamics;
    deallog << "(b) VCBCPBG Unl, Newmark, up to u_y = "
            << one_decimal(deflection(d.time.back())) << " mm" << std::endl;
    print_bound("  max pairing indicator",
                *std::max_element(d.disorder.begin(), d.disorder.end()),
                0.06);
    print_bound("  |W_int - W_supports| / W_int",
                (d.internal_work.back() - d.support_work.back()) /
                  d.internal_work.back(),
                1e-3);
    print_bound("  E_kin / W_int",
                d.kinetic.back() / d.internal_work.back(),
                1e-3);
  }
}
