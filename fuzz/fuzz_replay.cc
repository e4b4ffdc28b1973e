// Runs every file of the given directories through one fuzz target
// (fuzz_targets.h) without libFuzzer: the corpus, and every input that once
// crashed (kept in crashes/), stay tested in ordinary builds.
//
//   fuzz_replay formulation_code|parameter_lists DIRECTORY...
#include "fuzz_targets.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

int
main(int argc, char **argv)
{
  if (argc < 3)
    {
      std::cerr << "usage: fuzz_replay formulation_code|parameter_lists "
                   "DIRECTORY...\n";
      return 1;
    }
  const std::string target = argv[1];
  if (target != "formulation_code" && target != "parameter_lists")
    {
      std::cerr << "unknown fuzz target <" << target << ">\n";
      return 1;
    }
  unsigned int n_inputs = 0;
  for (int d = 2; d < argc; ++d)
    {
      if (!std::filesystem::is_directory(argv[d]))
        continue;
      std::vector<std::filesystem::path> files;
      for (const auto &file : std::filesystem::directory_iterator(argv[d]))
        if (file.is_regular_file())
          files.push_back(file.path());
      std::sort(files.begin(), files.end());
      for (const auto &file : files)
        {
          std::ifstream                   in(file, std::ios::binary);
          const std::vector<std::uint8_t> bytes(
            (std::istreambuf_iterator<char>(in)),
            std::istreambuf_iterator<char>());
          if (target == "formulation_code")
            pg::Fuzz::formulation_code(bytes.data(), bytes.size());
          else
            pg::Fuzz::parameter_lists(bytes.data(), bytes.size());
          ++n_inputs;
        }
    }
  std::cout << target << ": " << n_inputs << " inputs, none failed"
            << std::endl;
  return n_inputs > 0 ? 0 : 1;
}
