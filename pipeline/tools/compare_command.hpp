// `eyestream compare A B`: frame-by-frame differences between two outputs
// for regression tests, with idiff's exit convention (0 pass, 1 warn,
// 2 fail).
#pragma once

#include <optional>
#include <string>

namespace eyestream::pipeline {

struct CompareOptions {
  std::string a, b;
  // What --warn/--fail judge: visible (the default, as idiff judges: the
  // share of pixels whose CIEDE2000 exceeds de_warn or de_threshold), de99,
  // demax, max, mean or psnr.
  std::string metric = "visible";
  // Limits on the judged value; unset: 0 and 0 for visible (any pixel
  // beyond the threshold), 0.5 and 1.0 otherwise.
  std::optional<double> warn, fail;
  // Per-pixel CIEDE2000 limits of `visible`. +-1 code of random noise on
  // 10^6 random 8-bit colours reached 2.66 at most (none beyond 3), so
  // dithering-sized differences pass; a pasted patch is far beyond.
  double de_threshold = 5.0;  // a pixel beyond this differs visibly: fail
  double de_warn = 3.0;       // a pixel beyond this: warn
  std::string diff_out;       // PNG pattern for difference images (CIEDE2000 heat maps)
  double diff_scale = 5.0;    // CIEDE2000 shown at full scale
  std::string json;           // report file
  std::string layer;          // layered EXRs: the layer to compare ("" the beauty pass)
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
// worst frame's (for psnr, the lowest). The summary names the pixel of the
// largest CIEDE2000 (frame, x, y, both values). Unreadable inputs are
// InputError, unwritable outputs OutputError.
CompareResult compare(const CompareOptions& options);

}  // namespace eyestream::pipeline
