#ifndef pg_tests_fuzz_fuzz_targets_h
#define pg_tests_fuzz_fuzz_targets_h

#include <cstddef>
#include <cstdint>

// The fuzzed entry points of pg's input parsers. Each takes arbitrary bytes
// and must return normally: a bad input may only end in a deal.II exception
// (pg's ExcBadParameter and ExcMessage, ParameterHandler's pattern errors),
// which pg_solve reports as a message. Anything else (another exception, a
// crash, an address or undefined-behaviour sanitizer report) is a finding.
// libFuzzer calls them from fuzz_<name>.cc; fuzz_replay runs a corpus
// through them in every build (ctest fuzz/).
namespace pg
{
  namespace Fuzz
  {
    /** parse_formulation_code() of the bytes as a formulation code. */
    void
    formulation_code(const std::uint8_t *data, std::size_t size);

    /**
     * One list-valued entry: byte 0 picks it ('Boundary conditions/
     * Dirichlet', 'Fixed points', 'Dirichlet boxes', 'Symmetry', 'Neumann',
     * 'Neumann stress', 'Output/Points', 'Lines', 'Geometry/Meshfree
     * region', 'Hole'), byte 1 the dimension (2 or 3); the rest is the
     * value, parsed as in pg_solve.
     */
    void
    parameter_lists(const std::uint8_t *data, std::size_t size);
  } // namespace Fuzz
} // namespace pg

#endif
