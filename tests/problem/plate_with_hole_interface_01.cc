// The FE/PG interface where it meets a symmetry line with VC option sn
// (issue 11, item 3): the coupled plate with a hole of
// prm/plate_with_hole_coupled.prm with particles out to 3R, VCBCPPG V3sn
// Unl, at refinements 3 and 4 on the regular mesh and at 4 on the
// distorted one (Distortion 0.3).
//
// With the MLS-based V3 correction function on the one-sided families of
// the interface masters, the VC system is nearly singular where the
// interface meets the symmetry line y = 0 (and x = 0): max |alpha^k| h was
// 76 and 89 at refinements 3 and 4 (2 elsewhere), the energy error grew
// from 0.10 to 0.24 and the largest sigma_xx jump between the particle
// value and the adjacent Q1 cells was 0.31 and 1.1 times 3T. PPG masters on
// the interface now use the constant V1 (doc/ambiguities.md). Checked:
// 1. max |alpha^k| h below 5,
// 2. the energy error decreases at a rate of at least 0.9 in h between
//    refinements 3 and 4,
// 3. the interface jump is below 3 % of 3T at refinement 4 (regular and
//    distorted).

#include "../tests.h"
#include "problem_fixture.h"

#include <cmath>

std::string
plate(const unsigned int refinement, const double distortion)
{
  return read_file(SOURCE_DIR "/../../prm/plate_with_hole_coupled.prm") +
         "subsection Discretization\n  set Formulation = VCBCPPG V3sn Unl\n"
         "end\nsubsection Geometry\n  set Global refinement = " +
         std::to_string(refinement) +
         "\n  set Distortion = " + std::to_string(distortion) +
         "\n  set Meshfree region = ball 0, 0 : 3\nend\n"
         "subsection Linear solver\n  set Type = direct\nend\n"
         "subsection Output\n  set VTU = false\nend\n";
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  std::ostringstream          screen;
  const double                three_T = 30;
  std::vector<pg::RunSummary> runs;
  for (const auto &[refinement, distortion] :
       std::vector<std::pair<unsigned int, double>>{{3, 0.}, {4, 0.}, {4, 0.3}})
    {
      runs.push_back(run_problem<2>(plate(refinement, distortion), screen));
      const pg::RunSummary &s = runs.back();
      std::ostringstream    line;
      line << std::setprecision(2) << "refinement " << refinement
           << ", distortion " << distortion << ": " << s.n_dofs
           << " DoFs, max |alpha| h " << s.max_correction_factor << ", energy "
           << s.energy_relative << ", interface jump / 3T "
           << s.max_interface_stress_jump / three_T;
      deallog << line.str() << std::endl;
    }
  bool bounded = true;
  for (const auto &s : runs)
    bounded = bounded && s.max_correction_factor < 5;
  deallog << "max |alpha| h below 5: " << (bounded ? "yes" : "NO") << std::endl;
  const double rate =
    -2 * std::log(runs[1].energy_relative / runs[0].energy_relative) /
    std::log(double(runs[1].n_dofs) / runs[0].n_dofs);
  std::ostringstream r;
  r << std::fixed << std::setprecision(1) << rate;
  deallog << "energy rate 3 -> 4: " << r.str()
          << ", at least 0.9: " << (rate >= 0.9 ? "yes" : "NO") << std::endl;
  deallog << "interface jump below 3 % of 3T at refinement 4: "
          << (runs[1].max_interface_stress_jump / three_T < 0.03 &&
                  runs[2].max_interface_stress_jump / three_T < 0.03 ?
                "yes" :
                "NO")
          << std::endl;
}
