// 'Horizon' (absolute, in length units) beside 'Horizon factor' (issue 11,
// section 5). The factor gives each particle k its own horizon delta^k =
// factor x h^k, h^k the mean length of the meshfree cell edges at k; the
// absolute horizon is the same delta for every particle. On a regular
// lattice of spacing h = 1/8 every h^k is h, so 'Horizon = 2.51 h' gives the
// families, and the solution, of 'Horizon factor = 2.51' (BCPBG Unl, a
// square pulled by a traction). On a distorted lattice (Distortion 0.3) the
// two differ: the banner's family sizes are printed for both.

#include "../tests.h"
#include "problem_fixture.h"

std::string
parameters(const std::string &horizon, const double distortion)
{
  std::ostringstream s;
  s << "set Dimension = 2\n"
    << "subsection Geometry\n  set Subdivisions = 8\n"
    << "  set Distortion = " << distortion << "\nend\n"
    << "subsection Discretization\n"
    << "  set Formulation = BCPBG Unl\n"
    << horizon << "\nend\n"
    << "subsection Material\n  set Model = linear elastic\nend\n"
    << "subsection Boundary conditions\n  set Dirichlet = 0: xy\n"
    << "  set Neumann = 1\n  subsection Traction\n"
    << "    set Function expression = 0.1*t; 0.02*t\n  end\nend\n"
    << "subsection Output\n  set VTU = false\n"
    << "  set Directory = output_horizon\n"
    << "  set Points = corner: 1, 1\nend\n";
  return s.str();
}



std::string
family_line(const std::string &screen)
{
  std::istringstream lines(screen);
  std::string        line;
  while (std::getline(lines, line))
    if (line.find("family size:") != std::string::npos)
      return line;
  return "(no family line)";
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  for (const double distortion : {0., 0.3})
    {
      std::ostringstream   screen_factor, screen_absolute;
      const pg::RunSummary factor =
        run_problem<2>(parameters("  set Horizon factor = 2.51", distortion),
                       screen_factor);
      const pg::RunSummary absolute =
        run_problem<2>(parameters("  set Horizon = 0.31375", distortion),
                       screen_absolute);
      deallog << "Distortion " << distortion << ":" << std::endl;
      deallog << "  Horizon factor = 2.51:" << family_line(screen_factor.str())
              << std::endl;
      deallog << "  Horizon = 0.31375:    "
              << family_line(screen_absolute.str()) << std::endl;
      double difference = 0;
      for (unsigned int c = 0; c < 2; ++c)
        difference = std::max(difference,
                              std::abs(factor.points[0].second[c] -
                                       absolute.points[0].second[c]));
      if (distortion == 0.)
        print_bound("  |corner u (absolute) - corner u (factor)|",
                    difference,
                    1e-13);
      else
        deallog << "  the corner displacements differ: "
                << (difference > 1e-8 ? "yes" : "no") << std::endl;
      print_rounded("  corner u_x (factor)", factor.points[0].second[0], 6);
    }
}
