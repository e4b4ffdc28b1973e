// 'Boundary conditions/Rigid wall' in explicit runs (leapfrog): a node
// that the predictor puts behind the wall is projected onto it and held at
// rest; it is released when its reaction turns tensile. The block of
// rigid_wall_01 (E = 1, nu = 0.3, rho = 1, wave transit time ~ 1) rests
// on the wall y = 0; its clamped top moves slowly by u_y = -0.01 sin(2 pi
// t / 40): pressed to -0.01 at t = 10, back at 0 at t = 20, lifted to
// +0.01 at t = 30. Run to t = 10: every bottom node held, no node behind
// the wall, and the wall's reaction balances the top's up to the inertia
// of the loading: the waves its start excites are undamped (measured: FEM
// 7.8 %, PG 4 %; bound 10 %). Run to t = 30: every node
// released, the wall's reaction zero, the bottom above the wall. FEM Q1
// and VCBCPBG V5sn Unl. The same with Newmark (average acceleration,
// dt = 0.1, FEM), whose active set is updated inside each step: after the
// converged solve, nodes behind the wall are held, those with a tensile
// reaction (f_int - f_ext + M a) released, and the step solved again until
// the set stays.

#include "../tests.h"
#include "problem_fixture.h"

#include <tuple>

namespace
{
  std::string
  block(const std::string &formulation,
        const unsigned int n,
        const double       end_time,
        const std::string &integrator)
  {
    std::ostringstream s;
    s << "set Dimension = 2\n"
      << "subsection Geometry\n"
      << "  set Lower corner = 0, 0\n"
      << "  set Upper corner = 1, 1\n"
      << "  set Subdivisions = " << n << ", " << n << "\nend\n"
      << "subsection Discretization\n"
      << "  set Formulation = " << formulation << "\nend\n"
      << "subsection Material\n"
      << "  set Model = linear elastic\n"
      << "  set Young's modulus = 1\n"
      << "  set Poisson's ratio = 0.3\n"
      << "  set Density = 1\n"
      << "end\n"
      << "subsection Boundary conditions\n"
      << "  set Dirichlet = 3: xy\n"
      << "  subsection Prescribed displacement\n"
      << "    set Function expression = 0; -0.01*sin(2*pi*t/40)\n"
      << "  end\n"
      << "  subsection Rigid wall\n"
      << "    set Normal = 0, 1\n"
      << "  end\n"
      << "end\n"
      << "subsection Time\n"
      << "  set Integrator = " << integrator << "\n"
      << (integrator == "newmark" ? "  set Time step = 0.1\n" : "")
      << "  set End time = " << end_time << "\n"
      << "  set Output interval = " << end_time << "\n"
      << "end\n"
      << "subsection Output\n"
      << "  set VTU = false\n"
      << "end\n";
    return s.str();
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  for (const auto &[formulation, n, integrator] :
       std::vector<std::tuple<std::string, unsigned int, std::string>>{
         {"FEM", 4, "leapfrog"},
         {"VCBCPBG V5sn Unl", 6, "leapfrog"},
         {"FEM", 4, "newmark"}})
    {
      deallog << formulation << ", " << n << " x " << n << " cells, "
              << integrator << std::endl;
      std::ostringstream   screen;
      const pg::RunSummary pressed =
        run_problem<2>(block(formulation, n, 10, integrator), screen);
      const std::vector<double> &top  = pressed.reactions.at(3);
      const std::vector<double> &wall = pressed.wall_reaction;
      deallog << "  t = 10: nodes held " << pressed.wall_active_nodes
              << " (bottom nodes " << n + 1 << ")" << std::endl;
      print_rounded("  t = 10: wall reaction y", wall[1], 2);
      print_bound("  t = 10: |R_wall + R_top| / |R_top|",
                  std::hypot(wall[0] + top[0], wall[1] + top[1]) /
                    std::abs(top[1]),
                  0.1);
      print_bound("  t = 10: wall reaction x (frictionless)", wall[0], 1e-12);
      deallog << "  t = 10: min n . (x - p) >= -1e-12: "
              << (pressed.wall_min_gap >= -1e-12 ? "yes" : "NO") << std::endl;

      const pg::RunSummary lifted =
        run_problem<2>(block(formulation, n, 30, integrator), screen);
      deallog << "  t = 30: nodes held " << lifted.wall_active_nodes
              << std::endl;
      print_bound("  t = 30: |wall reaction|",
                  std::hypot(lifted.wall_reaction[0], lifted.wall_reaction[1]),
                  1e-12);
      deallog << "  t = 30: min gap in (0.005, 0.015): "
              << (lifted.wall_min_gap > 0.005 && lifted.wall_min_gap < 0.015 ?
                    "yes" :
                    "NO")
              << std::endl;
    }
}
