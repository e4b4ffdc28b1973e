// 'Boundary conditions/Rigid wall' in quasi-static runs: the active set
// inside the load steps. A block [0, 1]^2 (linear elastic, E = 1,
// nu = 0.3) lies 0.005 above the wall y = -0.005 (normal 0, 1), its top
// clamped in x and moved by u_y = 0.04 t - 0.03: at t = 0.5 it is pressed
// 0.005 into the wall, at t = 1 lifted 0.015 above it. With one load step
// to t = 0.5 the free block first moves down rigidly, every bottom node
// lands behind the wall, all are held and the step is solved again: the
// wall's reaction must balance the top's to round-off (static
// equilibrium), every reaction be compressive (nothing is released again)
// and no node lie behind the wall. The second step (t = 1) starts with
// the bottom held: every node pulls on the wall and is released, the block
// hangs free: no node held, the wall's reaction zero and the bottom 0.015
// above the wall. With 'Contact = two-sided' (FEM) the lifted block stays
// held: the wall pulls, its reaction balances the top's. Then a block
// standing on the wall y = 0 and pressed by the traction T_y = -0.01 on
// its top, held in x at one corner only: the nodes that touch the wall at
// the start are held (static runs), which supports the block; the wall's
// reaction is the load, 0.01, to round-off. FEM Q1 and VCBCPBG V5sn Unl.
// (The wall's point is any point of the plane; the normal is normalised.)

#include "../tests.h"
#include "problem_fixture.h"

#include <regex>

namespace
{
  std::string
  block(const std::string &formulation,
        const unsigned int n,
        const unsigned int load_steps,
        const std::string &top,
        const std::string &contact = "unilateral")
  {
    return "set Dimension = 2\n"
           "subsection Geometry\n"
           "  set Lower corner = 0, 0\n"
           "  set Upper corner = 1, 1\n"
           "  set Subdivisions = " +
           std::to_string(n) + ", " + std::to_string(n) +
           "\nend\n"
           "subsection Discretization\n"
           "  set Formulation = " +
           formulation +
           "\nend\n"
           "subsection Material\n"
           "  set Model = linear elastic\n"
           "  set Young's modulus = 1\n"
           "  set Poisson's ratio = 0.3\n"
           "end\n"
           "subsection Boundary conditions\n" +
           (top.empty() ? std::string("  set Neumann = 3\n"
                                      "  set Fixed points = 0, 0: x\n"
                                      "  subsection Traction\n"
                                      "    set Function expression = 0; -0.01\n"
                                      "  end\n"
                                      "  subsection Rigid wall\n"
                                      "    set Point  = 0.5, 0\n") :
                          "  set Dirichlet = 3: xy\n"
                          "  subsection Prescribed displacement\n"
                          "    set Function expression = 0; " +
                            top +
                            "\n  end\n"
                            "  subsection Rigid wall\n"
                            "    set Point  = 0.5, -0.005\n") +
           "    set Normal = 0, 2\n"
           "    set Contact = " +
           contact +
           "\n"
           "  end\n"
           "end\n"
           "subsection Loading\n"
           "  set Load steps = " +
           std::to_string(load_steps) +
           "\nend\n"
           "subsection Linear solver\n"
           "  set Type = direct\n"
           "end\n"
           "subsection Output\n"
           "  set VTU = false\n"
           "end\n";
  }

  /**
   * The sum of the numbers before @p what in the lines of @p screen
   * (collective).
   */
  unsigned int
  count(const std::string &screen, const std::string &what)
  {
    unsigned int     n = 0;
    const std::regex pattern("(\\d+) " + what);
    for (auto it = std::sregex_iterator(screen.begin(), screen.end(), pattern);
         it != std::sregex_iterator();
         ++it)
      n += std::stoi((*it)[1]);
    // (the screen is rank 0's)
    return Utilities::MPI::max(n, MPI_COMM_WORLD);
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  for (const auto &[formulation, n] :
       std::vector<std::pair<std::string, unsigned int>>{{"FEM", 4},
                                                         {"VCBCPBG V5sn Unl",
                                                          6}})
    {
      deallog << formulation << ", " << n << " x " << n << " cells"
              << std::endl;
      // pressed: one load step to u_y = -0.01
      std::ostringstream   screen;
      const pg::RunSummary pressed =
        run_problem<2>(block(formulation, n, 1, "-0.01*t"), screen);
      const std::vector<double> &top  = pressed.reactions.at(3);
      const std::vector<double> &wall = pressed.wall_reaction;
      deallog << "  pressed: nodes held " << pressed.wall_active_nodes
              << " (bottom nodes " << n + 1 << "), brought into contact "
              << count(screen.str(), "nodes in contact") << ", released "
              << count(screen.str(), "released") << std::endl;
      print_rounded("  pressed: wall reaction y", wall[1], 3);
      print_bound("  pressed: |R_wall + R_top| / |R_top|",
                  std::hypot(wall[0] + top[0], wall[1] + top[1]) /
                    std::abs(top[1]),
                  1e-10);
      print_bound("  pressed: wall reaction x (frictionless)", wall[0], 1e-12);
      deallog << "  pressed: min n . (x - p) >= -1e-12: "
              << (pressed.wall_min_gap >= -1e-12 ? "yes" : "NO") << std::endl;

      // pressed at t = 0.5, lifted at t = 1
      std::ostringstream   screen2;
      const pg::RunSummary lifted =
        run_problem<2>(block(formulation, n, 2, "0.04*t - 0.03"), screen2);
      deallog << "  lifted: nodes held " << lifted.wall_active_nodes
              << ", brought into contact "
              << count(screen2.str(), "nodes in contact") << ", released "
              << count(screen2.str(), "released") << std::endl;
      print_bound("  lifted: |wall reaction|",
                  std::hypot(lifted.wall_reaction[0], lifted.wall_reaction[1]),
                  1e-12);
      print_bound("  lifted: |top reaction|",
                  std::hypot(lifted.reactions.at(3)[0],
                             lifted.reactions.at(3)[1]),
                  1e-10);
      print_bound("  lifted: min gap - 0.015",
                  lifted.wall_min_gap - 0.015,
                  1e-12);
      // 'Contact = two-sided' (the source's implicit runs): held once
      // touched, so the lifted block hangs on the wall, whose (tensile)
      // reaction balances the top's.
      if (formulation == "FEM")
        {
          const pg::RunSummary glued = run_problem<2>(
            block(formulation, n, 2, "0.04*t - 0.03", "two-sided"),
            screen);
          deallog << "  two-sided, lifted: nodes held "
                  << glued.wall_active_nodes << std::endl;
          print_rounded("  two-sided, lifted: wall reaction y",
                        glued.wall_reaction[1],
                        3);
          print_bound("  two-sided, lifted: |R_wall + R_top| / |R_top|",
                      std::abs(glued.wall_reaction[1] +
                               glued.reactions.at(3)[1]) /
                        std::abs(glued.reactions.at(3)[1]),
                      1e-10);
          print_bound("  two-sided, lifted: min gap",
                      glued.wall_min_gap,
                      1e-12);
        }

      // standing on the wall, pressed by a traction alone
      const pg::RunSummary standing =
        run_problem<2>(block(formulation, n, 1, ""), screen);
      deallog << "  traction: nodes held " << standing.wall_active_nodes
              << std::endl;
      print_bound("  traction: |R_wall - (0, 0.01)| / 0.01",
                  std::hypot(standing.wall_reaction[0],
                             standing.wall_reaction[1] - 0.01) /
                    0.01,
                  1e-10);
      deallog << "  traction: min n . (x - p) >= -1e-12: "
              << (standing.wall_min_gap >= -1e-12 ? "yes" : "NO") << std::endl;
    }
}
