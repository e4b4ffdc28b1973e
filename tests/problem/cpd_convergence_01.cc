// Convergence of bond-based peridynamics (CPD, C2 = 0) on the unit square
// stretched by 0.1 % between rigid grips (prm/cpd_square_extension.prm;
// Javili et al. 2020, section 4.1; benchmarks C-1 and C-2), on lattices
// coarse enough for a Debug build:
//
// C-1 (fixed horizon delta = 0.201, h = 1/10, 1/20, 1/40, so delta/h =
// 2.01, 4.02, 8.04 as in doc/benchmarks/cpd_convergence.sh): the solution
// is mirror-symmetric about both centre lines, the square contracts
// (u_y < 0 on the upper edge BB', most in the middle), the hole of side 0.4
// makes the contraction along BB' larger, and the change of the u_y
// profiles along AA' (y = 0.7) and BB' from one lattice to the next
// shrinks. Without 'Partial volumes' the all-or-nothing bonds make the
// lattice's Poisson ratio jump with delta/h (0.19, 0.32, 0.34), so the
// first change is large; with them the ratio is 0.31, 0.33, 0.33 and the
// changes are small from the start (doc/cpd.md).
//
// C-2 (delta/h = 4.02 fixed, delta = 0.402, 0.201, 0.1005): the deviation
// of the u_y profiles from Q1 finite elements (h = 1/80, plane stress,
// nu = 1/3, the continuum limit of 2-D bond-based peridynamics) shrinks as
// delta -> 0. With partial volumes the lattice's Poisson ratio at 4.02 is
// 0.330, within 1 % of 1/3.

#include "../tests.h"
#include "problem_fixture.h"

#include <cmath>

/** u_y along the lines at the samples x = k / 10, keyed by "line k". */
using Profile = std::map<std::string, double>;

Profile
run_square(const unsigned int n,
           const double       factor,
           const bool         hole,
           const bool         partial_volumes,
           const bool         fem = false)
{
  // the grips: ceil(factor) lattice rows on either side (none for FEM)
  const unsigned int m = fem ? 0 : static_cast<unsigned int>(std::ceil(factor));
  const double       width = 1. * m / n;
  std::ostringstream prm;
  prm << std::setprecision(17)
      << read_file(SOURCE_DIR "/../../prm/cpd_square_extension.prm")
      << "subsection Geometry\n set Lower corner = " << -width
      << ", 0\n set Upper corner = " << 1 + width
      << ", 1\n set Subdivisions = " << n + 2 * m << ", " << n
      << "\n set Hole = " << (hole ? "box 0.3,0.3 : 0.7,0.7" : "")
      << "\nend\nsubsection Discretization\n set Formulation = "
      << (fem ? "FEM" : "CPD") << "\n set Horizon factor = " << factor
      << "\nend\nsubsection CPD\n set Partial volumes = "
      << (partial_volumes ? "true" : "false")
      << "\nend\nsubsection Material\n set Model = linear elastic\n"
         " set Plane = stress\n set Poisson's ratio = 0.333333333333333\n"
         "end\nsubsection Output\n set Line samples = 21\nend\n";
  std::ostringstream   screen;
  const pg::RunSummary s = run_problem<2>(prm.str(), screen);
  AssertThrow(s.converged, ExcMessage("the run did not converge"));
  Profile profile;
  for (const auto &sample : s.line_samples)
    {
      const double k = sample.arc_length * 20;
      if (std::abs(k - std::round(k)) < 1e-8)
        profile[sample.line + " " + std::to_string(std::lround(k))] =
          sample.displacement[1];
    }
  return profile;
}



/** max |a - b| over max |b| on the samples x = k / 10 (every lattice). */
double
relative_change(const Profile &a, const Profile &b)
{
  double change = 0, size = 0;
  for (const auto &[key, value] : b)
    if (std::stoi(key.substr(3)) % 2 == 0 && a.count(key))
      {
        change = std::max(change, std::abs(a.at(key) - value));
        size   = std::max(size, std::abs(value));
      }
  return change / size;
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  deallog << "C-1: delta = 0.201 fixed" << std::endl;
  std::map<bool, Profile> finest;
  for (const bool hole : {false, true})
    for (const bool pv : {true, false})
      {
        deallog << (hole ? "holed" : "full") << " square"
                << (pv ? ", partial volumes" : "") << std::endl;
        Profile previous;
        double  previous_change = 1e300;
        for (const unsigned int n : {10u, 20u, 40u})
          {
            const Profile u = run_square(n, 0.201 * n, hole, pv);
            // symmetry about x = 1/2 (y = 1/2 mirrors BB' onto y = 0)
            double asymmetry = 0, largest = 0;
            for (const std::string line : {"AA", "BB"})
              for (int k = 0; k <= 20; ++k)
                {
                  const auto here = u.find(line + " " + std::to_string(k));
                  const auto there =
                    u.find(line + " " + std::to_string(20 - k));
                  if (here == u.end() || there == u.end())
                    continue;
                  asymmetry =
                    std::max(asymmetry, std::abs(here->second - there->second));
                  largest = std::max(largest, std::abs(here->second));
                }
            deallog << "  h = 1/" << n
                    << ": min u_y(BB') / 1e-4 = " << std::fixed
                    << std::setprecision(3) << u.at("BB 10") / 1e-4
                    << std::defaultfloat;
            const bool contracts = u.at("BB 10") < u.at("BB 4") &&
                                   u.at("BB 4") < u.at("BB 1") &&
                                   u.at("BB 1") < 0;
            deallog << (contracts ? ", contracts most in the middle" :
                                    ", NO monotone contraction");
            deallog << (asymmetry < 1e-8 * largest ? ", mirror-symmetric" :
                                                     ", NOT symmetric");
            if (!previous.empty())
              {
                const double change = relative_change(u, previous);
                deallog << ", relative change " << std::fixed
                        << std::setprecision(2) << change << std::defaultfloat
                        << (change < previous_change ? ", shrinks" :
                                                       ", DOES NOT shrink");
                previous_change = change;
              }
            deallog << std::endl;
            previous = u;
          }
        if (pv)
          finest[hole] = previous;
      }
  deallog << "the hole raises the contraction along BB': "
          << (finest[true].at("BB 10") < finest[false].at("BB 10") ? "yes" :
                                                                     "NO")
          << std::endl;

  deallog << "C-2: delta/h = 4.02, against Q1 FEM (h = 1/80, nu = 1/3)"
          << std::endl;
  for (const bool hole : {false, true})
    {
      const Profile fem                = run_square(80, 1, hole, false, true);
      double        previous_deviation = 1e300;
      for (const unsigned int n : {10u, 20u, 40u})
        {
          const double deviation =
            relative_change(run_square(n, 4.02, hole, true), fem);
          deallog << "  " << (hole ? "holed" : "full")
                  << ", partial volumes, delta = " << 4.02 / n
                  << ": relative deviation " << std::fixed
                  << std::setprecision(2) << deviation << std::defaultfloat
                  << (deviation < previous_deviation ? ", shrinks" :
                                                       ", DOES NOT shrink")
                  << std::endl;
          previous_deviation = deviation;
        }
    }
}
