// Stability and sparsity of CPD (Javili et al. 2020, section 4.2 and
// Fig. 16; benchmarks C-3 and C-8), from the tangent of a free body in the
// reference state (prm/eigenmodes_block.prm: 20 x 10 particles, delta =
// 2.51 h; and a free 4 x 4 x 4 cube, delta = 1.51 h):
// * with C1 > 0 there are exactly d(d+1)/2 zero eigenvalues (the rigid
//   motions: 3 in 2-D, 6 in 3-D) and no negative one, with or without two-
//   and three-neighbour interactions, and for a slightly negative C2
//   (the auxetic side); a strongly negative C2 (-5 at this spacing h = 1,
//   where the area terms outweigh the bonds by C2 h^3 / C1) makes the
//   energy non-convex: many negative eigenvalues, printed as a warning
//   example;
// * the number of matrix entries (the one-horizon stencil of the
//   neighbour graph) does not change when C2 or C3 are switched on: higher
//   interactions add work, not nonzeros.
// (C1 = 0 is rejected: tests/problem/input_errors_01.)

#include "../tests.h"
#include "problem_fixture.h"

#include <algorithm>

template <int dim>
void
check(const std::string &base, const std::string &constants)
{
  std::ostringstream   screen;
  const pg::RunSummary s = run_problem<dim>(
    base +
      "subsection Discretization\n set Formulation = CPD\nend\n"
      "subsection CPD\n" +
      constants + "\nend\n",
    screen);
  unsigned int negative = 0;
  for (const double e : s.eigenvalues)
    negative += (e < -1e-10 * s.max_eigenvalue);
  std::ostringstream first;
  first << std::setprecision(3)
        << s.eigenvalues[s.n_zero_eigenvalues] / s.max_eigenvalue;
  std::string label = constants;
  std::replace(label.begin(), label.end(), '\n', ',');
  deallog << dim << "-D, " << label << ": zero eigenvalues "
          << s.n_zero_eigenvalues << ", negative " << negative
          << ", first non-zero / largest " << first.str() << ", matrix entries "
          << s.matrix_nonzeros << std::endl;
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const std::string block =
    read_file(SOURCE_DIR "/../../prm/eigenmodes_block.prm");
  check<2>(block, "set C1 = 1");
  check<2>(block, "set C1 = 1\nset C2 = 50");
  check<2>(block, "set C1 = 1\nset C2 = -0.1");
  check<2>(block, "set C1 = 1\nset C2 = -5");
  const std::string cube = "set Dimension = 3\n"
                           "subsection Geometry\n"
                           "  set Lower corner = 0, 0, 0\n"
                           "  set Upper corner = 1, 1, 1\n"
                           "  set Subdivisions = 4\n"
                           "end\n"
                           "subsection Discretization\n"
                           "  set Horizon factor = 1.51\n"
                           "end\n"
                           "subsection Analysis\n"
                           "  set Type = eigenmodes\n"
                           "end\n"
                           "subsection Output\n"
                           "  set Directory = results\n"
                           "  set VTU = false\n"
                           "end\n";
  check<3>(cube, "set C1 = 1");
  check<3>(cube, "set C1 = 1\nset C2 = 5\nset C3 = 50");
}
