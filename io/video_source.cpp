#include "io/video_source.hpp"

#include <cmath>
#include <cstdio>

#include "io/error.hpp"
#include "io/primaries.hpp"
#include "io/staged_file.hpp"
#include "io/transfer_functions.hpp"

namespace eyestream::io {

namespace {

std::string transfer_from_tag(const std::string& path, const VideoColour& c, const std::string& requested) {
  if (requested != "auto") return requested;
  if (c.transfer == "smpte2084") return "pq";
  if (c.transfer == "arib-std-b67") return "hlg";
  throw InputError(path + ": the video's transfer is '" + c.transfer +
                   "', not PQ or HLG; an SDR or untagged video needs --video-transfer (pq, hlg or sdr) and, for "
                   "sdr or hlg, --video-peak");
}

}  // namespace

VideoSource::VideoSource(const std::string& path, const VideoSourceOptions& o) : path_(path) {
  protect_input(path);
  reader_ = std::make_unique<VideoReader>(path);
  const VideoColour& c = reader_->colour();
  transfer_ = transfer_from_tag(path, c, o.transfer);
  peak_ = o.peak_cd_m2 > 0 ? o.peak_cd_m2 : transfer_ == "sdr" ? 100.0 : 1000.0;
  stop_on_bad_ = o.on_bad_video == "stop";
  bt2020_ = c.primaries == "bt2020" || (c.primaries == "unknown" && transfer_ != "sdr");
  if (std::int64_t(reader_->width()) * reader_->height() > o.max_pixels)
    throw InputError(path + ": " + std::to_string(reader_->width()) + "x" + std::to_string(reader_->height()) +
                     " exceeds --max-pixels");
  lut_.resize(65536);
  for (int i = 0; i < 65536; ++i) {
    const double e = i / 65535.0;
    lut_[i] = float(transfer_ == "pq" ? pq_to_luminance(e) : transfer_ == "hlg" ? hlg_to_scene(e) : bt1886_to_linear(e));
  }
  info_.width = reader_->width();
  info_.height = reader_->height();
  info_.frames_per_second = reader_->frames_per_second() > 0 ? reader_->frames_per_second() : 30.0;
  info_.frame_count = reader_->frame_count();
  info_.description = "video, " + std::to_string(c.bit_depth) + "-bit, transfer " + transfer_ +
                      (transfer_ == "pq" ? "" : " at " + std::to_string(int(peak_)) + " cd/m^2") + ", primaries " +
                      (bt2020_ ? "BT.2020" : "Rec.709");
}

std::optional<SceneFrame> VideoSource::next() {
  std::optional<VideoFrame> v;
  try {
    v = reader_->next();
  } catch (const InputError& e) {
    if (!stop_on_bad_) throw;
    std::fprintf(stderr, "eyestream: warning: %s; stopping after %lld frames (--on-bad-video stop)\n", e.what(),
                 (long long)read_);
    return std::nullopt;
  }
  if (!v) {
    // Early end: fewer frames than the container counts, or (without a
    // count) the last frame's end well before the container's duration.
    const double interval = 1.0 / info_.frames_per_second, duration = reader_->duration_s();
    const bool short_count = reader_->frame_count() > read_;
    const double gap = duration - (last_time_ + interval);
    const bool short_time = reader_->frame_count() < 0 && duration > 0 && gap > 1.5 * interval;
    // Half an interval to one and a half: container durations round, and a
    // variable frame rate stretches the last interval, so this may be no
    // loss; one missing frame looks the same. Said, not refused.
    if (reader_->frame_count() < 0 && duration > 0 && gap > 0.5 * interval && !short_time)
      std::fprintf(stderr,
                   "eyestream: warning: %s: the last frame ends at %.3f s, its container says %.3f s: a frame may be "
                   "missing\n",
                   path_.c_str(), last_time_ + interval, duration);
    if (short_count || short_time) {
      char said[64];
      std::snprintf(said, sizeof(said), short_count ? "%.0f frames" : "%.3f s", short_count ? double(reader_->frame_count()) : duration);
      const std::string message = path_ + ": ends after " + std::to_string(read_) + " frames, its container says " + said;
      if (!stop_on_bad_) throw InputError(message + " (--on-bad-video stop keeps what was read)");
      std::fprintf(stderr, "eyestream: warning: %s\n", message.c_str());
    }
    return std::nullopt;
  }
  ++read_;
  last_time_ = v->time_s;
  cv::Mat rgb = v->rgb;
  const double gamma = hlg_system_gamma(peak_);
  const bool hlg = transfer_ == "hlg", sdr = transfer_ == "sdr";
  rgb.forEach<cv::Vec3f>([&](cv::Vec3f& p, const int*) {
    for (int c = 0; c < 3; ++c) p[c] = lut_[int(std::lround(std::clamp(p[c], 0.0f, 1.0f) * 65535.0f))];
    if (hlg) {
      // BT.2100 OOTF: F_D = Lw Y_s^(gamma - 1) E, Y_s in the stream's primaries.
      const double ys = bt2020_ ? 0.2627 * p[0] + 0.6780 * p[1] + 0.0593 * p[2]
                                : 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
      p *= float(peak_ * (ys > 0 ? std::pow(ys, gamma - 1.0) : 0.0));
    } else if (sdr) {
      p *= float(peak_);
    }
  });
  if (bt2020_) apply_matrix(rgb, to_rec709_matrix(bt2020_chromaticities()));
  SceneFrame f;
  f.rgb = rgb;
  f.time_s = v->time_s;
  f.index = v->index;
  f.source = path_ + " frame " + std::to_string(v->index);
  return f;
}

}  // namespace eyestream::io
