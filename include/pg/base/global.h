#ifndef pg_base_global_h
#define pg_base_global_h

#include <deal.II/base/config.h>

namespace dealii
{}

/**
 * Everything in the pg library lives in this namespace. deal.II is imported
 * here, once, as ASPECT does.
 */
namespace pg
{
  using namespace dealii;
} // namespace pg

#endif
