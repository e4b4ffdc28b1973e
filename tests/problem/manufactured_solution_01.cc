// Convergence rates on the manufactured solution of
// prm/manufactured_solution.prm (benchmark B-6, eqs. 7.7-7.8): all-Dirichlet
// linear elasticity with a body force, particles on distorted meshes with
// 8, 16, 32 and 64 cells per side (a new random distortion on every level).
// Least-squares rates of the relative L2 and H1 errors (eq. 7.3).
//
// Asserted: FEM 2 and 1 (>= 1.9, >= 0.9); with VC (V3 for PPG, V5 for PBG)
// >= 1.8 in L2 and >= 0.9 in H1, the bounds of the dissertation's claim
// (section 7.2.3: VC restores the optimal rates). The uncorrected methods
// are printed: their rates are sub-optimal. The codes carry BC explicitly:
// the dissertation's "Unl" includes it by default (Table 7.1), pg's codes
// switch it on only when they say BC. Measured in Release and close to the
// independent implementation of pg-methods.md ("Verified numerically" 2.):
// FEM 1.97/0.97, VCBCPPG V3sn 1.89/1.43 (1.92/1.44), VCBCPBG V5sn
// 1.99/1.33 (2.19/1.34), BCPPG 0.85/0.55 (0.96/0.53), BCPBG 0.78/0.29
// (0.88/0.29).

#include "../tests.h"
#include "problem_fixture.h"

#include <cmath>



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const std::string base =
    read_file(SOURCE_DIR "/../../prm/manufactured_solution.prm");
  std::ostringstream screen;

  for (const auto &[code, l2_bound, h1_bound] :
       std::vector<std::tuple<std::string, double, double>>{
         {"FEM", 1.9, 0.9},
         {"VCBCPPG V3sn Unl", 1.8, 0.9},
         {"VCBCPBG V5sn Unl", 1.8, 0.9},
         {"BCPPG Unl", 0., 0.},
         {"BCPBG Unl", 0., 0.}})
    {
      std::vector<double> h, l2, h1;
      for (const unsigned int n : {8u, 16u, 32u, 64u})
        {
          const pg::RunSummary s = run_problem<2>(
            base + "subsection Discretization\n  set Formulation = " + code +
              "\nend\nsubsection Geometry\n  set Subdivisions = " +
              std::to_string(n) + "\n  set Random seed = " + std::to_string(n) +
              "\nend\nsubsection Output\n  set VTU = false\nend\n",
            screen);
          h.push_back(2. / n);
          l2.push_back(s.L2_relative);
          h1.push_back(s.H1_relative);
        }
      const double       r0 = log_log_slope(h, l2), r1 = log_log_slope(h, h1);
      std::ostringstream rates;
      rates << std::fixed << std::setprecision(1) << r0 << " / " << r1;
      deallog << std::left << std::setw(17) << code << std::right
              << " rates L2 / H1: " << rates.str();
      if (l2_bound > 0)
        {
          std::ostringstream bounds;
          bounds << std::fixed << std::setprecision(1) << l2_bound << " / "
                 << h1_bound;
          deallog << ", at least " << bounds.str() << ": "
                  << (r0 >= l2_bound && r1 >= h1_bound ? "yes" : "NO");
        }
      deallog << std::endl;
    }
}
