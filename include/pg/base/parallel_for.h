#ifndef pg_base_parallel_for_h
#define pg_base_parallel_for_h

#include <deal.II/base/parallel.h>

#include <exception>
#include <limits>
#include <mutex>

namespace pg
{
  /**
   * Call @p f(i) for i = 0 .. n - 1 on deal.II's threads (TBB), in chunks of
   * @p grain_size indices. The calls must be independent (distinct i write
   * distinct data). If calls throw, the exception of the smallest failing i
   * is rethrown once all chunks have ended, so the message is the one a
   * serial loop would give (e.g. the first singular family), whatever the
   * number of threads.
   */
  template <typename Function>
  void
  parallel_for_each_index(const unsigned int n,
                          const Function    &f,
                          const unsigned int grain_size = 16)
  {
    std::mutex         mutex;
    unsigned int       first_failure = std::numeric_limits<unsigned>::max();
    std::exception_ptr failure;
    dealii::parallel::apply_to_subranges(
      0u,
      n,
      [&](const unsigned int begin, const unsigned int end) {
        for (unsigned int i = begin; i < end; ++i)
          try
            {
              f(i);
            }
          catch (...)
            {
              std::lock_guard<std::mutex> lock(mutex);
              if (i < first_failure)
                {
                  first_failure = i;
                  failure       = std::current_exception();
                }
              return; // the rest of this chunk can only fail later
            }
      },
      grain_size);
    if (failure)
      std::rethrow_exception(failure);
  }
} // namespace pg

#endif
