// libFuzzer's entry point for pg::Fuzz::formulation_code() (fuzz_targets.h);
// built with -DPG_FUZZ=ON and clang (see README.md, "Fuzzing").
#include "fuzz_targets.h"

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  pg::Fuzz::formulation_code(data, size);
  return 0;
}
