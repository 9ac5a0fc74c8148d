#include "pipeline/memory/malloc_arenas.hpp"

#include <cstdlib>  // on glibc, defines __GLIBC__ (through <features.h>)
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace eyestream::pipeline {

void limit_malloc_arenas() {
#if defined(__GLIBC__)
  if (std::getenv("MALLOC_ARENA_MAX") == nullptr) mallopt(M_ARENA_MAX, 2);  // a user's own setting stands
#endif
}

}  // namespace eyestream::pipeline
