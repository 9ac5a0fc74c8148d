// `eyestream bench`: the speed/accuracy trade of the quality presets,
// measured on built-in scenes (quality_presets.hpp, stage_activity.hpp).
#pragma once

#include <string>
#include <vector>

#include "pipeline/bench/bench_case.hpp"
#include "pipeline/bench/reference_error.hpp"

namespace eyestream::pipeline {

struct BenchRequest {
  std::string scene = "night-drive,night-city";  // scenes that need every stage, comma-separated
  std::string sizes = "720p,1080p";   // 720p, 1080p, 4k or WxH, comma-separated
  std::string presets = "reference,balanced,fast";
  int frames = 24;  // enough that every stage works on most frames (with 8, mesopic vision began on 3 of them)
  bool skip_study = true;  // balanced with and without skipping, on a dim still frame and on the scene
  std::string csv, png;    // where the table and the chart go ("": not written)
  bool quiet = false;      // no line per case on stderr
  std::string flare_model = "drawn";  // every case's --flare-model
  bool peers = false;  // also time the peers (bench_peers.hpp)
};

struct BenchRow {
  std::string scene, size, preset;
  bool skip = true;
  std::string against;  // what the error is measured against
  BenchCase figures;    // without its frames
  ReferenceError error;
};

// Runs every case, printing a line per case to stderr as it goes.
std::vector<BenchRow> run_bench(const BenchRequest& request);

// The rows as an aligned text table, and as CSV (with a header).
std::string bench_table(const std::vector<BenchRow>& rows);
void write_bench_csv(const std::vector<BenchRow>& rows, const std::string& path);

// The items of a comma-separated list (empty items dropped).
std::vector<std::string> split_list(const std::string& text);

// A preset's settings for a bench case (UsageError for an unknown preset).
Settings preset_settings(const std::string& preset, bool skip, const std::string& flare_model = "drawn");

// Width and height of "720p", "1080p", "4k" or "WxH"; UsageError otherwise.
cv::Size parse_frame_size(const std::string& text);

}  // namespace eyestream::pipeline
