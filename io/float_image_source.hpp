// Frames from Radiance .hdr or PFM stills: one file, or a numbered
// sequence or folder of them (OpenCV reads both), for renderer output.
#pragma once

#include <string>
#include <vector>

#include "io/exr_sequence_source.hpp"
#include "io/frame_sequence.hpp"
#include "io/frame_source.hpp"

namespace eyestream::io {

// Pixel values times the scale are linear Rec.709 cd/m^2: --scale, else
// 179 for .hdr (Radiance's luminous efficacy of its watts: L = 179 Y) and
// 1 for PFM. Frame k's time is (number_k - number_0) / fps (--fps, else
// 30). A frame of another size than the first is an InputError naming it.
class FloatImageSource : public FrameSource {
 public:
  FloatImageSource(const std::string& input, const ExrSequenceOptions& options);
  const SourceInfo& info() const override { return info_; }
  std::optional<SceneFrame> next() override;
  bool knows_times() const override { return true; }
  std::optional<double> time_of(std::int64_t index) const override;

 private:
  ExrSequenceOptions options_;
  std::vector<SequenceEntry> entries_;
  SourceInfo info_;
  std::optional<SceneFrame> first_;
  size_t position_ = 0;
};

// True for a path naming .hdr or .pfm stills (file, pattern or folder of them).
bool is_float_image_input(const std::string& input);

}  // namespace eyestream::io
