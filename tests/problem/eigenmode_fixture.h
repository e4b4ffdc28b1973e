#ifndef pg_tests_eigenmode_fixture_h
#define pg_tests_eigenmode_fixture_h

// The free block of prm/eigenmodes_block.prm (B-3) under several
// formulations: a variant's parameters from its name, and the counts of
// its spectrum that eigenmodes_01 and eigenmodes_02 print.

#include <pg/problem.h>

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <string>

/**
 * The parameter text for @p variant, "<code>", "<code> @ <nu>" (the block
 * at another Poisson's ratio) or "<code> hg <alpha>" (with 'Hourglass
 * coefficient = alpha').
 */
inline std::string
block_variant(const std::string &variant)
{
  const auto at = variant.find(" @ ");
  const auto hg = variant.find(" hg ");
  return "subsection Discretization\n  set Formulation = " +
         variant.substr(0, std::min(at, hg)) + "\n" +
         (hg == std::string::npos ?
            "" :
            "  set Hourglass coefficient = " + variant.substr(hg + 4) + "\n") +
         "end\n" +
         (at == std::string::npos ?
            "" :
            "subsection Material\n  set Poisson's ratio = " +
              variant.substr(at + 3) + "\nend\n");
}

/**
 * "zero: Z, non-rigid below 0.893: L, negative: N, first non-rigid: F"
 * for the eigenvalues of @p s: Z rigid (zero) modes, L non-rigid ones
 * below 0.893 (spurious low modes of the block; Q1's first bending mode is
 * 0.893), N negative ones (below -1e-8 of the largest), F the first
 * non-rigid eigenvalue to 3 digits.
 */
inline std::string
spectrum_counts(const pg::RunSummary &s)
{
  const auto  &ev  = s.eigenvalues;
  const auto   z   = s.n_zero_eigenvalues;
  unsigned int low = 0, negative = 0;
  for (unsigned int i = z; i < ev.size(); ++i)
    {
      low += (ev[i] < 0.893);
      negative += (ev[i] < -1e-8 * s.max_eigenvalue);
    }
  std::ostringstream text;
  text << "zero: " << z << ", non-rigid below 0.893: " << low
       << ", negative: " << negative
       << ", first non-rigid: " << std::setprecision(3) << ev[z];
  return text.str();
}

#endif
