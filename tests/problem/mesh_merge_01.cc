// Coincident vertices in a mesh file (issue 11, item 4). Peridigm's
// tensile-test mesh comes with 252 coincident node pairs where Cubit's
// blocks meet; unmerged, FEM solved a singular system silently, BCPBG Unl
// assembled NaN and VC stopped. Here the same cause at a small size: a bar
// [0,2] x [0,1] (x [0,1] in 3-D) of two blocks that meet at x = 1, as the
// Gmsh files two_blocks_*.msh written by two_blocks_meshes.py, merged and
// unmerged (5 node pairs on x = 1 in 2-D, 9 in 3-D).
//
// The bar is pulled by two 'Dirichlet boxes' (u_x = 0 at x = 0, u_x = 0.02
// at x = 2: strain 0.01, plane stress, E = 100), so each box carries the
// reaction E A strain = 1 (A = 1), with opposite signs. With the default
// 'Coincident vertices = merge' the unmerged file gives the same result as
// the merged one (the difference is printed), for FEM, BCPBG Unl and
// VCBCPBG V5sn Unl in 2-D and FEM in 3-D (without 'Lower corner' and 'Upper
// corner', which 'Mesh = file' does not use: before, 3-D needed them with 3
// coordinates). With 'reject' the run stops, naming the positions.

#include "../tests.h"
#include "problem_fixture.h"

std::string
parameters(const unsigned int dim,
           const std::string &file,
           const std::string &formulation,
           const std::string &extra = "")
{
  std::ostringstream s;
  s << "set Dimension = " << dim << "\n"
    << "subsection Geometry\n"
    << "  set Mesh = file\n"
    << "  set File name = " << SOURCE_DIR << "/" << file << "\n"
    << extra << "end\n"
    << "subsection Discretization\n"
    << "  set Formulation = " << formulation << "\n"
    << "end\n"
    << "subsection Material\n"
    << "  set Model = linear elastic\n  set Young's modulus = 100\n"
    << "  set Poisson's ratio = 0.3\n"
    << (dim == 2 ? "  set Plane = stress\n" : "") << "end\n"
    << "subsection Boundary conditions\n";
  if (dim == 2)
    s << "  set Dirichlet boxes = 0, 0 : 0, 1 : x; 2, 0 : 2, 1 : x\n"
      << "  set Fixed points = 0, 0: y\n"
      << "  subsection Prescribed displacement\n"
      << "    set Function expression = 0.01*x*t; 0\n  end\n";
  else
    s << "  set Dirichlet boxes = 0, 0, 0 : 0, 1, 1 : x; "
         "2, 0, 0 : 2, 1, 1 : x\n"
      << "  set Fixed points = 0, 0, 0: yz; 0, 1, 0: z\n"
      << "  subsection Prescribed displacement\n"
      << "    set Function expression = 0.01*x*t; 0; 0\n  end\n";
  s << "end\n"
    << "subsection Output\n"
    << "  set VTU = false\n  set Directory = output_mesh_merge\n"
    << "  set Points = corner: " << (dim == 2 ? "2, 1" : "2, 1, 1") << "\n"
    << "end\n";
  return s.str();
}



/** The merge line of the banner, without the path. */
std::string
merge_line(const std::string &screen)
{
  std::istringstream lines(screen);
  std::string        line;
  while (std::getline(lines, line))
    if (line.find("mesh file:") != std::string::npos)
      return line;
  return "(no merge line)";
}



template <int dim>
void
compare(const std::string &formulation)
{
  const std::string    name = "two_blocks_" + std::to_string(dim) + "d";
  std::ostringstream   screen_merged, screen_unmerged;
  const pg::RunSummary merged =
    run_problem<dim>(parameters(dim, name + ".msh", formulation),
                     screen_merged);
  const pg::RunSummary unmerged =
    run_problem<dim>(parameters(dim, name + "_unmerged.msh", formulation),
                     screen_unmerged);
  deallog << dim << "-D " << formulation << ":" << std::endl;
  deallog << "  merged file:  " << merge_line(screen_merged.str()) << std::endl;
  deallog << "  unmerged file:" << merge_line(screen_unmerged.str())
          << std::endl;
  deallog << "  particles " << unmerged.n_particles << " (merged file "
          << merged.n_particles << "), DoFs " << unmerged.n_dofs
          << " (merged file " << merged.n_dofs << ")" << std::endl;
  double difference = 0;
  for (unsigned int c = 0; c < dim; ++c)
    difference = std::max(difference,
                          std::abs(unmerged.points[0].second[c] -
                                   merged.points[0].second[c]));
  for (unsigned int b = 0; b < 2; ++b)
    for (unsigned int c = 0; c < dim; ++c)
      difference = std::max(difference,
                            std::abs(unmerged.box_reactions[b][c] -
                                     merged.box_reactions[b][c]));
  print_bound("  |unmerged - merged| (corner u, box reactions)",
              difference,
              1e-12);
  print_rounded("  corner u_x", unmerged.points[0].second[0], 6);
  print_rounded("  corner u_y", unmerged.points[0].second[1], 6);
  for (unsigned int b = 0; b < 2; ++b)
    print_rounded("  reaction x of box " + std::to_string(b + 1),
                  unmerged.box_reactions[b][0],
                  6);
  print_bound("  sum of the box reactions x",
              unmerged.box_reactions[0][0] + unmerged.box_reactions[1][0],
              1e-10);
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  compare<2>("FEM");
  compare<2>("BCPBG Unl");
  compare<2>("VCBCPBG V5sn Unl");
  compare<3>("FEM");

  deallog << "Coincident vertices = reject:" << std::endl;
  std::ostringstream screen;
  try
    {
      run_problem<2>(parameters(2,
                                "two_blocks_2d_unmerged.msh",
                                "FEM",
                                "  set Coincident vertices = reject\n"),
                     screen);
      deallog << "  no error (wrong)" << std::endl;
    }
  catch (ExceptionBase &e)
    {
      std::string       message = exception_message(e);
      const std::string dir     = SOURCE_DIR;
      for (std::size_t p = message.find(dir); p != std::string::npos;
           p             = message.find(dir))
        message.replace(p, dir.size(), "<dir>");
      deallog << message << std::endl;
    }
}
