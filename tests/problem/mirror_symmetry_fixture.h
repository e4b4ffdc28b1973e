#ifndef pg_tests_mirror_symmetry_fixture_h
#define pg_tests_mirror_symmetry_fixture_h

// The body, load and output points of the symmetry-plane tests
// (mirror_symmetry_01 on quadrilaterals/hexahedra, simplex_mirror_symmetry_01
// on the same boxes split into simplices): a model is the full body or a
// part cut at the coordinate planes, with its symmetry boundaries.

#include <sstream>
#include <string>

struct Model
{
  std::string name;
  std::string lower, upper, subdivisions, symmetry, dirichlet;
};



/**
 * The parameter text of @p model: clamped at x = +-2 (the 'dirichlet'
 * ids), neo-Hooke (E = 100, nu = 0.3; the isochoric-volumetric split for
 * the mixed codes), the body force (20 x, 10 (y + y^3), 10 z) t, 'Symmetry
 * treatment' @p treatment on the 'symmetry' ids, CPD with bonds, triangles
 * (tetrahedra) and partial volumes, and three output points. @p
 * extra_geometry and @p extra_discretization are appended to those
 * subsections.
 */
template <int dim>
std::string
mirror_parameters(const Model       &model,
                  const std::string &formulation,
                  const std::string &extra_discretization = "",
                  const std::string &treatment            = "mirror",
                  const std::string &meshfree_region      = "all",
                  const std::string &extra_geometry       = "",
                  const std::string &directory = "output_mirror_symmetry")
{
  // the mixed codes (UnlP0, U2P1, U2P1C, Unl+P1C, Q1P0) need the split
  const bool mixed = formulation.find("P0") != std::string::npos ||
                     formulation.find("P1") != std::string::npos;
  std::ostringstream s;
  s << "set Dimension = " << dim << "\n"
    << "subsection Geometry\n"
    << extra_geometry << "  set Lower corner = " << model.lower << "\n"
    << "  set Upper corner = " << model.upper << "\n"
    << "  set Subdivisions = " << model.subdivisions << "\n"
    << "  set Meshfree region = " << meshfree_region << "\n"
    << "end\n"
    << "subsection Discretization\n"
    << "  set Formulation = " << formulation << "\n"
    << extra_discretization << "end\n"
    << "subsection Material\n"
    << "  set Model = "
    << (mixed ? "isochoric-volumetric neo-Hooke" : "neo-Hooke") << "\n"
    << "  set Young's modulus = 100\n  set Poisson's ratio = 0.3\n"
    << "end\n"
    << "subsection Boundary conditions\n"
    << "  set Dirichlet = " << model.dirichlet << "\n"
    << "  set Symmetry = " << model.symmetry << "\n"
    << "  set Symmetry treatment = " << treatment << "\n"
    << "  subsection Body force\n"
    << "    set Function expression = 20*x*t; 10*(y+y^3)*t"
    << (dim == 3 ? "; 10*z*t" : "") << "\n"
    << "  end\n"
    << "end\n"
    << (formulation == "CPD" ?
          // bonds, triangles (and tetrahedra in 3-D), partial volumes
          std::string("subsection CPD\n  set C1 = 1000\n  set C2 = 500\n") +
            (dim == 3 ? "  set C3 = 100\n" : "") +
            "  set Partial volumes = true\nend\n" :
          std::string())
    << "subsection Output\n"
    << "  set VTU = false\n  set Directory = " << directory << "\n"
    << "  set Points = "
    << (dim == 2 ? "a: 0.5, 0.25; b: 1.5, 0.75; c: 0.25, 0.125" :
                   "a: 0.5, 0.25, 0.5; b: 1.5, 0.75, 0.5; c: 0.25, 0.5, 0.75")
    << "\n"
    << "end\n";
  return s.str();
}

#endif
