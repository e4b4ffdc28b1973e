// Newton's method with the consistent CPD tangent under finite deformation
// (Javili et al. 2020, Table 3; benchmark C-7): prm/cpd_cube_extension.prm
// on a coarser lattice (6 x 6 x 6 cells, delta = 1.51 h), 100 % extension
// in 25 load steps, for one-neighbour interactions, one- plus two-, one-
// plus three-neighbour interactions, and the cube with a cubic hole of side
// 1/3. Printed like Table 3: the normalised residual |R|/|R_0| of every
// Newton iteration (rows) at load steps 1, 5, 10, 15, 20, 25 (columns),
// rounded to one digit (values below 1e-9 are printed as "<1e-9": their
// digits depend on round-off).
//
// Asserted: quadratic convergence. Near the solution (|R_{k-1}|/|R_0| <
// 1e-2) every iteration gains at least 3 orders of magnitude or reaches
// round-off (< 1e-12), and every step converges to 1e-13 within 6
// iterations.

#include "../tests.h"
#include "problem_fixture.h"

void
table(const std::string &title, const std::string &overrides)
{
  std::ostringstream   screen;
  const pg::RunSummary s = run_problem<3>(
    read_file(SOURCE_DIR "/../../prm/cpd_cube_extension.prm") +
      "subsection Geometry\n set Subdivisions = 6\nend\n"
      "subsection Discretization\n set Horizon factor = 1.51\nend\n"
      "subsection Output\n set VTU = false\nend\n" +
      overrides,
    screen);
  deallog << title << " (" << s.newton_residuals.size() << " steps)"
          << std::endl;
  const std::vector<unsigned int> columns = {1, 5, 10, 15, 20, 25};
  unsigned int                    rows    = 0;
  bool quadratic = s.newton_residuals.size() == 25, fast = true;
  for (const auto &r : s.newton_residuals)
    {
      rows = std::max<unsigned int>(rows, r.size());
      fast = fast && r.size() <= 7;
      for (unsigned int k = 1; k < r.size(); ++k)
        if (r[k - 1] / r[0] < 1e-2 && r[k] / r[0] >= 1e-12 &&
            r[k] / r[k - 1] > 1e-3)
          quadratic = false;
    }
  for (unsigned int k = 0; k < rows; ++k)
    {
      std::ostringstream line;
      line << "  iteration " << k + 1 << ":";
      for (const unsigned int step : columns)
        {
          const auto &r = s.newton_residuals[step - 1];
          line << std::setw(9);
          if (k >= r.size())
            line << "";
          else if (r[k] / r[0] < 1e-9)
            line << "<1e-9";
          else
            {
              std::ostringstream v;
              v << std::scientific << std::setprecision(0) << r[k] / r[0];
              line << v.str();
            }
        }
      deallog << line.str() << std::endl;
    }
  deallog << "  quadratic: " << (quadratic ? "yes" : "NO")
          << ", at most 6 iterations per step: " << (fast ? "yes" : "NO")
          << std::endl;
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  deallog << "|R|/|R_0| at load steps     1        5       10       15       "
             "20       25"
          << std::endl;
  table("one-neighbour", "");
  table("one- and two-neighbour", "subsection CPD\n set C2 = 20\nend\n");
  table("one- and three-neighbour", "subsection CPD\n set C3 = 200\nend\n");
  table("one-neighbour, cube with a hole",
        "subsection Geometry\n set Hole = box 0.34,0.34,0.34 : "
        "0.66,0.66,0.66\nend\n");
}
