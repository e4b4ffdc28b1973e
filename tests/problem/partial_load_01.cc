// Loads on part of a face ('Particle traction area = test functions',
// issue 45): the resultant of a pressure q on a patch of the top of a block
// equals its face integral to round-off, and the moment about the face
// centre is close to the exact one.
// 1. 2-D, the block [-1, 1] x [0, 1] on 20 x 10 cells (spacing 0.1), fixed
//    at the bottom, the pressure on -0.23 < x < 0.41 (6.4 spacings, both
//    edges inside cells) of the top (id 3), given by a traction function
//    that is zero outside the patch; VCBCPPG V3sn Unl and VCBCPBG V5sn Unl.
//    Eq. 4.32 alone (T(X^k) c_b) put q on the 7 particles inside the patch
//    and missed the resultant by +7.4 % (printed: the relative error of
//    the sum of T(X^k) c_b against the face integral, QGauss(2): 0.65;
//    +9.1 % against q times the width, 0.64).
// 2. 2-D, the same block read from a mesh file in which the patch
//    -0.2 < x < 0.4 of the top is a boundary id of its own (6, loaded with
//    a uniform traction; the rest of the top, id 3, is free): the particles
//    at x = -0.2 and 0.4 have parts of ids 3 and 6 in one plane, and eq.
//    4.32 gave each part the particle's whole area.
// 3. 3-D, the full block [-0.1, 0.1]^2 x [0, 0.05] on 8 x 8 x 4 cells
//    (n = 4, spacing 0.025), a centred patch |x|, |y| < 0.04 of the top,
//    VCBCPBG V5sn Unl.
// The moment is about the centroid of the loaded face (id 3 or 5: the
// whole top; id 6: the patch); the exact one is q times the first moment
// of the patch, so the 2-D ratio tells how well the load's centre is
// placed (the correction fixes the resultant only; the moment is within
// 0.3 % here and converges like h^3, README).

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_out.h>
#include <deal.II/grid/tria.h>

#include "../tests.h"
#include "problem_fixture.h"

std::string
parameters(const unsigned int dim,
           const std::string &formulation,
           const std::string &mesh)
{
  std::ostringstream s;
  s << "set Dimension = " << dim << "\n"
    << "subsection Geometry\n";
  if (!mesh.empty())
    s << "  set Mesh = file\n  set File name = " << mesh << "\n";
  else if (dim == 2)
    s << "  set Lower corner = -1, 0\n  set Upper corner = 1, 1\n"
      << "  set Subdivisions = 20, 10\n";
  else
    s << "  set Lower corner = -0.1, -0.1, 0\n"
      << "  set Upper corner = 0.1, 0.1, 0.05\n"
      << "  set Subdivisions = 8, 8, 4\n";
  s << "end\n"
    << "subsection Discretization\n"
    << "  set Formulation = " << formulation << "\n"
    << "end\n"
    << "subsection Material\n"
    << "  set Model = linear elastic\n"
    << "  set Young's modulus = 100\n"
    << "  set Poisson's ratio = 0.3\n"
    << "end\n"
    << "subsection Boundary conditions\n"
    << "  set Particle traction area = test functions\n";
  if (dim == 2)
    s << "  set Dirichlet = 2: xy\n"
      << "  set Neumann = " << (mesh.empty() ? "3" : "6") << "\n"
      << "  subsection Traction\n"
      << "    set Function expression = 0; "
      << (mesh.empty() ? "-t * if(x > -0.23 && x < 0.41, 1, 0)" : "-t")
      << "\n  end\n";
  else
    s << "  set Dirichlet = 4: xyz\n"
      << "  set Neumann = 5\n"
      << "  subsection Traction\n"
      << "    set Function expression = 0; 0; "
      << "-t * if(abs(x) < 0.04 && abs(y) < 0.04, 1, 0)\n"
      << "  end\n";
  s << "end\n"
    << "subsection Loading\n  set Load steps = 1\nend\n"
    << "subsection Output\n  set VTU = false\nend\n";
  return s.str();
}



/** The block of case 2 with the patch -0.2 < x < 0.4 of the top as id 6. */
std::string
write_patch_mesh()
{
  Triangulation<2> tria;
  GridGenerator::subdivided_hyper_rectangle(tria,
                                            {20, 10},
                                            Point<2>(-1, 0),
                                            Point<2>(1, 1),
                                            true);
  for (const auto &face : tria.active_face_iterators())
    if (face->at_boundary() && face->boundary_id() == 3 &&
        face->center()[0] > -0.2 && face->center()[0] < 0.4)
      face->set_boundary_id(6);
  const std::string name = "patch_mesh.ucd";
  std::ofstream     file(name);
  GridOut           out;
  out.set_flags(GridOutFlags::Ucd(false, true));
  out.write_ucd(tria, file);
  return name;
}



/** |a - b| / |b| of two force vectors. */
double
relative_difference(const std::vector<double> &a, const std::vector<double> &b)
{
  double d = 0, n = 0;
  for (unsigned int c = 0; c < a.size(); ++c)
    {
      d += (a[c] - b[c]) * (a[c] - b[c]);
      n += b[c] * b[c];
    }
  return std::sqrt(d / n);
}



void
report(const std::string &name, const pg::RunSummary &s)
{
  deallog << name << std::endl;
  for (const auto &r : s.neumann_resultants)
    if (r.n_partly_loaded > 0)
      {
        const double error = relative_difference(r.force, r.exact_force);
        deallog << "  id " << static_cast<int>(r.id) << ": "
                << r.n_partly_loaded
                << " partly loaded particles, resultant - exact "
                << (error < 1e-12 ? "< 1e-12 (yes)" : "NOT round-off")
                << std::endl;
        if (error >= 1e-12)
          deallog << "    " << error << std::endl;
        std::ostringstream before, moment;
        before << std::showpos << std::setprecision(3)
               << relative_difference(r.point_force, r.exact_force) *
                    (std::abs(r.point_force[s.dimension - 1]) >
                         std::abs(r.exact_force[s.dimension - 1]) ?
                       1 :
                       -1);
        deallog << "  eq. 4.32 alone: |resultant - exact| / |exact| = "
                << before.str() << " (sign: more or less load)" << std::endl;
        // the moment about the centre, relative to q times the area and
        // the patch size: components below 1e-10 are round-off (symmetry)
        double scale = 0;
        for (const double f : r.exact_force)
          scale += f * f;
        scale = std::sqrt(scale) * 0.1;
        moment << std::setprecision(4);
        for (unsigned int c = 0; c < r.moment.size(); ++c)
          {
            const double m = r.moment[c] / scale, e = r.exact_moment[c] / scale;
            moment << " " << (std::abs(m) < 1e-10 ? 0. : m) << " (exact "
                   << (std::abs(e) < 1e-10 ? 0. : e) << ")";
          }
        deallog << "  moment / (|F| 0.1):" << moment.str() << std::endl;
      }
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  std::ostringstream screen;

  for (const std::string code : {"VCBCPPG V3sn Unl", "VCBCPBG V5sn Unl"})
    report("2-D, patch in the traction function, " + code,
           run_problem<2>(parameters(2, code, ""), screen));
  const std::string mesh = write_patch_mesh();
  for (const std::string code : {"VCBCPPG V3sn Unl", "VCBCPBG V5sn Unl"})
    report("2-D, patch as boundary id 6, " + code,
           run_problem<2>(parameters(2, code, mesh), screen));
  report("3-D, centred patch on the top, n = 4, VCBCPBG V5sn Unl",
         run_problem<3>(parameters(3, "VCBCPBG V5sn Unl", ""), screen));
}
