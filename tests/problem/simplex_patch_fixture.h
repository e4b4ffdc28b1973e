#ifndef pg_tests_simplex_patch_fixture_h
#define pg_tests_simplex_patch_fixture_h

// The linear patch test (prm/linear_patch_test.prm, benchmark B-4) on the
// Gmsh meshes of tests/mesh: distorted_triangles.msh (Dirichlet on tags 0,
// 1, 2, the exact traction on tag 3) and distorted_tetrahedra.msh (u = G X,
// Dirichlet on tags 0 to 4, the exact traction on tag 5), with the cells
// of 'Meshfree region' @p region meshfree (all: meshfree only).

#include "problem_fixture.h"

#include <iomanip>
#include <sstream>
#include <string>

inline std::string
patch_2d(const std::string &formulation, const std::string &region = "all")
{
  return read_file(SOURCE_DIR "/../../prm/linear_patch_test.prm") +
         "subsection Geometry\n  set Mesh = file\n"
         "  set File name = " SOURCE_DIR "/../mesh/distorted_triangles.msh\n"
         "  set Distortion = 0\n  set Meshfree region = " +
         region +
         "\nend\n"
         "subsection Discretization\n  set Formulation = " +
         formulation +
         "\nend\n"
         "subsection Output\n  set VTU = false\nend\n";
}



inline std::string
patch_3d(const std::string &formulation, const std::string &region = "all")
{
  return "set Dimension = 3\n"
         "subsection Geometry\n  set Mesh = file\n"
         "  set File name = " SOURCE_DIR
         "/../mesh/distorted_tetrahedra.msh\n  set Meshfree region = " +
         region +
         "\nend\n"
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



/**
 * Print "<label> <details>, round-off: yes" if the run @p s reproduced the
 * linear field (relative L2 and H1 errors below 1e-11), else "NO" and the
 * errors to 2 digits.
 */
inline void
print_patch_result(const std::string    &label,
                   const std::string    &details,
                   const pg::RunSummary &s)
{
  const bool exact = s.L2_relative < 1e-11 && s.H1_relative < 1e-11;
  deallog << "  " << std::left << std::setw(22) << label << std::right
          << details << ", round-off: " << (exact ? "yes" : "NO") << std::endl;
  if (!exact)
    {
      std::ostringstream line;
      line << std::setprecision(2) << s.L2_relative << ", " << s.H1_relative;
      deallog << "    relative L2, H1 errors: " << line.str() << std::endl;
    }
}

#endif
