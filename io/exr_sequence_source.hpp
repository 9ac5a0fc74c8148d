// Frames from a numbered OpenEXR sequence or a folder of EXR files.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "io/exr_file.hpp"
#include "io/memory_guard.hpp"
#include "io/frame_sequence.hpp"
#include "io/frame_source.hpp"

namespace eyestream::io {

struct ExrSequenceOptions {
  std::optional<double> scale;              // cd/m^2 per unit; overrides whiteLuminance
  std::optional<double> frames_per_second;  // overrides framesPerSecond
  double default_frames_per_second = 30.0;  // when neither says
  bool skip_missing = false;
  std::int64_t max_pixels = default_max_pixels();  // memory_guard.hpp
  std::string layer;  // of layered files (exr_file.hpp); "": the beauty pass
};

// Decodes each frame to linear Rec.709 in cd/m^2: pixel * scale, where scale
// is --scale, else the file's whiteLuminance, else 1 (values already in
// cd/m^2); converted from the file's chromaticities when they differ from
// Rec.709. Frame k's time is (number_k - number_0) / fps, so a skipped frame
// keeps the timing of the rest. A frame whose size or channels (RGB, RGBA,
// Y) differ from the first is an InputError naming it.
class ExrSequenceSource : public FrameSource {
 public:
  ExrSequenceSource(const std::string& input, const ExrSequenceOptions& options);
  const SourceInfo& info() const override { return info_; }
  std::optional<SceneFrame> next() override;
  bool knows_times() const override { return true; }
  std::optional<double> time_of(std::int64_t index) const override;

 private:
  SceneFrame decode(const SequenceEntry& entry, std::int64_t index) const;
  // Reads the entry's file, each band of rows taken to Rec.709 and cd/m^2
  // and its non-finite pixels counted while it is in cache.
  ExrImage read(const SequenceEntry& entry, std::int64_t* nonfinite) const;
  // The frame from an image so read.
  SceneFrame frame_from(ExrImage image, std::int64_t nonfinite, const SequenceEntry& entry, std::int64_t index) const;

  ExrSequenceOptions options_;
  std::vector<SequenceEntry> entries_;
  std::optional<SceneFrame> first_;  // decoded while probing, handed out first
  SourceInfo info_;
  std::string channels_;  // of the first frame; every frame must match
  size_t position_ = 0;
};

}  // namespace eyestream::io
