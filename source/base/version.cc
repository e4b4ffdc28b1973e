#include <pg/version.h>

namespace pg
{
  std::string
  version()
  {
    return PG_VERSION_STRING;
  }
} // namespace pg
