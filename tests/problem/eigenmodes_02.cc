// Eigenvalues of the free 20 x 10 block of prm/eigenmodes_block.prm
// (benchmark B-3; linear elasticity, E = 100, regular 20 x 10 particles,
// horizon 2.51 h) for the mixed formulations whose pressure (and
// dilatation) are global unknowns (issue 13, deliverable 6): U2P1C and
// Unl+P1C (nodal p and Theta of the particles) at nu = 0.4 and 0.4999, and
// IUnlP0 (the pressure of every family, nu = 0.5) with PBG and PPG.
//
// Their tangent is a saddle-point matrix; the analysis reports the
// eigenvalues of the stiffness the displacements see: the Schur complement
// with p and Theta eliminated (U2P1C, Unl+P1C), or the displacement
// stiffness on the displacements the incompressibility constraint admits
// (IUnlP0, whose K_pp = 0). Checked: exactly the 3 rigid modes, no negative
// eigenvalue, how many non-rigid ones lie below Q1's bending eigenvalue
// 0.893 (the source: no spurious modes), the first non-rigid one (how much
// each locks; Q1P0: 0.95 at nu = 0.4999, the displacement Unl: 2.46), and
// how many family pressures of IUnlP0 constrain nothing (spurious pressure
// modes).
//
// An independent check of the constrained reduction: IUnlP0 at nu = 0.5 is
// the limit of UnlP0 (p and Theta condensed per family, no global pressure)
// as K -> infinity. The low eigenvalues of VCBCPBG V5sn UnlP0 at
// nu = 0.4999999 (the same E, so mu agrees to 1e-7) must agree with
// IUnlP0's at nu = 0.5 (within 1e-3); the same for PPG.

#include "../tests.h"
#include "eigenmode_fixture.h"
#include "problem_fixture.h"

#include <map>


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const std::string base =
    read_file(SOURCE_DIR "/../../prm/eigenmodes_block.prm") +
    "subsection Linear solver\n  set Type = direct\nend\n";

  std::map<std::string, std::vector<double>> spectra;
  for (const std::string code : {"VCPBG U2P1C",
                                 "VCPBG U2P1C @ 0.4999",
                                 "VCPBG Unl+P1C",
                                 "VCPBG Unl+P1C @ 0.4999",
                                 "VCPBG IUnlP0 @ 0.5",
                                 "VCPPG IUnlP0 @ 0.5",
                                 "VCBCPBG V5sn UnlP0 @ 0.4999999",
                                 "VCBCPPG V3sn UnlP0 @ 0.4999999"})
    {
      std::ostringstream   screen;
      const pg::RunSummary s =
        run_problem<2>(base + block_variant(code), screen);
      const auto z  = s.n_zero_eigenvalues;
      spectra[code] = std::vector<double>(s.eigenvalues.begin() + z,
                                          s.eigenvalues.begin() + z + 10);
      deallog << code << ": " << spectrum_counts(s) << std::endl;
      // IUnlP0: the screen names the pressure modes without a constraint
      const std::string text  = screen.str();
      const auto        modes = text.find(" pressure modes without");
      if (modes != std::string::npos)
        deallog << "  "
                << text.substr(text.rfind(", ", modes) + 2,
                               modes - text.rfind(", ", modes) - 2)
                << " pressure modes without a constraint" << std::endl;
    }

  // IUnlP0 = the incompressible limit of UnlP0: the 10 lowest non-rigid
  // eigenvalues agree (measured: within 2.0e-4 (PBG) and 2.4e-4 (PPG)
  // relative, the largest differences in the 7th eigenvalue, where the
  // penalty K/mu = 5e6 of UnlP0 is felt; a wrong reduction would differ
  // by O(1))
  for (const auto &pair :
       {std::make_pair("VCPBG IUnlP0 @ 0.5", "VCBCPBG V5sn UnlP0 @ 0.4999999"),
        std::make_pair("VCPPG IUnlP0 @ 0.5", "VCBCPPG V3sn UnlP0 @ 0.4999999")})
    {
      double difference = 0;
      for (unsigned int i = 0; i < 10; ++i)
        difference =
          std::max(difference,
                   std::abs(spectra[pair.first][i] - spectra[pair.second][i]) /
                     spectra[pair.second][i]);
      deallog << pair.first << " against " << pair.second
              << ": 10 lowest non-rigid eigenvalues agree within 1e-3: "
              << (difference < 1e-3 ? "yes" : "no") << std::endl;
    }
}
