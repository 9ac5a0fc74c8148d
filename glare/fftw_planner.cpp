#include "glare/fftw_planner.hpp"

#include <fftw3.h>

#include <cstdio>
#include <cstdlib>

#include "glare/fftw_wisdom_text.hpp"

namespace eyestream::glare {

namespace {

const char* wisdom_out() {
  static const char* path = std::getenv("EYESTREAM_FFTW_WISDOM_OUT");
  return path && *path ? path : nullptr;
}

// Adds what the planner learnt to the maintainer's file when the program ends.
void export_wisdom() {
  std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  if (!fftw_export_wisdom_to_filename(wisdom_out()))
    std::fprintf(stderr, "eyestream: error: cannot write FFTW wisdom to %s\n", wisdom_out());
}

bool import_wisdom() {
  if (wisdom_out()) {  // making wisdom: start from the file's (if any), not the shipped
    fftw_import_wisdom_from_filename(wisdom_out());
    std::atexit(export_wisdom);
    return true;
  }
  return fftw_import_wisdom_from_string(kShippedFftwWisdom) != 0;
}

bool took_shipped = false;

}  // namespace

std::mutex& fftw_planner_mutex() {
  static std::mutex m;
  static std::once_flag imported;
  std::call_once(imported, [] { took_shipped = import_wisdom(); });
  return m;
}

// Plans leave out FFTW's buffered solvers: they allocate their buffers at
// every execution (measured plans with them: 90 blocks of 180 KB a frame
// in `balanced`, SteadyStateAllocation), and the frame loop takes no
// image-sized block. Wisdom serves a request of equal or less rigor whose
// buffering flag it satisfies: measured entries made without buffering
// serve these estimated requests, not plain FFTW_ESTIMATE ones.
unsigned fftw_plan_rigor() { return (wisdom_out() ? FFTW_MEASURE : FFTW_ESTIMATE) | FFTW_NO_BUFFERING; }

bool fftw_took_shipped_wisdom() {
  fftw_planner_mutex();  // imports it, once
  return took_shipped && !wisdom_out();
}

}  // namespace eyestream::glare
