// The linear patch test (prm/linear_patch_test.prm, benchmark B-4) on Gmsh
// triangle and tetrahedron meshes, all cells meshfree (issue 49): the
// particles are the mesh vertices with volumes lumped from the simplices,
// the boundary area vectors come from the simplex faces.
//
// 2-D: u = (0.1 X + 0.3 Y, 0.2 X + 0.4 Y) on tests/mesh/
// distorted_triangles.msh ([-1,1]^2, 288 triangles, interior vertices moved
// by up to 0.3 h), Dirichlet on the left, right and bottom edges (Gmsh
// physical tags 0, 1, 2), the exact traction on the top edge (tag 3).
// 3-D: u = G X with G = ((0.1, 0.3, 0.2), (0.2, 0.4, 0.1), (0.1, 0.2,
// 0.3)) on distorted_tetrahedra.msh ([-1,1]^3, 384 tetrahedra),
// Dirichlet on the faces with tags 0 to 4, the exact traction
// T = sigma e_z = (0.3 mu, 0.3 mu, 0.6 mu + 0.8 lambda) on tag 5.
//
// Every VC code reproduces u to round-off (relative L2 and H1 errors
// below 1e-11), the mixed Unl+P1C too; the uncorrected PPG Unl does not
// (its errors are printed to 2 digits).

#include "../tests.h"
#include "problem_fixture.h"

std::string
patch_2d(const std::string &formulation)
{
  return read_file(SOURCE_DIR "/../../prm/linear_patch_test.prm") +
         "subsection Geometry\n  set Mesh = file\n"
         "  set File name = " SOURCE_DIR "/../mesh/distorted_triangles.msh\n"
         "  set Distortion = 0\nend\n"
         "subsection Discretization\n  set Formulation = " +
         formulation +
         "\nend\n"
         "subsection Output\n  set VTU = false\nend\n";
}



std::string
patch_3d(const std::string &formulation)
{
  return "set Dimension = 3\n"
         "subsection Geometry\n  set Mesh = file\n"
         "  set File name = " SOURCE_DIR
         "/../mesh/distorted_tetrahedra.msh\nend\n"
         "subsection Discretization\n  set Formulation = " +
         formulation +
         "\n  set Horizon factor = 2.51\nend\n"
         "subsection Material\n  set Model = linear elastic\n"
         "  set Young's modulus = 100\n  set Poisson's ratio = 0.3\nend\n"
         "subsection Boundary conditions\n"
         "  set Dirichlet = 0: xyz, 1: xyz, 2: xyz, 3: xyz, 4: xyz\n"
         "  set Neumann   = 5\n"
         "  subsection Prescribed displacement\n"
         "    set Function expression = 0.1*x + 0.3*y + 0.2*z; "
         "0.2*x + 0.4*y + 0.1*z; 0.1*x + 0.2*y + 0.3*z\n"
         "  end\n"
         "  subsection Traction\n"
         "    set Function constants  = lambda=57.692307692307692, "
         "mu=38.461538461538462\n"
         "    set Function expression = 0.3*mu; 0.3*mu; 0.6*mu + 0.8*lambda\n"
         "  end\n"
         "end\n"
         "subsection Exact solution\n  set Compute errors = true\n"
         "  set Function expression = 0.1*x + 0.3*y + 0.2*z; "
         "0.2*x + 0.4*y + 0.1*z; 0.1*x + 0.2*y + 0.3*z\n"
         "  set Gradient expression = 0.1; 0.3; 0.2; 0.2; 0.4; 0.1; 0.1; "
         "0.2; 0.3\nend\n"
         "subsection Output\n  set VTU = false\nend\n";
}



template <int dim>
void
check(const std::string &code, const std::string &parameters)
{
  std::ostringstream   screen;
  const pg::RunSummary s     = run_problem<dim>(parameters, screen);
  const bool           exact = s.L2_relative < 1e-11 && s.H1_relative < 1e-11;
  deallog << "  " << std::left << std::setw(22) << code << std::right
          << " particles " << s.n_particles
          << ", round-off: " << (exact ? "yes" : "NO") << std::endl;
  if (!exact)
    {
      std::ostringstream line;
      line << std::setprecision(2) << s.L2_relative << ", " << s.H1_relative;
      deallog << "    relative L2, H1 errors: " << line.str() << std::endl;
    }
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  deallog << "triangles:" << std::endl;
  for (const std::string code :
       {"VCBCPPG V3sn Unl", "VCBCPBG V5sn Unl", "VCBCPBG V5sn Unl+P1C"})
    check<2>(code, patch_2d(code));
  check<2>("PPG Unl noBC", patch_2d("PPG Unl noBC"));

  deallog << "tetrahedra:" << std::endl;
  for (const std::string code : {"VCBCPPG V3sn Unl", "VCBCPBG V5sn Unl"})
    check<3>(code, patch_3d(code));
}
