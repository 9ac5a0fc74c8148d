// `eyestream compare A B`: frame-by-frame differences between two outputs
// for regression tests, with idiff's exit convention (0 pass, 1 warn,
// 2 fail).
#pragma once

#include <string>

namespace eyestream::pipeline {

struct CompareOptions {
  std::string a, b;
  std::string metric = "de99";  // what --warn/--fail judge: de99, demax, max, mean or psnr
  double warn = 0.5, fail = 1.0;
  double de_threshold = 2.0;  // pixels whose CIEDE2000 exceeds this are counted
  std::string diff_out;       // PNG pattern for difference images (CIEDE2000 heat maps)
  double diff_scale = 5.0;    // CIEDE2000 shown at full scale
  std::string json;           // report file
  bool verbose = false;       // a line per frame
};

struct CompareResult {
  int exit_code = 0;  // 0 pass, 1 warn, 2 fail (including mismatched frame counts or sizes)
  std::string text;   // the summary (and per-frame lines when verbose)
};

// Pairs the frames of A and B in order. Per frame: max and mean absolute
// difference of the values (display code values 0..1 for PNG and video,
// display-linear values for EXR), PSNR (peak 1), the 99th percentile and
// the maximum CIEDE2000 between the displayed colours, and the fraction of
// pixels whose CIEDE2000 exceeds de_threshold. The metric judged is the
// worst frame's (for psnr, the lowest). Unreadable inputs are InputError,
// unwritable outputs OutputError.
CompareResult compare(const CompareOptions& options);

}  // namespace eyestream::pipeline
