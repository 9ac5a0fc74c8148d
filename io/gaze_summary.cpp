#include "io/gaze_summary.hpp"

#include <algorithm>
#include <cstdio>

namespace eyestream::io {

std::string gaze_format_name(GazeFormat f) {
  switch (f) {
    case GazeFormat::kPupilCore: return "pupil-core";
    case GazeFormat::kNeon: return "neon";
    case GazeFormat::kNeonSurface: return "neon-surface";
    case GazeFormat::kTobii: return "tobii";
    case GazeFormat::kEyeLink: return "eyelink";
    default: return "native";
  }
}

GazeSummary summarise_gaze(const std::vector<GazeSample>& samples, GazeFormat format, int w, int h,
                           double video_end_s) {
  GazeSummary s;
  s.format = gaze_format_name(format);
  s.samples = samples.size();
  if (samples.empty()) return s;
  s.first_s = samples.front().t_s;
  s.last_s = samples.back().t_s;
  std::vector<double> intervals;
  size_t lost = 0, closed = 0, open = 0, off = 0, open_in_video = 0, off_in_video = 0;
  for (size_t i = 0; i < samples.size(); ++i) {
    const GazeSample& g = samples[i];
    if (i > 0) intervals.push_back(g.t_s - samples[i - 1].t_s);
    if (g.state == EyeState::kLost) ++lost;
    else if (g.state == EyeState::kClosed) ++closed;
    else {
      const bool is_off = g.x < 0 || g.y < 0 || g.x > w || g.y > h;
      ++open;
      off += is_off;
      if (video_end_s >= 0 && g.t_s >= 0 && g.t_s <= video_end_s) ++open_in_video, off_in_video += is_off;
    }
  }
  // The share that matters is the video's: a long log may look at the
  // screen after the video has ended.
  if (open_in_video > 0) open = open_in_video, off = off_in_video;
  if (!intervals.empty()) {
    std::nth_element(intervals.begin(), intervals.begin() + intervals.size() / 2, intervals.end());
    s.median_interval_s = intervals[intervals.size() / 2];
  }
  const double n = double(samples.size());
  s.lost_share = lost / n;
  s.closed_share = closed / n;
  s.off_frame_share = open ? double(off) / double(open) : 0.0;
  char text[256];
  if (s.off_frame_share > kOffFrameWarnShare) {
    std::snprintf(text, sizeof(text),
                  "%.0f%% of the open-eye gaze samples during the video fall off the %dx%d frame: check --gaze-units and "
                  "--gaze-source-width/--gaze-source-height",
                  100 * s.off_frame_share, w, h);
    s.warnings.push_back(text);
  }
  if (video_end_s >= 0 && (s.last_s < 0 || s.first_s > video_end_s)) {
    std::snprintf(text, sizeof(text),
                  "the gaze log (%.3f to %.3f s) does not overlap the video (0 to %.3f s): check --gaze-offset "
                  "and --gaze-sync",
                  s.first_s, s.last_s, video_end_s);
    s.warnings.push_back(text);
  }
  if (!intervals.empty() && (s.median_interval_s < 0.0005 || s.median_interval_s > 0.5)) {
    std::snprintf(text, sizeof(text),
                  "the median interval between gaze samples is %.3g s (a tracker gives 0.0005 to 0.5 s): check "
                  "the log's time unit",
                  s.median_interval_s);
    s.warnings.push_back(text);
  }
  return s;
}

std::string GazeSummary::line() const {
  char text[256];
  std::snprintf(text, sizeof(text),
                "gaze: %s, %zu samples at %.4g Hz, %.3f to %.3f s, %.1f%% lost, %.1f%% closed, %.1f%% off the frame",
                format.c_str(), samples, median_interval_s > 0 ? 1.0 / median_interval_s : 0.0, first_s, last_s,
                100 * lost_share, 100 * closed_share, 100 * off_frame_share);
  return text;
}

}  // namespace eyestream::io
