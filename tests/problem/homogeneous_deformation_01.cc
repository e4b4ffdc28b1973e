// A homogeneous finite deformation u = (F - 1) X, imposed on the whole
// boundary (neo-Hooke, 2 load steps), is reproduced to round-off by Q1
// finite elements on a distorted mesh in 2-D and 3-D.
//
// The uncorrected PG methods are not exact in this test, even on a regular
// lattice: near the boundary the discrete integration constraint d^k = 0
// fails (pg-methods.md section 9.4; see unit_stress_residual_01), so a
// constant stress leaves residual forces on interior particles near the
// surface. Their relative errors are printed as regression numbers for the
// VC correction, which is meant to make them round-off.

#include "../tests.h"
#include "problem_fixture.h"

std::string
parameters(const unsigned int dim,
           const std::string &formulation,
           const double       distortion)
{
  const std::string u =
    dim == 2 ? "t*(0.1*x + 0.3*y); t*(0.2*x + 0.4*y)" :
               "t*(0.1*x + 0.3*y + 0.1*z); t*(0.2*x - 0.1*y + 0.05*z); "
               "t*(-0.1*x + 0.1*y + 0.2*z)";
  const std::string  grad = dim == 2 ?
                              "0.1; 0.3; 0.2; 0.4" :
                              "0.1; 0.3; 0.1; 0.2; -0.1; 0.05; -0.1; 0.1; 0.2";
  std::ostringstream s;
  s << "set Dimension = " << dim << "\n"
    << "subsection Geometry\n"
    << "  set Lower corner = " << (dim == 2 ? "-1, -1" : "-1, -1, -1") << "\n"
    << "  set Upper corner = " << (dim == 2 ? "1, 1" : "1, 1, 1") << "\n"
    << "  set Subdivisions = " << (dim == 2 ? 10 : 4) << "\n"
    << "  set Distortion = " << distortion << "\n"
    << "end\n"
    << "subsection Discretization\n"
    << "  set Formulation = " << formulation << "\n"
    << "  set Horizon factor = " << (dim == 2 ? 2.51 : 2.01) << "\n"
    << "end\n"
    << "subsection Material\n"
    << "  set Model = neo-Hooke\n  set Young's modulus = 100\n"
    << "end\n"
    << "subsection Boundary conditions\n"
    << "  set Dirichlet = "
    << (dim == 2 ? "0: xy, 1: xy, 2: xy, 3: xy" :
                   "0: xyz, 1: xyz, 2: xyz, 3: xyz, 4: xyz, 5: xyz")
    << "\n  subsection Prescribed displacement\n"
    << "    set Function expression = " << u << "\n  end\n"
    << "end\n"
    << "subsection Exact solution\n"
    << "  set Compute errors = true\n"
    << "  set Function expression = " << u << "\n"
    << "  set Gradient expression = " << grad << "\n"
    << "end\n"
    << "subsection Loading\n  set Load steps = 2\nend\n"
    << "subsection Newton\n"
    << "  set Relative tolerance = 1e-14\n  set Absolute tolerance = 1e-13\n"
    << "end\n"
    << "subsection Output\n  set VTU = false\nend\n";
  return s.str();
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  std::ostringstream screen;

  for (const unsigned int dim : {2u, 3u})
    {
      const pg::RunSummary s =
        dim == 2 ? run_problem<2>(parameters(2, "FEM", 0.3), screen) :
                   run_problem<3>(parameters(3, "FEM", 0.2), screen);
      deallog << dim << "d FEM, distorted: converged " << s.converged << ", "
              << s.newton_iterations << " Newton iterations, "
              << "exact to round-off: "
              << (s.L2_relative < 1e-12 && s.H1_relative < 1e-12 ? "yes" : "NO")
              << std::endl;
      if (!(s.L2_relative < 1e-12 && s.H1_relative < 1e-12))
        deallog << "  L2 " << s.L2_relative << " H1 " << s.H1_relative
                << std::endl;
    }

  deallog << "2d uncorrected PG on a regular lattice (relative L2, H1 error):"
          << std::endl;
  for (const std::string code :
       {"PBG Unl", "BCPBG Unl", "PPG Unl", "BCPPG Unl", "BCPPG2 Unl", "PBG U1"})
    {
      const pg::RunSummary s = run_problem<2>(parameters(2, code, 0.), screen);
      std::ostringstream   line;
      line << std::setprecision(4) << s.L2_relative << ", " << s.H1_relative;
      deallog << "  " << std::left << std::setw(11) << code << std::right
              << line.str() << " (converged " << s.converged << ")"
              << std::endl;
    }
}
