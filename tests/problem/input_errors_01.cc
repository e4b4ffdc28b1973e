// Bad input gives a clear message that names the entry (with its
// subsection) or the particle, and says how to fix it. The messages are
// part of the expected output, so rewording one is a reviewed change.

#include "../tests.h"
#include "problem_fixture.h"

void
check(const std::string &title, const std::string &changes)
{
  const std::string base = "set Dimension = 2\n"
                           "subsection Geometry\n"
                           "  set Subdivisions = 4\n"
                           "end\n"
                           "subsection Material\n"
                           "  set Model = linear elastic\n"
                           "end\n"
                           "subsection Boundary conditions\n"
                           "  set Dirichlet = 0: xy\n"
                           "  set Neumann = 1\n"
                           "  subsection Traction\n"
                           "    set Function expression = 0.1*t; 0\n"
                           "  end\n"
                           "end\n"
                           "subsection Output\n"
                           "  set VTU = false\n"
                           "end\n";
  deallog << title << ":" << std::endl;
  std::ostringstream screen;
  try
    {
      run_problem<2>(base + changes, screen);
      deallog << "  no error (wrong)" << std::endl;
    }
  catch (ExceptionBase &e)
    {
      deallog << exception_message(e) << std::endl;
    }
  catch (std::exception &e)
    {
      deallog << "  " << e.what() << std::endl;
    }
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  check("unknown formulation code",
        "subsection Discretization\n  set Formulation = XPBG Unl\nend\n");
  check("formulation not yet available",
        "subsection Discretization\n"
        "  set Formulation = VCPBG V5sn Unl UL\nend\n");
  check("incompressible formulation with a compressible material",
        "subsection Discretization\n"
        "  set Formulation = VCPBG V5sn IUnlP0\nend\n");
  check("incompressible formulation coupled to finite elements",
        "subsection Geometry\n  set Meshfree region = box 0, 0 : 0.5, 1\n"
        "end\n"
        "subsection Discretization\n"
        "  set Formulation = VCPBG V5sn IUnlP0\nend\n"
        "subsection Material\n  set Poisson's ratio = 0.5\nend\n");
  check("mixed formulation on a material without the volumetric split",
        "subsection Discretization\n"
        "  set Formulation = VCPPG V3sn UnlP0\nend\n"
        "subsection Material\n  set Model = saint venant kirchhoff\nend\n");
  check("function constant that is a formula, not a number",
        "subsection Boundary conditions\n  set Dirichlet = 0: xy\n"
        "  subsection Prescribed displacement\n"
        "    set Function constants  = a=10*pi/180\n"
        "    set Function expression = a*x; 0\n  end\nend\n");
  check("mixed formulation in plane stress",
        "subsection Discretization\n"
        "  set Formulation = FEM Q1P0\nend\n"
        "subsection Material\n  set Plane = stress\nend\n");
  check("hourglass coefficient on a formulation that is not U1",
        "subsection Discretization\n"
        "  set Formulation = VCPBG Unl\n"
        "  set Hourglass coefficient = 0.02\nend\n");
  check("correction function without VC",
        "subsection Discretization\n  set Formulation = PPG V3sn Unl\nend\n");
  check("contradictory formulation",
        "subsection Discretization\n  set Formulation = PPG U1\nend\n");
  check("VC2 on PBG",
        "subsection Discretization\n  set Formulation = VC2PBG V1s U2\nend\n");
  check("VC2 with option sn",
        "subsection Discretization\n  set Formulation = VC2PPG V1sn U2\nend\n");
  check("incompressible material",
        "subsection Material\n  set Poisson's ratio = 0.5\nend\n");
  check("horizon too small",
        "subsection Discretization\n  set Horizon factor = 0.5\nend\n");
  check("missing mesh file",
        "subsection Geometry\n  set Mesh = file\n"
        "  set File name = does_not_exist.msh\nend\n");
  check("CG with a non-symmetric tangent",
        "subsection Discretization\n  set Formulation = PPG Unl\nend\n"
        "subsection Linear solver\n  set Type = cg\nend\n");
  check("unknown displacement component",
        "subsection Boundary conditions\n  set Dirichlet = 0: xw\nend\n");
  check("reference point outside the body",
        "subsection Output\n  set Points = tip: 2, 0.5\nend\n");
  check("Newton does not converge",
        "subsection Material\n  set Model = neo-Hooke\nend\n"
        "subsection Boundary conditions\n  subsection Traction\n"
        "    set Function expression = 0.3*t; 0\n  end\nend\n"
        "subsection Newton\n  set Maximum iterations = 1\nend\n"
        "subsection Loading\n  set Maximum step cuts = 1\nend\n");
  check("CPD without one-neighbour interactions",
        "subsection Discretization\n  set Formulation = CPD\nend\n"
        "subsection CPD\n  set C1 = 0\n  set C2 = 1\nend\n");
  check("CPD volume interactions in 2-D",
        "subsection Discretization\n  set Formulation = CPD\nend\n"
        "subsection CPD\n  set C3 = 1\nend\n");
  check("CPD with a further part",
        "subsection Discretization\n  set Formulation = CPD U1\nend\n");
  check("fixed point off the mesh vertices",
        "subsection Boundary conditions\n  set Fixed points = 0.1, 0.5: "
        "y\nend\n");
  check("hole that is not a box",
        "subsection Geometry\n  set Hole = ball 0.5, 0.5 : 0.2\nend\n");
  check("Dirichlet box with the corners swapped",
        "subsection Boundary conditions\n  set Dirichlet boxes = 1, 1 : 0, 0 "
        ": xy\nend\n");
  check("Dirichlet box that holds no vertex",
        "subsection Boundary conditions\n  set Dirichlet boxes = 5, 5 : 6, 6 "
        ": xy\nend\n");
  check("Horizon and Horizon factor both set",
        "subsection Discretization\n  set Horizon = 0.5\n"
        "  set Horizon factor = 2.51\nend\n");
  check("negative Horizon",
        "subsection Discretization\n  set Horizon = -0.5\nend\n");
  check("NaN traction",
        "subsection Boundary conditions\n  subsection Traction\n"
        "    set Function expression = sqrt(-1)*t; 0\n  end\nend\n"
        "subsection Loading\n  set Maximum step cuts = 1\nend\n");
  check("line without an end",
        "subsection Output\n  set Lines = AA: 0, 0.7\nend\n");
}
