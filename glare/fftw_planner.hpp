// FFTW's planner: its lock, and the plans it is given.
//
// The planner is not thread-safe (executing distinct plans is): every plan
// is made and destroyed under fftw_planner_mutex().
//
// Plans are chosen without timing anything (FFTW_ESTIMATE), so that a run's
// bytes never depend on the machine's load, except where wisdom shipped
// with the program (glare/fftw_wisdom.txt) holds a plan for that very
// problem: FFTW then uses the recorded plan, chosen once by measuring
// (FFTW_MEASURE) for the transforms the presets make at 720p, 1080p and
// 4K. The wisdom is fixed text, so the plans it gives are the same on
// every run. FFTW refuses the whole text where it does not fit: another
// build of FFTW, or a CPU without AVX (its solvers differ there); then
// every plan is estimated. The lock's first use imports it.
//
// scripts/fftw-wisdom.sh remakes the file: with EYESTREAM_FFTW_WISDOM_OUT
// set to a path, every plan is made by measuring instead (a maintainer's
// switch: such runs' bytes depend on the timings) and the wisdom gathered
// is added to that file when the program ends.
#pragma once

#include <fftw3.h>

#include <mutex>
#include <stdexcept>

namespace eyestream::glare {

std::mutex& fftw_planner_mutex();

// The planner flags for a frame loop's transform: FFTW_ESTIMATE (wisdom
// applies where it holds the problem), or FFTW_MEASURE while wisdom is
// being made; with FFTW_NO_BUFFERING either way (buffered plans allocate
// at every execution). A problem FFTW cannot plan so gets a null plan:
// make_fftw_plan then plans it by FFTW_ESTIMATE alone.
unsigned fftw_plan_rigor();

// A plan made by make(flags) (a call of one of FFTW's planners) with
// fftw_plan_rigor(), or, where FFTW cannot plan the problem without
// buffering (some small sizes with odd factors: the plan is null), with
// FFTW_ESTIMATE alone (buffered, estimated). Never null. Under
// fftw_planner_mutex(), as every plan.
template <typename Make>
auto make_fftw_plan(const Make& make) {
  auto plan = make(fftw_plan_rigor());
  if (!plan) plan = make(unsigned(FFTW_ESTIMATE));
  if (!plan) throw std::runtime_error("FFTW could not plan a transform");
  return plan;
}

// Whether FFTW took the shipped wisdom (it refuses text made by another
// FFTW build), for tests; false while wisdom is being made.
bool fftw_took_shipped_wisdom();

}  // namespace eyestream::glare
