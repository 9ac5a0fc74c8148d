#include "pipeline/bench/peak_memory.hpp"

#include <fstream>
#include <string>

namespace eyestream::pipeline {

namespace {

// The value of `key` ("VmRSS:") in /proc/self/status, in MiB.
double status_mib(const std::string& key) {
  std::ifstream in("/proc/self/status");
  std::string word;
  while (in >> word)
    if (word == key) {
      double kib = 0;
      in >> kib;
      return kib / 1024.0;
    }
  return -1.0;
}

}  // namespace

double resident_mib() { return status_mib("VmRSS:"); }
double peak_resident_mib() { return status_mib("VmHWM:"); }

bool reset_peak_resident() {
  std::ofstream out("/proc/self/clear_refs");
  out << "5";
  out.flush();
  return bool(out);
}

}  // namespace eyestream::pipeline
