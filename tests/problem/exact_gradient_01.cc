// Exact errors without 'Gradient expression' (issue 11, item 5): the H1
// and energy errors then take grad u from a fourth-order central
// difference of the exact displacement (h = 1e-4 of the mesh diameter).
// 1. The linear patch test (FEM and VCBCPBG V5sn Unl) stays at round-off,
//    relative H1 below 1e-12 (the deal.II default difference, central with
//    h = 1e-8, left a floor of about 1e-9).
// 2. The manufactured solution (sin/cos, FEM, 8 x 8 cells): the H1 error
//    with and without the gradient expression agrees to 1e-10 relative.

#include "../tests.h"
#include "problem_fixture.h"

// @p file with its 'Gradient expression' line removed and @p formulation.
std::string
without_gradient(const std::string &file, const std::string &formulation)
{
  std::istringstream in(read_file(file));
  std::string        line, result;
  bool               continued = false;
  while (std::getline(in, line))
    {
      const bool gradient =
        continued || line.find("Gradient expression") != std::string::npos;
      continued = gradient && !line.empty() && line.back() == '\\';
      if (!gradient)
        result += line + "\n";
    }
  return result +
         "subsection Discretization\n  set Formulation = " + formulation +
         "\nend\nsubsection Output\n  set VTU = false\nend\n";
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  std::ostringstream screen;

  const std::string linear = SOURCE_DIR "/../../prm/linear_patch_test.prm";
  for (const std::string code : {"FEM", "VCBCPBG V5sn Unl"})
    {
      const pg::RunSummary s =
        run_problem<2>(without_gradient(linear, code), screen);
      deallog << "linear patch test, " << code
              << ", no gradient expression: relative H1 below 1e-12: "
              << (s.H1_relative < 1e-12 ? "yes" : "NO") << std::endl;
    }

  const std::string manufactured =
    SOURCE_DIR "/../../prm/manufactured_solution.prm";
  const std::string options =
    "subsection Geometry\n  set Subdivisions = 8\n  set Global refinement "
    "= 0\nend\n";
  const pg::RunSummary with_gradient =
    run_problem<2>(read_file(manufactured) +
                     "subsection Discretization\n  set Formulation = FEM\nend\n"
                     "subsection Output\n  set VTU = false\nend\n" +
                     options,
                   screen);
  const pg::RunSummary difference =
    run_problem<2>(without_gradient(manufactured, "FEM") + options, screen);
  deallog << "manufactured solution, FEM: H1 error with and without the "
             "gradient expression agree to 1e-10: "
          << (std::abs(difference.H1 - with_gradient.H1) <
                  1e-10 * with_gradient.H1 ?
                "yes" :
                "NO")
          << std::endl;
}
