// Node sets of an Exodus II mesh as Dirichlet conditions ('Dirichlet node
// sets'), side sets as loaded boundaries: the bar of tests/exodus/bar_hex.g
// (two element blocks, unmerged at x = 1, interior nodes moved), once
// refined, u_x = 0 on node set 'left' (x = 0), u_y = 0 on the edge
// 'nodelist_5' (x = y = 0), u_z = 0 on the corner 'nodelist_6', a unit
// traction in x on side set 7 (x = 3). The exact solution is uniaxial
// stress, u = (x, -nu y, -nu z) / E: FEM and VCBCPBG V5sn Unl reproduce it
// to round-off, and the reaction of node set 'left' balances the load
// (-1, 0, 0). The same on 2 MPI ranks. The triangles of square_tri.g
// (2-D, P1 cells) likewise.

#include <pg/base/exceptions.h>

#include "../problem/problem_fixture.h"
#include "../tests.h"

#include <cmath>
#include <sstream>
#include <string>

namespace
{
  std::string
  bar(const std::string &formulation)
  {
    return "set Dimension = 3\n"
           "subsection Geometry\n  set Mesh = file\n"
           "  set File name = " SOURCE_DIR "/bar_hex.g\n"
           "  set Global refinement = 1\nend\n"
           "subsection Discretization\n  set Formulation = " +
           formulation +
           "\nend\n"
           "subsection Material\n  set Model = linear elastic\n"
           "  set Young's modulus = 10\n  set Poisson's ratio = 0.3\nend\n"
           "subsection Boundary conditions\n"
           "  set Dirichlet node sets = left: x, nodelist_5: y, "
           "nodelist_6: z\n"
           "  set Neumann = 7\n"
           "  subsection Traction\n    set Function expression = 1; 0; 0\n"
           "  end\nend\n"
           "subsection Exact solution\n  set Compute errors = true\n"
           "  set Function expression = x/10; -0.03*y; -0.03*z\n"
           "  set Gradient expression = 0.1; 0; 0; 0; -0.03; 0; 0; 0; "
           "-0.03\nend\n"
           "subsection Output\n  set VTU = false\n"
           "  set Directory = output_" +
           std::to_string(formulation.size()) + "\nend\n";
  }



  std::string
  square(const std::string &formulation)
  {
    return "set Dimension = 2\n"
           "subsection Geometry\n  set Mesh = file\n"
           "  set File name = " SOURCE_DIR "/square_tri.g\n"
           "  set Global refinement = 2\nend\n"
           "subsection Discretization\n  set Formulation = " +
           formulation +
           "\nend\n"
           "subsection Material\n  set Model = linear elastic\n"
           "  set Young's modulus = 10\n  set Poisson's ratio = 0.3\n"
           "  set Plane = stress\nend\n"
           "subsection Boundary conditions\n"
           "  set Dirichlet node sets = left: x, nodelist_2: y\n"
           "  set Neumann = 4\n"
           "  subsection Traction\n    set Function expression = 1; 0\n"
           "  end\nend\n"
           "subsection Exact solution\n  set Compute errors = true\n"
           "  set Function expression = x/10; -0.03*y\n"
           "  set Gradient expression = 0.1; 0; 0; -0.03\nend\n"
           "subsection Output\n  set VTU = false\n"
           "  set Directory = output_2d_" +
           std::to_string(formulation.size()) + "\nend\n";
  }



  void
  print(const std::string &what, const pg::RunSummary &summary)
  {
    deallog << what << ": " << summary.n_particles << " particles, "
            << summary.n_dofs << " DoFs, converged " << summary.converged
            << std::endl;
    deallog << "  relative L2 error < 1e-10: " << (summary.L2_relative < 1e-10)
            << ", H1: " << (summary.H1_relative < 1e-10) << std::endl;
    for (const auto &[name, r] : summary.node_set_reactions)
      {
        deallog << "  reaction on node set " << name << ":";
        for (const double v : r)
          deallog << " "
                  << (std::abs(v) < 1e-10 ? 0. : std::round(v * 1e8) / 1e8);
        deallog << std::endl;
      }
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    initlog();
  else
    deallog.depth_console(0);
  std::ostringstream screen;
  print("bar, FEM", run_problem<3>(bar("FEM"), screen));
  print("bar, VCBCPBG V5sn Unl",
        run_problem<3>(bar("VCBCPBG V5sn Unl"), screen));
  print("triangles, FEM", run_problem<2>(square("FEM"), screen));
  print("triangles, VCBCPBG V5sn Unl",
        run_problem<2>(square("VCBCPBG V5sn Unl"), screen));
}
