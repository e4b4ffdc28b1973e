// ML's near-null space ('Linear solver/AMG near-null space'): with the
// rigid body modes, CG and GMRES preconditioned by ML need fewer Krylov
// iterations per Newton solve than with the translations alone, and both
// give the tip displacement of the direct solver. Cantilevers clamped at
// x = 0 under a dead traction at the free end, neo-Hooke, cells distorted
// by 0.25, one load step, above ML's coarse size of 2000 DoFs (below it ML
// solves directly): 3-D FEM (24 x 6 x 6 cells, length 4) with cg; 2-D
// (96 x 12 cells, length 8) BCPBG Unl with cg, VCBCPPG V3sn Unl and a
// coupled model (VCBCPPG V3sn Unl on the clamped half, Q1 on the other)
// with gmres. The measured counts against DoFs are in
// doc/benchmarks/amg_iterations.md.

#include "../tests.h"
#include "problem_fixture.h"

namespace
{
  struct Case
  {
    std::string  name;
    unsigned int dim;
    std::string  formulation, solver, region;
  };

  std::string
  cantilever(const Case &c, const std::string &solver, const std::string &modes)
  {
    const bool three = (c.dim == 3);
    return "set Dimension = " + std::to_string(c.dim) +
           "\nsubsection Geometry\n"
           "  set Lower corner = " +
           (three ? "0, 0, 0" : "0, 0") +
           "\n  set Upper corner = " + (three ? "4, 1, 1" : "8, 1") +
           "\n  set Subdivisions = " + (three ? "24, 6, 6" : "96, 12") +
           "\n  set Distortion   = 0.25\n" +
           (c.region.empty() ? "" :
                               "  set Meshfree region = " + c.region + "\n") +
           "end\n"
           "subsection Discretization\n  set Formulation = " +
           c.formulation +
           "\nend\n"
           "subsection Material\n"
           "  set Model           = neo-Hooke\n"
           "  set Young's modulus = 1000\n"
           "  set Poisson's ratio = 0.3\n"
           "end\n"
           "subsection Boundary conditions\n"
           "  set Dirichlet = 0: " +
           (three ? "xyz" : "xy") +
           "\n  set Neumann   = 1\n"
           "  subsection Traction\n"
           "    set Function expression = " +
           (three ? "0; 0; -t" : "0; -0.1*t") +
           "\n  end\nend\n"
           "subsection Loading\n  set Load steps = 1\nend\n"
           "subsection Linear solver\n  set Type                = " +
           solver +
           "\n  set Tolerance           = 1e-10\n"
           "  set AMG near-null space = " +
           modes +
           "\nend\n"
           "subsection Output\n"
           "  set Directory = results\n"
           "  set VTU       = false\n"
           "  set Points    = tip: " +
           (three ? "4, 0.5, 0.5" : "8, 0.5") + "\nend\n";
  }

  template <int dim>
  void
  run(const Case &c, std::ostream &screen)
  {
    deallog << c.name << ", " << c.solver << std::endl;
    const double u_direct =
      run_problem<dim>(cantilever(c, "direct", "translations"), screen)
        .points[0]
        .second[dim - 1];
    double iterations[2];
    for (const unsigned int rigid : {0, 1})
      {
        const pg::RunSummary s = run_problem<dim>(
          cantilever(c, c.solver, rigid ? "rigid body modes" : "translations"),
          screen);
        iterations[rigid] =
          static_cast<double>(s.assembly_cost.linear_iterations) /
          s.assembly_cost.n_solves;
        print_bound(std::string("  ") +
                      (rigid ? "rigid body modes" : "translations") +
                      ": |u(tip) / u(direct) - 1|",
                    s.points[0].second[dim - 1] / u_direct - 1.,
                    1e-7);
      }
    deallog << "  iterations per solve with the rigid body modes below 0.7 x "
               "those with the translations: "
            << (iterations[1] < 0.7 * iterations[0] ? "yes" : "NO")
            << std::endl;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  std::ostringstream screen;
  run<3>({"FEM 3-D", 3, "FEM", "cg", ""}, screen);
  run<2>({"BCPBG Unl 2-D", 2, "BCPBG Unl", "cg", ""}, screen);
  run<2>({"VCBCPPG V3sn Unl 2-D", 2, "VCBCPPG V3sn Unl", "gmres", ""}, screen);
  run<2>({"coupled VCBCPPG V3sn Unl / Q1 2-D",
          2,
          "VCBCPPG V3sn Unl",
          "gmres",
          "box 0, 0 : 4, 1"},
         screen);
}
