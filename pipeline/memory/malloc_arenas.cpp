#include "pipeline/memory/malloc_arenas.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace eyestream::pipeline {

void limit_malloc_arenas() {
#if defined(__GLIBC__)
  mallopt(M_ARENA_MAX, 2);
#endif
}

}  // namespace eyestream::pipeline
