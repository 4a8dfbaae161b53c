#include "cablefit/core/errors.h"

#include <cstdio>
#include <cstdlib>

namespace cablefit {

void AbortOnBrokenInvariant(const char* condition, const char* file, int line,
                            const std::string& message) {
  std::fprintf(stderr, "cablefit: internal error: %s (%s) at %s:%d\n", message.c_str(), condition,
               file, line);
  std::abort();
}

}  // namespace cablefit
