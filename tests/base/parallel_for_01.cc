// parallel_for_each_index() calls f once for every index, on more than one
// thread, and rethrows the exception of the smallest failing index (the
// one a serial loop would report), whatever the order the chunks ran in.

#include <pg/base/parallel_for.h>

#include "../tests.h"

#include <atomic>
#include <stdexcept>
#include <vector>

int
main()
{
  initlog();
  MultithreadInfo::set_thread_limit(2);

  // every index once
  std::vector<unsigned int> calls(10000, 0);
  pg::parallel_for_each_index(calls.size(),
                              [&](const unsigned int i) { ++calls[i]; });
  unsigned int wrong = 0;
  for (const unsigned int c : calls)
    wrong += (c != 1);
  deallog << "indices not called exactly once: " << wrong << std::endl;

  // no call for an empty range
  std::atomic<unsigned int> n_calls = 0;
  pg::parallel_for_each_index(0, [&](const unsigned int) { ++n_calls; });
  deallog << "calls for n = 0: " << n_calls << std::endl;

  // failures at 9001, 4000 and 3999 (grain size 1: every index may be a
  // chunk of its own), 50 times: always 3999
  unsigned int reported_first = 0;
  for (unsigned int run = 0; run < 50; ++run)
    try
      {
        pg::parallel_for_each_index(
          10000,
          [](const unsigned int i) {
            if (i == 9001 || i == 4000 || i == 3999)
              throw std::runtime_error(std::to_string(i));
          },
          1);
      }
    catch (const std::runtime_error &e)
      {
        reported_first += (std::string(e.what()) == "3999");
      }
  deallog << "runs that reported index 3999: " << reported_first << " of 50"
          << std::endl;
}
