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
#include "simplex_patch_fixture.h"

template <int dim>
void
check(const std::string &code, const std::string &parameters)
{
  std::ostringstream   screen;
  const pg::RunSummary s = run_problem<dim>(parameters, screen);
  print_patch_result(code, " particles " + std::to_string(s.n_particles), s);
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
