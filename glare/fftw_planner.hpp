// FFTW's planner is not thread-safe (executing distinct plans is): every
// plan is made and destroyed under this one lock.
#pragma once

#include <mutex>

namespace eyestream::glare {

std::mutex& fftw_planner_mutex();

}  // namespace eyestream::glare
