// What a gaze log holds, against the video it steers: one line a run
// prints, --print-plan shows and the report keeps, and the warnings a user
// needs before trusting the output: most samples off the frame (wrong
// units or coordinate frame), a log that does not overlap the video (wrong
// sync), or an implausible sample interval (wrong time unit).
#pragma once

#include <string>
#include <vector>

#include "io/gaze_import.hpp"
#include "io/gaze_sample.hpp"

namespace eyestream::io {

struct GazeSummary {
  std::string format;  // native, pupil-core, neon, tobii or eyelink
  size_t samples = 0;
  double median_interval_s = 0.0;
  double first_s = 0.0, last_s = 0.0;
  double lost_share = 0.0, closed_share = 0.0;
  double off_frame_share = 0.0;  // of the samples with the eye open and seen (during the video, when it has any)
  std::vector<std::string> warnings;
  std::vector<std::string> notes;  // what the reader assumed or took from elsewhere (GazeRead)
  std::string line() const;  // "gaze: tobii, 1200 samples at 120 Hz, ..."
};

// Shares above this of open samples off the frame are warned about.
inline constexpr double kOffFrameWarnShare = 0.25;

// `video_end_s` < 0: the video's length is unknown (no overlap check).
GazeSummary summarise_gaze(const std::vector<GazeSample>& samples, GazeFormat format, int frame_width,
                           int frame_height, double video_end_s);

// "native", "pupil-core", "neon", "tobii" or "eyelink".
std::string gaze_format_name(GazeFormat format);

}  // namespace eyestream::io
