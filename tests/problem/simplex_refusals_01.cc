// What triangle and tetrahedron meshes do not run (issue 49) stops with a
// message that names the parameter (or the cell and its position) and says
// what to do: mixed finite element cells on a simplex mesh (FEM Q1P0, a
// mixed PG code with a 'Meshfree region' other than all: P1-P0 locks), a
// mesh of triangles and quadrilaterals, second-order triangles, a triangle
// without area. P1 cells (FEM, or coupled to a PG displacement code) and
// the AMG operator of 'Q1 cells' (P1 cells here; GMRES to 1e-13) run and
// pass the patch test. A triangle numbered clockwise is not an error: GridIn
// renumbers it, and the run passes the patch test. Duplicated vertices where
// two blocks of triangles meet are merged (the patch test passes) or, with
// 'Coincident vertices = reject', named. On the hyper rectangle split by
// 'Cells = simplices' the same refusals name that entry and advise
// 'Cells = hypercubes'. (The test directory in the messages is printed as
// <tests>.)

#include "../tests.h"
#include "problem_fixture.h"

const std::string directory = SOURCE_DIR "/..";

std::string
parameters(const std::string &mesh, const std::string &changes)
{
  return read_file(SOURCE_DIR "/../../prm/linear_patch_test.prm") +
         "subsection Geometry\n  set Mesh = file\n"
         "  set File name = " +
         directory + "/mesh/" + mesh +
         "\n  set Distortion = 0\nend\n"
         "subsection Output\n  set VTU = false\nend\n" +
         changes;
}



void
check(const std::string &title,
      const std::string &mesh,
      const std::string &changes = "")
{
  deallog << title << ":" << std::endl;
  std::ostringstream screen;
  std::string        message;
  try
    {
      const pg::RunSummary s =
        run_problem<2>(parameters(mesh, changes), screen);
      deallog << "  no error; patch test at round-off: "
              << (s.L2_relative < 1e-11 && s.H1_relative < 1e-11 ? "yes" : "NO")
              << std::endl;
      return;
    }
  catch (ExceptionBase &e)
    {
      message = exception_message(e);
    }
  catch (std::exception &e)
    {
      message = std::string("  ") + e.what();
    }
  for (std::string::size_type p = message.find(directory);
       p != std::string::npos;
       p = message.find(directory))
    message.replace(p, directory.size(), "<tests>");
  deallog << message << std::endl;
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  check("FEM on triangles",
        "distorted_triangles.msh",
        "subsection Discretization\n  set Formulation = FEM\nend\n");
  check("finite element cells beside the particles on triangles",
        "distorted_triangles.msh",
        "subsection Geometry\n  set Meshfree region = box 0, -1.1 : 1.1, "
        "1.1\nend\n");
  check("FEM Q1P0 on triangles",
        "distorted_triangles.msh",
        "subsection Discretization\n  set Formulation = FEM Q1P0\nend\n");
  for (const std::string code :
       {"VCBCPBG V5sn UnlP0", "VCPBG V5sn U2P1", "VCBCPBG V5sn Unl+P1C"})
    check(code + " beside P1 cells on triangles",
          "distorted_triangles.msh",
          "subsection Discretization\n  set Formulation = " + code +
            "\nend\n"
            "subsection Geometry\n  set Meshfree region = box 0, -1.1 : "
            "1.1, 1.1\nend\n");
  check("triangles and quadrilaterals in one mesh",
        "mixed_triangles_quads.msh");
  check("second-order triangles", "second_order_triangles.msh");
  check("a triangle without area", "flat_triangle.msh");
  check("a triangle numbered clockwise", "inverted_triangle.msh");
  check("the AMG operator of Q1 (here P1) cells on triangles",
        "distorted_triangles.msh",
        "subsection Linear solver\n  set Type = gmres\n"
        "  set AMG operator = Q1 cells\n  set Tolerance = 1e-13\nend\n"
        "subsection Newton\n  set Relative tolerance = 1e-13\nend\n");
  check("two blocks of triangles with duplicated vertices, merged",
        "split_triangles.msh");
  check("two blocks of triangles with duplicated vertices, rejected",
        "split_triangles.msh",
        "subsection Geometry\n  set Coincident vertices = reject\nend\n");
  // the built-in mesh split by 'Cells = simplices': the hint is
  // 'Cells = hypercubes', not Gmsh's recombination
  const std::string split =
    "subsection Geometry\n  set Mesh = hyper rectangle\n"
    "  set Cells = simplices\n  set Lower corner = -1, -1\n"
    "  set Upper corner = 1, 1\n  set Subdivisions = 6\nend\n";
  check("FEM Q1P0 on the split hyper rectangle",
        "distorted_triangles.msh",
        split +
          "subsection Discretization\n  set Formulation = FEM Q1P0\nend\n");
  check("VCBCPBG V5sn UnlP0 beside P1 cells on the split hyper rectangle",
        "distorted_triangles.msh",
        split + "subsection Discretization\n"
                "  set Formulation = VCBCPBG V5sn UnlP0\nend\n"
                "subsection Geometry\n  set Meshfree region = box 0, -1.1 : "
                "1.1, 1.1\nend\n");
}
