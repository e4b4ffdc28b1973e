// Benchmark B-13 short: prm/necking.prm (Simo's necking bar scaled by
// 5/14, one eighth with mirrored families, J2 plasticity with the source's
// sigma_yinf = 1.165) on its coarse mesh prm/meshes/necking_n2.msh (171
// particles), elongated by 5 mm in 10 load steps instead of 50, with FEM
// H1P0 and VCBCPBG V5sn UnlP0. Checked for each, from the per-step columns
// of statistics.txt (reaction_4_x, max_equivalent_plastic_strain):
//  1. the bar necks: the force of the bar (4 reaction_4_x) has its maximum
//     before the end, and the end force is at least 0.5 % below it (the
//     clamped bar at this resolution: FE 1.5 %, PG 1.1 %; a bar that does
//     not neck keeps hardening);
//  2. the maximum force against the homogeneous bar's Considere force
//     sigma(a*) exp(-eps*) A_0 (a* = 0.1472, eps* = 15.3 % log strain) on
//     the centre section of the mesh (radius 0.99 R, a 16-gon: 15.20 kN):
//     between 0.97 and 1.03 (the clamped, tapered bar: FE 1.005);
//  3. the largest equivalent plastic strain at the end, rounded, and its
//     growth over the last two steps (localisation: it rises faster than
//     the mean strain);
//  4. FEM H1P0 and UnlP0 give the same maximum force within 3 %.

#include "../tests.h"
#include "problem_fixture.h"

#include <sstream>

using namespace pg;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  std::vector<double> maximum_forces;
  for (const std::string code : {"FEM H1P0", "VCBCPBG V5sn UnlP0"})
    {
      const std::string directory =
        "output_" + std::to_string(maximum_forces.size());
      const std::string text = read_file(SOURCE_DIR "/../../prm/necking.prm") +
                               R"(
subsection Geometry
  set File name = )" SOURCE_DIR R"(/../../prm/meshes/necking_n2.msh
end
subsection Discretization
  set Formulation = )" + code + R"(
end
subsection Loading
  set Load steps = 10
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
      const auto columns = read_statistics(directory + "/statistics.txt");
      const std::vector<double> &reaction = columns.at("reaction_4_x");
      const std::vector<double> &ep =
        columns.at("max_equivalent_plastic_strain");
      std::vector<double> force;
      for (const double r : reaction)
        force.push_back(4. * r);
      const unsigned int i_max =
        std::max_element(force.begin(), force.end()) - force.begin();
      const double f_max = force[i_max];
      deallog << "  force maximum before the end: "
              << (i_max + 1 < force.size() ? "yes" : "NO") << ", at step "
              << i_max + 1 << " of " << force.size() << std::endl;
      deallog << "  end force at least 0.5 % below the maximum: "
              << (force.back() < 0.995 * f_max ? "yes" : "NO") << std::endl;
      // the Considere force of the homogeneous bar on the centre section
      const double sinf = 1.165, s0 = 0.45, H = 0.13, delta = 16.93;
      const double E = 206.9, a = 0.147221540978;
      const double sigma =
        s0 + H * a + (sinf - s0) * (1. - std::exp(-delta * a));
      const double eps = a + sigma / E;
      // the centre section: radius 0.99 R, a 16-gon in this mesh (area
      // 8 sin(pi / 8) r^2 = 0.9745 pi r^2)
      const double r = 0.99 * 2.2904;
      const double f_considere =
        sigma * std::exp(-eps) * 8. * std::sin(numbers::PI / 8.) * r * r;
      deallog << "  F_max / F_Considere in [0.97, 1.03]: "
              << (f_max / f_considere >= 0.97 && f_max / f_considere <= 1.03 ?
                    "yes" :
                    "NO")
              << std::endl;
      print_rounded("  F_max / F_Considere", f_max / f_considere, 2);
      print_rounded("  max equivalent plastic strain at the end", ep.back(), 2);
      const unsigned int n = ep.size();
      deallog << "  it grew by more than the mean strain over the last two "
                 "steps (0.1 x 5 / 19.048 = 0.026): "
              << (ep[n - 1] - ep[n - 3] > 0.026 ? "yes" : "NO") << std::endl;
      maximum_forces.push_back(f_max);
    }
  print_bound("|F_max(UnlP0) / F_max(H1P0) - 1|",
              maximum_forces[1] / maximum_forces[0] - 1.,
              0.03);
}
