// The quadratic patch test of prm/quadratic_patch_test.prm (benchmark B-5,
// Table 7.3): u quadratic, the stress linear, a constant body force,
// Dirichlet on three edges and the exact stress on the top edge.
//
// Second-order variational consistency (VC2, on PPG2, option s) with the
// quadratic trial space U2 (WTE2) reproduces u to round-off, with V1 (the
// source's code) and with V3; the first- and second-order residuals d^k,
// D^k vanish at every interior particle. Nothing else does; their absolute
// errors are printed next to Table 7.3. The dissertation's "Unl" includes
// the bond correction, so its "PPG Unl" and "VCPPG V3sn Unl" are pg's
// BCPPG Unl and VCBCPPG V3sn Unl; the test requires first-order VC to
// reduce the uncorrected L2 error at least 20 times (the source: 295
// times on 1345 particles). Without BC, PPG1 is far less accurate on these
// distorted particles (also printed).
//
// Last, the 'exact stress' load makes option s pass the linear patch test,
// which it fails with the traction load T (n . d^k) (pg-methods.md 8.2).

#include "../tests.h"
#include "problem_fixture.h"

std::string
with_formulation(const std::string &file, const std::string &formulation)
{
  return read_file(file) +
         "subsection Discretization\n  set Formulation = " + formulation +
         "\nend\nsubsection Output\n  set VTU = false\nend\n";
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  std::ostringstream screen;
  const std::string  quadratic =
    SOURCE_DIR "/../../prm/quadratic_patch_test.prm";

  deallog << "Round-off (relative L2 and H1 below 1e-11):" << std::endl;
  for (const std::string code : {"VC2PPG V1s U2", "VC2PPG V3s U2"})
    {
      const pg::RunSummary s =
        run_problem<2>(with_formulation(quadratic, code), screen);
      deallog << "  " << std::left << std::setw(17) << code << std::right
              << " round-off: "
              << (s.L2_relative < 1e-11 && s.H1_relative < 1e-11 ? "yes" : "NO")
              << ", interior d^k = 0: "
              << (s.max_interior_unit_stress_residual < 1e-12 ? "yes" : "NO")
              << ", interior D^k = 0: "
              << (s.max_interior_second_order_residual < 1e-12 ? "yes" : "NO")
              << std::endl;
    }

  deallog << "Not exact (absolute L2, H1 error; Table 7.3 in brackets):"
          << std::endl;
  std::map<std::string, double> L2;
  for (const auto &[code, table] :
       std::vector<std::pair<std::string, std::string>>{
         {"BCPPG Unl", "(PPG Unl 1.8e-1, 3.7e-1)"},
         {"VCBCPPG V3sn Unl", "(VCPPG V3sn Unl 6.0e-4, 1.9e-2)"},
         {"VCPPG V3sn Unl", ""},
         {"VCBCPBG V5sn Unl", ""},
         {"VC2PPG V1s Unl", ""},
         {"PPG2 U2", ""},
         {"FEM", ""}})
    {
      const pg::RunSummary s =
        run_problem<2>(with_formulation(quadratic, code), screen);
      L2[code] = s.L2;
      std::ostringstream line;
      line << std::setprecision(2) << std::scientific << s.L2 << ", " << s.H1;
      deallog << "  " << std::left << std::setw(17) << code << std::right
              << line.str() << (table.empty() ? "" : " " + table) << std::endl;
    }
  deallog << "VCBCPPG V3sn Unl at least 20 times below BCPPG Unl: "
          << (L2["VCBCPPG V3sn Unl"] * 20 < L2["BCPPG Unl"] ? "yes" : "NO")
          << std::endl;

  const std::string linear =
    with_formulation(SOURCE_DIR "/../../prm/linear_patch_test.prm",
                     "VCPPG V3s Unl") +
    "subsection Boundary conditions\n"
    "  set Particle traction area = exact stress\nend\n";
  const pg::RunSummary s = run_problem<2>(linear, screen);
  deallog << "Linear patch test, VCPPG V3s Unl with 'exact stress': "
          << (s.L2_relative < 1e-11 && s.H1_relative < 1e-11 ? "round-off" :
                                                               "NOT exact")
          << std::endl;
}
