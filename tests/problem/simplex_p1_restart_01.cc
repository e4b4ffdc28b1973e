// Checkpoint and restart of runs with P1 cells on a triangle mesh (issue
// 49): tests/mesh/distorted_triangles.msh, neo-Hooke, the left edge (tag 0)
// clamped, a traction (10 t, 5 t) on the right edge (tag 1), 5 load steps,
// a checkpoint every 2 steps. For FEM everywhere and for P1 cells coupled
// to VCBCPBG V5sn Unl particles in the box x < 0.2, the uninterrupted run
// writes its files to <case>_full; its last checkpoint (step 4) is copied to
// <case>_restart and continued. Compared as in problem/restart_01: every
// entry of statistics.txt except the wall time, the points, the load steps
// and Newton iterations; on one rank bit for bit.

#include "../tests.h"
#include "problem_fixture.h"

#include <filesystem>
#include <map>

namespace
{
  std::string
  parameters(const std::string &formulation,
             const std::string &region,
             const std::string &directory)
  {
    return "subsection Geometry\n  set Mesh = file\n"
           "  set File name = " SOURCE_DIR "/../mesh/distorted_triangles.msh\n"
           "  set Meshfree region = " +
           region +
           "\nend\n"
           "subsection Discretization\n  set Formulation = " +
           formulation +
           "\nend\n"
           "subsection Material\n  set Model = neo-Hooke\n"
           "  set Young's modulus = 100\n  set Poisson's ratio = 0.3\nend\n"
           "subsection Boundary conditions\n  set Dirichlet = 0: xy\n"
           "  set Neumann = 1\n"
           "  subsection Traction\n"
           "    set Function expression = 10*t; 5*t\n  end\nend\n"
           "subsection Loading\n  set Load steps = 5\nend\n"
           "subsection Linear solver\n  set Type = direct\nend\n"
           "subsection Output\n  set Directory = " +
           directory +
           "\n  set VTU = false\n  set Points = corner: 1, 1\n"
           "  set Checkpoint interval = 2\nend\n";
  }

  void
  run_case(const std::string &name,
           const std::string &formulation,
           const std::string &region)
  {
    std::ostringstream   screen;
    const pg::RunSummary a =
      run_problem<2>(parameters(formulation, region, name + "_full"), screen);
    std::filesystem::remove_all(name + "_restart");
    std::filesystem::create_directories(name + "_restart");
    std::filesystem::copy(name + "_full/checkpoint",
                          name + "_restart/checkpoint",
                          std::filesystem::copy_options::recursive);
    const pg::RunSummary b =
      run_problem<2>(parameters(formulation, region, name + "_restart"),
                     screen,
                     true);
    const bool same_statistics =
      !read_statistics(name + "_full/statistics.txt").empty() &&
      read_statistics(name + "_full/statistics.txt") ==
        read_statistics(name + "_restart/statistics.txt");
    bool same_points = a.points.size() == b.points.size();
    for (unsigned int i = 0; same_points && i < a.points.size(); ++i)
      same_points = a.points[i].second == b.points[i].second;
    deallog << name << ": " << a.n_fe_cells << " P1 cells, " << a.n_particles
            << " particles" << std::endl;
    deallog << "  load steps " << b.load_steps << " of " << a.load_steps
            << ", Newton iterations " << b.newton_iterations << " of "
            << a.newton_iterations << std::endl;
    deallog << "  statistics.txt and points bit for bit equal: "
            << (same_statistics && same_points ? "yes" : "NO") << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  run_case("fem", "FEM", "all");
  run_case("coupled", "VCBCPBG V5sn Unl", "box -1.1, -1.1 : 0.2, 1.1");
}
