// The quadratic patch test of prm/quadratic_patch_test.prm (benchmark B-5,
// Table 7.3): u quadratic, the stress linear, a constant body force,
// Dirichlet on three edges and a traction on the top edge.
//
// 1. Second-order variational consistency (VC2, on PPG2, option s) with
//    the quadratic trial space U2 (WTE2) reproduces u to round-off, with
//    V1 (the source's code) and with V3, when the top edge is loaded with
//    the test-function integral of the exact stress ('exact stress'); the
//    first- and second-order residuals d^k, D^k vanish at every interior
//    particle. With the load of eq. (4.32), T (n . d^k), it does not: the
//    first moment of the linear surface load is missing (printed).
// 2. Table 7.3's first-order rows on 36 x 36 cells (1369 particles; the
//    source has 1345) with the load of eq. (4.32) ('test functions'), in
//    the source's codes: 'PPG Unl' and 'VCPPG V3sn Unl' include the bond
//    correction (Table 7.1). Asserted: VC reduces the L2 error at least 100
//    times (benchmarks-from-seeds B-5; the source: 295 times), and its
//    absolute L2 error is below 2e-3 (the source: 5.95e-4).
// 3. Other rows for contrast on the 20 x 20 set of the prm.
// 4. The 'exact stress' load makes option s pass the linear patch test,
//    which it fails with the traction load T (n . d^k) (pg-methods.md 8.2).

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
  const std::string test_function_load =
    "subsection Boundary conditions\n"
    "  set Particle traction area = test functions\nend\n";

  deallog << "Round-off with 'exact stress' (relative L2 and H1 below "
             "1e-11):"
          << std::endl;
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
  {
    const pg::RunSummary s =
      run_problem<2>(with_formulation(quadratic, "VC2PPG V1s U2") +
                       test_function_load,
                     screen);
    std::ostringstream line;
    line << std::setprecision(2) << std::scientific << s.L2 << ", " << s.H1;
    deallog << "  VC2PPG V1s U2 with the load of eq. (4.32) instead: "
            << line.str()
            << " (not round-off: " << (s.L2_relative > 1e-8 ? "yes" : "NO")
            << ")" << std::endl;
  }

  deallog << "Table 7.3, 36 x 36 cells, load of eq. (4.32) (absolute L2, "
             "H1 error; the source's in brackets):"
          << std::endl;
  std::map<std::string, double> L2;
  for (const auto &[code, table] :
       std::vector<std::pair<std::string, std::string>>{
         {"PPG Unl", "(1.757e-1, 3.658e-1)"},
         {"VCPPG V3sn Unl", "(5.950e-4, 1.861e-2)"}})
    {
      const pg::RunSummary s =
        run_problem<2>(with_formulation(quadratic, code) + test_function_load +
                         "subsection Geometry\n  set Subdivisions = 36\nend\n",
                       screen);
      L2[code] = s.L2;
      std::ostringstream line;
      line << std::setprecision(2) << std::scientific << s.L2 << ", " << s.H1;
      deallog << "  " << std::left << std::setw(15) << code << std::right
              << line.str() << " " << table << std::endl;
    }
  deallog << "  VC reduces the L2 error at least 100 times: "
          << (L2["VCPPG V3sn Unl"] * 100 < L2["PPG Unl"] ? "yes" : "NO")
          << "; VC error below 2e-3: "
          << (L2["VCPPG V3sn Unl"] < 2e-3 ? "yes" : "NO") << std::endl;

  deallog << "Other rows, 20 x 20 cells, load of eq. (4.32) (absolute L2, "
             "H1 error):"
          << std::endl;
  for (const std::string code : {"VCPPG V3sn Unl noBC",
                                 "VCPBG V5sn Unl",
                                 "VC2PPG V1s Unl",
                                 "PPG2 U2",
                                 "FEM"})
    {
      const pg::RunSummary s =
        run_problem<2>(with_formulation(quadratic, code) + test_function_load,
                       screen);
      std::ostringstream line;
      line << std::setprecision(2) << std::scientific << s.L2 << ", " << s.H1;
      deallog << "  " << std::left << std::setw(20) << code << std::right
              << line.str() << std::endl;
    }

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
