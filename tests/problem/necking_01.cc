// Benchmark B-13 short: prm/necking.prm (Simo's necking bar scaled by
// 5/14, one eighth with mirrored families, J2 plasticity with the source's
// sigma_yinf = 1.165) on its coarse mesh prm/meshes/necking_n2.msh (171
// vertices), elongated by 1 mm in 2 load steps (before the force maximum at
// 2.6 mm; the whole curve needs about 1,700 Newton iterations with FEM
// H1P0, minutes in Debug), read from the per-step columns of
// statistics.txt (reaction_4_x, max_equivalent_plastic_strain):
//  1. FEM H1P0: the force of the bar (4 reaction_4_x) at 1 mm against the
//     homogeneous bar's: sigma_y(a) exp(-eps) A with the mean log strain
//     eps = ln(1 + 1 / 19.048) and a = eps - sigma / E, on the mesh's
//     section at the end (radius R, a 16-gon; 12.95 kN) and at the centre
//     (0.99 R; 12.69 kN): the clamped, tapered bar lies between 0.95 and
//     1.05 times the centre's (13.1 kN: 1.03; benchmark, 50 steps: 13.05);
//  2. the largest equivalent plastic strain at 1 mm, rounded (50 steps:
//     0.060), above the mean plastic strain (the neck starts at the
//     centre);
//  3. VCBCPBG V5sn Unl on the same steps: its force within 4 % of FEM
//     H1P0's (50 steps: +2.2 %), where the source's curves coincide.

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
    const std::string directory = "output_" + std::to_string(code.size());
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

  const auto   fe    = run("FEM H1P0", 2, 1.);
  const double f_fe  = 4. * fe.at("reaction_4_x").back();
  const double ep_fe = fe.at("max_equivalent_plastic_strain").back();
  const double sinf = 1.165, s0 = 0.45, H = 0.13, delta = 16.93;
  const double E     = 206.9;
  const double eps   = std::log(1. + 1. / 19.048);
  double       a     = eps;
  double       sigma = 0.;
  for (unsigned int it = 0; it < 50; ++it)
    {
      sigma = s0 + H * a + (sinf - s0) * (1. - std::exp(-delta * a));
      a     = eps - sigma / E;
    }
  const double r = 0.99 * 2.2904;
  const double f_homogeneous =
    sigma * std::exp(-eps) * 8. * std::sin(numbers::PI / 8.) * r * r;
  deallog << "FEM H1P0: force at 1 mm / homogeneous bar's in [0.95, 1.05]: "
          << (f_fe / f_homogeneous >= 0.95 && f_fe / f_homogeneous <= 1.05 ?
                "yes" :
                "NO")
          << std::endl;
  print_rounded("  force of the bar at 1 mm (kN)", f_fe, 3);
  print_rounded("  max equivalent plastic strain at 1 mm", ep_fe, 2);
  deallog << "  above the mean plastic strain " << std::setprecision(3) << a
          << ": " << (ep_fe > a ? "yes" : "NO") << std::endl;

  const auto pg = run("VCBCPBG V5sn Unl", 2, 1.);
  print_bound("|F_Unl / F_H1P0 - 1| at 1 mm",
              pg.at("reaction_4_x").back() / fe.at("reaction_4_x").back() - 1.,
              0.04);
}
