// Peak resident memory of this process, for `eyestream bench`: Linux's
// high-water mark (VmHWM in /proc/self/status), which writing 5 to
// /proc/self/clear_refs resets to the current resident size.
#pragma once

namespace eyestream::pipeline {

// Resident and peak resident memory in MiB; -1 where /proc is unavailable.
double resident_mib();
double peak_resident_mib();
// Starts a new peak at the current resident size; false if the kernel refused.
bool reset_peak_resident();

}  // namespace eyestream::pipeline
