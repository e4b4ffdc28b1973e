// Checkpoint and restart ('Output/Checkpoint interval', pg_solve --restart,
// SIGINT/SIGTERM): a run continued from a checkpoint gives the results of
// the run without interruption. For each case the uninterrupted run writes
// its files to <case>_full; a second run is stopped or its checkpoint is
// copied to <case>_restart and continued from there. Compared: every entry
// of statistics.txt except the wall time, the points, the load steps and
// Newton iterations of the summary. On one rank they agree bit for bit; on
// two ranks within 1e-12 of each column's largest value (the order of the
// sums over the ranks may change round-off).
//
// Cases: static (Cook's membrane, VCBCPBG V5sn Unl, neo-Hooke, 5 load
// steps) from the checkpoint of step 4 (interval 2), and stopped by a
// SIGTERM (recorded on rank 0 only) after step 1; leapfrog (VCBCPBG Unl on
// the Ganzenmueller patch, 66 steps) from the checkpoint of step 50
// (interval 25); Newmark (VCBCPPG V3sn Unl, 10 steps) stopped by a SIGINT
// after step 1; leapfrog with a block bouncing on a rigid wall (the active
// set is in the checkpoint) from step 20. Then the errors of a restart without
// a checkpoint and of one with other parameters.

#include <pg/base/exceptions.h>
#include <pg/base/interruption.h>

#include "../tests.h"
#include "problem_fixture.h"

#include <csignal>
#include <filesystem>
#include <map>

namespace
{
  /**
   * The largest difference of @p a and @p b relative to the largest
   * |value| of its column in @p a (absolute for a column of zeros);
   * 1 if the tables differ in shape.
   */
  double
  difference(const std::map<std::string, std::vector<double>> &a,
             const std::map<std::string, std::vector<double>> &b)
  {
    if (a.size() != b.size() || a.empty())
      return 1;
    double d = 0;
    for (const auto &[name, x] : a)
      {
        const auto y = b.find(name);
        if (y == b.end() || y->second.size() != x.size())
          return 1;
        double scale = 0;
        for (const double v : x)
          scale = std::max(scale, std::abs(v));
        for (unsigned int i = 0; i < x.size(); ++i)
          d =
            std::max(d,
                     std::abs(x[i] - y->second[i]) / (scale > 0 ? scale : 1.));
      }
    return d;
  }

  /** Output settings of a case: its directory and checkpoint interval. */
  std::string
  output(const std::string &directory, const unsigned int interval)
  {
    return "subsection Output\n  set Directory = " + directory +
           "\n  set VTU = false\n  set Checkpoint interval = " +
           std::to_string(interval) + "\nend\n";
  }

  /** Copy the files of @p from to @p to (rank 0), without the results. */
  void
  copy_checkpoint(const std::string &from, const std::string &to)
  {
    namespace fs = std::filesystem;
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        fs::remove_all(to);
        fs::create_directories(to);
        fs::copy(from + "/checkpoint",
                 to + "/checkpoint",
                 fs::copy_options::recursive);
      }
    MPI_Barrier(MPI_COMM_WORLD);
  }

  /** Compare the restarted run @p b with the uninterrupted @p a. */
  void
  compare(const std::string    &name,
          const pg::RunSummary &a,
          const pg::RunSummary &b)
  {
    const double d =
      difference(read_statistics(name + "_full/statistics.txt"),
                 read_statistics(name + "_restart/statistics.txt"));
    double p = 0;
    for (unsigned int i = 0; i < a.points.size(); ++i)
      for (unsigned int c = 0; c < a.points[i].second.size(); ++c)
        p =
          std::max(p, std::abs(a.points[i].second[c] - b.points[i].second[c]));
    deallog << "  load/time steps " << b.load_steps << " of " << a.load_steps
            << ", Newton iterations " << b.newton_iterations << " of "
            << a.newton_iterations << std::endl;
    if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1)
      deallog << "  statistics.txt and points bit for bit equal: "
              << (d == 0 && p == 0 ? "yes" : "NO") << std::endl;
    else
      {
        print_bound("  statistics.txt, relative difference", d, 1e-12);
        print_bound("  points, difference", p, 1e-12);
      }
  }

  /** "status" of <directory>/summary.json. */
  std::string
  status(const std::string &directory)
  {
    const std::string text = read_file(directory + "/summary.json");
    const auto        at   = text.find("\"status\": \"");
    if (at == std::string::npos)
      return "(none)";
    const auto start = at + 11;
    return text.substr(start, text.find('"', start) - start);
  }

  /**
   * Run @p parameters with the signal @p signal recorded (on rank 0
   * only): the run must stop after its first step with RunInterrupted.
   */
  void
  interrupt(const std::string &parameters,
            const int          signal,
            const std::string &directory,
            std::ostream      &screen)
  {
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      pg::Interruption::request(signal);
    try
      {
        run_problem<2>(parameters, screen);
        deallog << "  not interrupted: NO" << std::endl;
      }
    catch (const pg::RunInterrupted &e)
      {
        deallog << "  interrupted: exit code " << 128 + e.signal() << ", "
                << pg::one_line(e.what()) << std::endl;
      }
    pg::Interruption::clear();
    deallog << "  summary.json status: " << status(directory) << std::endl;
  }

  /**
   * The run of @p parameters without interruption into <name>_full, with
   * a checkpoint every @p interval steps, then the restart from its last
   * checkpoint (a copy in <name>_restart), compared. Returns the summary of
   * the uninterrupted run.
   */
  pg::RunSummary
  from_checkpoint(const std::string &name,
                  const std::string &parameters,
                  const unsigned int interval,
                  std::ostream      &screen)
  {
    const pg::RunSummary full =
      run_problem<2>(parameters + output(name + "_full", interval), screen);
    copy_checkpoint(name + "_full", name + "_restart");
    compare(name,
            full,
            run_problem<2>(parameters + output(name + "_restart", interval),
                           screen,
                           true));
    return full;
  }

  /** What a run that throws says. */
  void
  expect_error(const std::string &parameters, std::ostream &screen)
  {
    try
      {
        run_problem<2>(parameters, screen, true);
        deallog << "  no error: NO" << std::endl;
      }
    catch (const std::exception &e)
      {
        deallog << "  " << pg::one_line(pg::user_message(e)) << std::endl;
      }
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // one log: rank 0's
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    initlog();
  else
    deallog.depth_console(0);
  std::ostringstream screen;
  const std::string  cook =
    read_file(SOURCE_DIR "/../pg_solve/cook_membrane_nu_04999_pg.prm");
  const std::string patch =
    "include " SOURCE_DIR "/../../prm/ganzenmueller_patch.prm\n"
    "subsection Geometry\n  set Subdivisions = 8, 8\nend\n";
  const std::string leapfrog = patch + "subsection Time\n  set End time = 2\n"
                                       "  set Output interval = 0.5\nend\n";
  const std::string newmark =
    patch + "subsection Discretization\n  set Formulation = VCBCPPG V3sn Unl\n"
            "  set Shape functions = MTE1\nend\n"
            "subsection Linear solver\n  set Type = direct\nend\n"
            "subsection Time\n  set Integrator = newmark\n"
            "  set Time step = 0.1\n  set End time = 1\n"
            "  set Output interval = 0.5\nend\n";

  // a block that falls onto a rigid wall and bounces (100 steps): the
  // checkpoint of step 90 is written while its bottom nodes are held
  const std::string wall =
    "set Dimension = 2\n"
    "subsection Geometry\n  set Upper corner = 1, 1\n"
    "  set Subdivisions = 4, 4\nend\n"
    "subsection Material\n  set Model = linear elastic\n"
    "  set Young's modulus = 1\n  set Poisson's ratio = 0.3\n"
    "  set Density = 1\nend\n"
    "subsection Boundary conditions\n  subsection Rigid wall\n"
    "    set Point = 0, -0.01\n    set Normal = 0, 1\n  end\nend\n"
    "subsection Time\n  set Integrator = leapfrog\n  set End time = 2\n"
    "  set Time step = 0.02\n"
    "  set Output interval = 0.1\n  subsection Initial velocity\n"
    "    set Function expression = 0; -0.1\n  end\nend\n";

  deallog << "static, from the checkpoint of step 4" << std::endl;
  const pg::RunSummary cook_full = from_checkpoint("static", cook, 2, screen);

  deallog << "static, SIGTERM in load step 1" << std::endl;
  interrupt(cook + output("static_restart", 0),
            SIGTERM,
            "static_restart",
            screen);
  compare("static",
          cook_full,
          run_problem<2>(cook + output("static_restart", 0), screen, true));
  deallog << "  summary.json status: " << status("static_restart") << std::endl;

  deallog << "leapfrog, from the checkpoint of step 50" << std::endl;
  from_checkpoint("leapfrog", leapfrog, 25, screen);

  deallog << "newmark, SIGINT in time step 1" << std::endl;
  const pg::RunSummary newmark_full =
    run_problem<2>(newmark + output("newmark_full", 0), screen);
  interrupt(newmark + output("newmark_restart", 0),
            SIGINT,
            "newmark_restart",
            screen);
  compare("newmark",
          newmark_full,
          run_problem<2>(newmark + output("newmark_restart", 0), screen, true));

  deallog << "leapfrog with a rigid wall, from the checkpoint of step 90"
          << std::endl;
  from_checkpoint("wall", wall, 30, screen);

  deallog << "restart without a checkpoint" << std::endl;
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::filesystem::remove_all("no_checkpoint");
  expect_error(cook + output("no_checkpoint", 0), screen);
  deallog << "restart with other load steps" << std::endl;
  expect_error(cook + output("static_restart", 0) +
                 "subsection Loading\n  set Load steps = 6\nend\n",
               screen);
}
