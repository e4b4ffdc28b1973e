// P1 finite element cells on Gmsh triangle and tetrahedron meshes (issue
// 49): the linear patch test (prm/linear_patch_test.prm, benchmark B-4)
// with FEM everywhere and with P1 cells coupled to VC PG particles through
// the shared nodes (particles in a box over part of the mesh), and the
// rates of FEM on triangles for the manufactured solution of
// prm/manufactured_solution.prm.
//
// Patch tests: tests/mesh/distorted_triangles.msh ([-1,1]^2, 288
// triangles, Dirichlet on tags 0, 1, 2, the exact traction on the top edge,
// tag 3, which the coupled runs share between P1 faces and meshfree faces)
// and distorted_tetrahedra.msh ([-1,1]^3, 384 tetrahedra, Dirichlet on
// tags 0 to 4, the exact traction on tag 5), as in
// problem/simplex_patch_test_01. The coupled runs put the particles in
// the box x < 0.2 (triangles) or x < 0.1 (tetrahedra). Relative L2 and H1
// errors below 1e-11.
//
// Rates: the manufactured solution on distorted_triangles.msh with
// 'Global refinement' 0, 1, 2 (288 to 4608 triangles): L2 rate about 2, H1
// rate about 1 (printed to one decimal).

#include "../tests.h"
#include "simplex_patch_fixture.h"

#include <cmath>

template <int dim>
void
check(const std::string &code, const std::string &parameters)
{
  std::ostringstream   screen;
  const pg::RunSummary s = run_problem<dim>(parameters, screen);
  deallog << "  " << code << ": " << s.n_fe_cells << " P1 cells, "
          << s.n_particles << " particles" << std::endl;
  print_bound("    relative L2 error", s.L2_relative, 1e-11);
  print_bound("    relative H1 error", s.H1_relative, 1e-11);
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  deallog << "patch test, triangles:" << std::endl;
  check<2>("FEM", patch_2d("FEM", "all"));
  for (const std::string code : {"VCBCPPG V3sn Unl", "VCBCPBG V5sn Unl"})
    check<2>(code, patch_2d(code, "box -1.1, -1.1 : 0.2, 1.1"));

  deallog << "patch test, tetrahedra:" << std::endl;
  check<3>("FEM", patch_3d("FEM", "all"));
  for (const std::string code : {"VCBCPPG V3sn Unl", "VCBCPBG V5sn Unl"})
    check<3>(code, patch_3d(code, "box -1.1, -1.1, -1.1 : 0.1, 1.1, 1.1"));

  deallog << "manufactured solution, FEM on triangles:" << std::endl;
  double L2 = 0, H1 = 0;
  for (unsigned int refinement = 0; refinement < 3; ++refinement)
    {
      std::ostringstream   screen;
      const pg::RunSummary s = run_problem<2>(
        read_file(SOURCE_DIR "/../../prm/manufactured_solution.prm") +
          "subsection Geometry\n  set Mesh = file\n"
          "  set File name = " SOURCE_DIR "/../mesh/distorted_triangles.msh\n"
          "  set Distortion = 0\n  set Global refinement = " +
          std::to_string(refinement) +
          "\nend\n"
          "subsection Discretization\n  set Formulation = FEM\nend\n"
          "subsection Output\n  set VTU = false\nend\n",
        screen);
      std::ostringstream line;
      line << "  " << s.n_fe_cells << " P1 cells";
      if (refinement > 0)
        line << std::fixed << std::setprecision(1)
             << ": L2 rate = " << std::log2(L2 / s.L2_relative)
             << ", H1 rate = " << std::log2(H1 / s.H1_relative);
      deallog << line.str() << std::endl;
      L2 = s.L2_relative;
      H1 = s.H1_relative;
    }
}
