// Benchmark B-13 short: prm/necking.prm (Simo's necking bar scaled by
// 5/14, one eighth with mirrored families, J2 plasticity with the source's
// sigma_yinf = 1.165) on its coarse mesh prm/meshes/necking_n2.msh (171
// vertices), read from the per-step columns of statistics.txt
// (reaction_4_x, max_equivalent_plastic_strain).
//
// FEM H1P0, elongated by 5 mm in 10 load steps (the benchmark: 50):
//  1. the bar necks: the force of the bar (4 reaction_4_x) has its maximum
//     before the end, and the end force is at least 10 % below it (50
//     steps: 27 %; a bar that does not neck keeps hardening);
//  2. the maximum force against the homogeneous bar's Considere force
//     sigma(a*) exp(-eps*) A_0 (a* = 0.1472, eps* = 15.3 % log strain) on
//     the centre section of the mesh (radius 0.99 R, a 16-gon: 15.20 kN):
//     between 0.97 and 1.03 (50 steps: 1.005);
//  3. the largest equivalent plastic strain at the end, rounded (50 steps:
//     0.73), and its growth over the last two steps, more than the mean
//     strain (localisation).
// VCBCPBG V5sn Unl, elongated by 1 mm in 2 load steps (before the force
// maximum, where the source's curves coincide):
//  4. its force at 1 mm is that of FEM H1P0 within 4 % (50 steps: +2.1 %).

#include "../tests.h"
#include "problem_fixture.h"

#include <sstream>

using namespace pg;

namespace
{
  /** Run prm/necking.prm with @p code, @p steps load steps to the
   * elongation @p u; return the columns of statistics.txt. */
  std::map<std::string, std::vector<double>>
  run(const std::string &code, const unsigned int steps, const double u)
  {
    const std::string directory = "output_" + std::to_string(steps);
    const std::string text = read_file(SOURCE_DIR "/../../prm/necking.prm") +
                             R"(
subsection Geometry
  set File name = )" SOURCE_DIR R"(/../../prm/meshes/necking_n2.msh
end
subsection Discretization
  set Formulation = )" + code +
                             R"(
end
subsection Boundary conditions
  subsection Prescribed displacement
    set Function constants = u = )" +
                             std::to_string(u) + R"(
  end
end
subsection Loading
  set Load steps = )" + std::to_string(steps) +
                             R"(
end
subsection Output
  set Directory = )" + directory +
                             R"(
  set VTU       = false
end
)";
    std::ostringstream screen;
    const RunSummary   summary = run_problem<3>(text, screen);
    deallog << code << ": converged " << (summary.converged ? "yes" : "no")
            << ", load steps " << summary.load_steps << std::endl;
    return read_statistics(directory + "/statistics.txt");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  const auto          fe = run("FEM H1P0", 10, 5.);
  std::vector<double> force;
  for (const double r : fe.at("reaction_4_x"))
    force.push_back(4. * r);
  const std::vector<double> &ep = fe.at("max_equivalent_plastic_strain");
  const unsigned int         i_max =
    std::max_element(force.begin(), force.end()) - force.begin();
  const double f_max = force[i_max];
  deallog << "  force maximum before the end: "
          << (i_max + 1 < force.size() ? "yes" : "NO") << std::endl;
  deallog << "  end force at least 10 % below the maximum: "
          << (force.back() < 0.9 * f_max ? "yes" : "NO") << std::endl;
  // the Considere force of the homogeneous bar on the centre section:
  // radius 0.99 R, a 16-gon in this mesh (area 8 sin(pi / 8) r^2)
  const double sinf = 1.165, s0 = 0.45, H = 0.13, delta = 16.93;
  const double E = 206.9, a = 0.147221540978;
  const double sigma = s0 + H * a + (sinf - s0) * (1. - std::exp(-delta * a));
  const double eps   = a + sigma / E;
  const double r     = 0.99 * 2.2904;
  const double f_considere =
    sigma * std::exp(-eps) * 8. * std::sin(numbers::PI / 8.) * r * r;
  deallog << "  F_max / F_Considere in [0.97, 1.03]: "
          << (f_max / f_considere >= 0.97 && f_max / f_considere <= 1.03 ?
                "yes" :
                "NO")
          << std::endl;
  print_rounded("  max equivalent plastic strain at 5 mm", ep.back(), 2);
  const unsigned int n = ep.size();
  deallog << "  it grew by more than the mean strain over the last two "
             "steps (1 / 19.048): "
          << (ep[n - 1] - ep[n - 3] > 1. / 19.048 ? "yes" : "NO") << std::endl;

  // the row of statistics.txt at the load factor 0.2 (1 mm)
  const std::vector<double> &t = fe.at("load factor");
  const unsigned int         i_1mm =
    std::find_if(t.begin(),
                 t.end(),
                 [](const double s) { return std::abs(s - 0.2) < 1e-12; }) -
    t.begin();
  const auto pg = run("VCBCPBG V5sn Unl", 2, 1.);
  print_bound("|F_Unl / F_H1P0 - 1| at 1 mm",
              pg.at("reaction_4_x").back() / fe.at("reaction_4_x")[i_1mm] - 1.,
              0.04);
}
