#include "core/demand.h"

#include <cstdio>
#include <cstdlib>

namespace mg::detail {

void demand_failed(const char* condition, const char* file, int line) noexcept {
  std::fprintf(stderr, "mergeguard: invariant failed: %s (%s:%d)\n", condition, file, line);
  std::fflush(stderr);
  std::abort();
}

}  // namespace mg::detail
