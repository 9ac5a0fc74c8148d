// Scene frames from an HDR video file through the FFmpeg libraries: PQ
// (absolute) or HLG (relative, displayed at a nominal peak), BT.2020 or
// Rec.709 primaries, frame times from the stream's timestamps.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "io/frame_source.hpp"
#include "io/video_reader.hpp"

namespace eyestream::io {

struct VideoSourceOptions {
  // auto: from the stream's transfer tag (PQ or HLG; anything else is
  // refused); pq, hlg, or sdr (BT.1886, gamma 2.4) to state it.
  std::string transfer = "auto";
  double peak_cd_m2 = 0.0;  // HLG nominal peak (0: 1000) or SDR white (0: 100), cd/m^2
  std::int64_t max_pixels = 400'000'000;
  // A packet that does not decode, or a file that ends more than a frame
  // before its container says: fail (InputError), or stop there with a
  // warning on stderr, so what was read is finalised.
  std::string on_bad_video = "fail";
};

// Decodes each frame to linear Rec.709 in cd/m^2: the transfer's EOTF (for
// HLG the BT.2100 OOTF with the system gamma of the nominal peak), then the
// primaries (BT.2020 converted, out-of-gamut values kept negative; untagged
// primaries are BT.2020 for PQ and HLG, Rec.709 for SDR). InputError naming
// the file for an SDR or untagged stream without --video-transfer, a frame
// over max_pixels, or a packet that does not decode.
class VideoSource : public FrameSource {
 public:
  VideoSource(const std::string& path, const VideoSourceOptions& options);
  const SourceInfo& info() const override { return info_; }
  std::optional<SceneFrame> next() override;

 private:
  std::string path_;
  std::unique_ptr<VideoReader> reader_;
  std::string transfer_;  // pq, hlg or sdr
  double peak_ = 0.0;
  bool bt2020_ = false;
  std::vector<float> lut_;  // 16-bit code -> linear (PQ: cd/m^2; HLG: scene light; SDR: relative)
  bool stop_on_bad_ = false;
  std::int64_t read_ = 0;
  double last_time_ = 0.0;
  SourceInfo info_;
};

}  // namespace eyestream::io
