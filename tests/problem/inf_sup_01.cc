// The numerical inf-sup test (Analysis/Type = inf-sup, benchmark B-8,
// dissertation section 7.2.5) checked against what is known exactly:
// * Q1P0, clamped unit square: N = 2 has one free node and
//   beta~^2 = 3/8 (T = 1, S = 8/3 per component); for even N the kernel
//   of the P0 divergence is the constant pressure and the checkerboard,
//   so the zero eigenvalues number n_u - n_p + 2 (k_pm = 2, eq. 7.15),
//   and beta~ decays like h (Chapelle & Bathe 1993): slope in [0.8, 1.2].
// * Q1 displacement-based (full div-div): locks, slope in [0.9, 1.1].
// * S_h is positive definite once a side is clamped; a free body and a
//   PPG formulation are refused with a clear message, as are a stabilised
//   U1 (its stabilisation is not in T_h, S_h) and meshes too
//   big for the dense solver.

#include "../tests.h"
#include "problem_fixture.h"

#include <cmath>

const std::string base = "set Dimension = 2\n"
                         "subsection Discretization\n"
                         "  set Formulation = FEM\n"
                         "end\n"
                         "subsection Boundary conditions\n"
                         "  set Dirichlet = 0: xy, 1: xy, 2: xy, 3: xy\n"
                         "end\n"
                         "subsection Analysis\n"
                         "  set Type = inf-sup\n"
                         "end\n"
                         "subsection Output\n"
                         "  set VTU = false\n"
                         "end\n";

pg::RunSummary
run(const std::string &changes)
{
  std::ostringstream screen;
  return run_problem<2>(base + changes, screen);
}

void
check_error(const std::string &title, const std::string &changes)
{
  deallog << title << ":" << std::endl;
  try
    {
      run(changes);
      deallog << "  no error (wrong)" << std::endl;
    }
  catch (ExceptionBase &e)
    {
      deallog << exception_message(e) << std::endl;
    }
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  {
    const pg::RunSummary s =
      run("subsection Analysis\n  set Pressure space = P0\n"
          "  set Inf-sup subdivisions = 2, 4, 8, 16\nend\n");
    const auto &r = s.inf_sup;
    deallog << "Q1P0: beta(N = 2)^2 - 3/8 = "
            << (std::abs(r.beta[0] * r.beta[0] - 0.375) < 1e-12 ? "0" : "wrong")
            << std::endl;
    for (unsigned int i = 1; i < r.N.size(); ++i)
      {
        const int expected = r.n_free[i] - r.n_pressure[i] + 2;
        deallog << "Q1P0 N = " << int(r.N[i]) << ": zero eigenvalues "
                << int(r.n_zero[i]) << " (n_u - n_p + 2 = " << expected
                << "), k_pm = " << int(r.k_pm[i]) << std::endl;
      }
    deallog << "Q1P0 slope 8 -> 16 in [0.8, 1.2]: "
            << (r.slope[3] >= 0.8 && r.slope[3] <= 1.2 ? "yes" : "no")
            << std::endl;
  }
  {
    const pg::RunSummary s =
      run("subsection Analysis\n  set Pressure space = displacement\n"
          "  set Inf-sup subdivisions = 8, 16\nend\n");
    deallog << "Q1 displacement: zero eigenvalues " << int(s.inf_sup.n_zero[1])
            << ", slope 8 -> 16 in [0.9, 1.1]: "
            << (s.inf_sup.slope[1] >= 0.9 && s.inf_sup.slope[1] <= 1.1 ? "yes" :
                                                                         "no")
            << std::endl;
  }
  {
    // Clamped on one side only: S_h is still positive definite.
    const pg::RunSummary s =
      run("subsection Boundary conditions\n  set Dirichlet = 0: xy\nend\n"
          "subsection Analysis\n  set Inf-sup subdivisions = 4\nend\n");
    deallog << "clamped on x = 0 only: S positive definite, "
            << int(s.inf_sup.n_free[0]) << " free DoFs" << std::endl;
  }
  check_error("free body",
              "subsection Boundary conditions\n  set Dirichlet =\nend\n"
              "subsection Analysis\n  set Inf-sup subdivisions = 2\nend\n");
  check_error("PPG",
              "subsection Geometry\n  set Meshfree region = all\nend\n"
              "subsection Discretization\n  set Formulation = PPG Unl\nend\n"
              "subsection Analysis\n  set Inf-sup subdivisions = 2\nend\n");
  check_error("U1SIG",
              "subsection Geometry\n  set Meshfree region = all\nend\n"
              "subsection Discretization\n  set Formulation = VCPBG U1SIG\n"
              "end\n"
              "subsection Analysis\n  set Inf-sup subdivisions = 2\nend\n");
  check_error("too big",
              "subsection Analysis\n  set Inf-sup subdivisions = 2, 64\n"
              "end\n");
}
