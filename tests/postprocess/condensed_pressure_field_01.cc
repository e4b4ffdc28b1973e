// The condensed pressure of the mixed formulations in the output (issue
// 13): summary.json's condensed_pressure_range and the fields
// condensed_pressure / condensed_dilatation of solution.pvd (cells) and
// particles.pvd. On the finite-strain patch test (K = 50, mu = 10,
// F = diag(1.2, 0.9), J = 1.08) every element must carry
// p = K/2 (J - 1/J) = 3.8518518... and Theta = J, for Q1P0, PBG and PPG
// UnlP0, U2P1 and a coupled model (particles on the right half).

#include "../problem/problem_fixture.h"
#include "../tests.h"

#include <filesystem>
#include <fstream>

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const double       J = 1.08, K = 50.;
  const double       p_exact = K / 2. * (J - 1. / J);
  std::ostringstream screen;
  for (const std::string code : {"FEM Q1P0",
                                 "VCBCPBG V5sn UnlP0",
                                 "VCBCPPG V3sn UnlP0",
                                 "VCPBG U2P1",
                                 "VCBCPPG V3sn UnlP0 @ right half"})
    {
      const auto        at = code.find(" @ ");
      const std::string region =
        (at == std::string::npos ? (code == "FEM Q1P0" ? "none" : "all") :
                                   "box 0.5, -0.1 : 1.1, 1.1");
      const std::string    dir = "output_" + std::to_string(code.size());
      const pg::RunSummary s   = run_problem<2>(
        read_file(SOURCE_DIR "/../pg_solve/isovol_neo_hooke_patch_fem.prm") +
          "subsection Discretization\n  set Formulation = " +
          code.substr(0, at) +
          "\n  set Horizon factor = 2.51\nend\n"
            "subsection Geometry\n  set Meshfree region = " +
          region +
          "\nend\n"
            "subsection Output\n  set VTU = true\n  set Directory = " +
          dir + "\nend\n",
        screen);
      const auto  &range = s.condensed_pressure_range;
      const double error =
        (range.size() == 2 ? std::max(std::abs(range[0] - p_exact),
                                      std::abs(range[1] - p_exact)) /
                               p_exact :
                             1.);
      // the VTU records name the fields
      bool in_cells = false, in_particles = false;
      for (const auto &entry : std::filesystem::directory_iterator(dir))
        {
          std::ifstream      file(entry.path());
          std::ostringstream text;
          text << file.rdbuf();
          const bool named =
            text.str().find("Name=\"condensed_pressure\"") != std::string::npos;
          const std::string name = entry.path().filename().string();
          if (name.rfind("solution_", 0) == 0 && name.find(".vtu") != name.npos)
            in_cells = in_cells || named;
          if (name.rfind("particles_", 0) == 0 &&
              name.find(".vtu") != name.npos)
            in_particles = in_particles || named;
        }
      std::filesystem::remove_all(dir);
      deallog << std::left << std::setw(32) << code << std::right
              << " p = K/2 (J - 1/J) everywhere: "
              << (error < 1e-10 ? "yes" : "NO")
              << ", in solution VTU: " << (in_cells ? "yes" : "NO")
              << ", in particles VTU: " << (in_particles ? "yes" : "NO")
              << std::endl;
    }
  // a displacement formulation has no condensed pressure
  const pg::RunSummary s =
    run_problem<2>(read_file(SOURCE_DIR
                             "/../pg_solve/isovol_neo_hooke_patch_fem.prm"),
                   screen);
  deallog << "FEM: condensed_pressure_range empty: "
          << (s.condensed_pressure_range.empty() ? "yes" : "NO") << std::endl;
}
