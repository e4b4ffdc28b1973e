// The linear patch test (prm/linear_patch_test.prm, benchmark B-4) on the
// built-in meshes split into simplices ('Geometry/Cells = simplices',
// issue 49): the hyper rectangle [-1,1]^dim, distorted and then split into
// 8 triangles (24 tetrahedra) per cell.
//
// 2-D: 6 x 6 quadrilaterals, 'Distortion = 0.3', split into 288 triangles
// (169 particles); u = (0.1 X + 0.3 Y, 0.2 X + 0.4 Y), Dirichlet on x = -1,
// x = 1 and y = -1, the exact traction on y = 1.
// 3-D: 3 x 3 x 3 hexahedra, 'Distortion = 0.2', split into 648 tetrahedra
// (172 particles); u = G X (tests/problem/simplex_patch_fixture.h),
// Dirichlet on the faces 0 to 4, the exact traction on z = 1.
//
// P1 finite elements, VCBCPPG V3sn Unl and VCBCPBG V5sn Unl (meshfree
// only) and P1 cells coupled to VCBCPBG V5sn Unl particles in the box
// x < 0.2 reproduce u to round-off (relative L2 and H1 errors below
// 1e-11).

#include "../tests.h"
#include "simplex_patch_fixture.h"

template <int dim>
std::string
split_mesh(const std::string &formulation, const std::string &region)
{
  const std::string box      = (dim == 2 ? "box -1.1, -1.1 : 0.2, 1.1" :
                                           "box -1.1, -1.1, -1.1 : 0.2, 1.1, 1.1");
  const std::string meshfree = (region == "all" ? "all" : box);
  return (dim == 2 ? patch_2d(formulation, meshfree) :
                     patch_3d(formulation, meshfree)) +
         "subsection Geometry\n  set Mesh = hyper rectangle\n"
         "  set Cells = simplices\n" +
         (dim == 2 ? "  set Lower corner = -1, -1\n  set Upper corner = 1, 1\n"
                     "  set Subdivisions = 6\n  set Distortion = 0.3\n" :
                     "  set Lower corner = -1, -1, -1\n"
                     "  set Upper corner = 1, 1, 1\n"
                     "  set Subdivisions = 3\n  set Distortion = 0.2\n") +
         "end\n";
}



template <int dim>
void
check(const std::string &formulation, const std::string &region = "all")
{
  std::ostringstream   screen;
  const pg::RunSummary s =
    run_problem<dim>(split_mesh<dim>(formulation, region), screen);
  print_patch_result(formulation,
                     std::string(region == "all" ? "" : " coupled") +
                       (s.n_particles > 0 ?
                          " particles " + std::to_string(s.n_particles) :
                          " (P1 cells)"),
                     s);
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  deallog << "split into triangles:" << std::endl;
  for (const std::string code : {"FEM", "VCBCPPG V3sn Unl", "VCBCPBG V5sn Unl"})
    check<2>(code);
  check<2>("VCBCPBG V5sn Unl", "box");
  deallog << "split into tetrahedra:" << std::endl;
  for (const std::string code : {"FEM", "VCBCPPG V3sn Unl", "VCBCPBG V5sn Unl"})
    check<3>(code);
  check<3>("VCBCPBG V5sn Unl", "box");
}
