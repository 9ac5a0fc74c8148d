// The wave-optics lines of the lights in a frame (--flare-model wave):
// the fine structure of wave_pattern.hpp laid over the smooth PSF that a
// glare engine has already spread, frame by frame:
//   - which lights show lines: those of the light the engine spreads (the
//     whole frame, or in --glare-mode excess the excess over the display
//     peak) whose luminance is at least 40 times their surround's, the
//     mean between the 2 deg and the 6 deg square around them (a lamp or
//     the sun's disc lies inside the inner one): the contrast Matsuda and
//     Ikedo's table 2 gives for glare to show (their threshold 40);
//   - the state: the optics' pupil plus hippus (hippus.hpp), the frame's
//     time (the vitreous drifts), and the direction of the brightest such
//     light from the gaze (the eye's axis): particles at different depths
//     meet it at different places. Every light of a frame takes that one
//     direction's pattern (one pattern a frame: this project's economy);
//   - the lines: each light adds its PSF's line components (inner, outer,
//     halo, with their weights) times (1 - haze)(M' - 1) within
//     kWavePatternReach_deg, M' the pattern scaled on each 1 px ring so
//     that the ring's light is unchanged (sum of lines M' = sum of lines):
//     light moved along rings, none added, and haze thins the lines by its
//     share (Matsuda and Ikedo).
// Lights are scattered one by one, row by row, while that costs less than
// convolving their box by FFT (a channel per task); the search for lights
// reads box sums from one integral image, and the lines come back to the
// frame's resolution in one pass that also adds them.
#pragma once

#include <array>
#include <opencv2/core.hpp>

#include "glare/eye_optics.hpp"
#include "glare/hippus.hpp"
#include "glare/psf_kernel.hpp"
#include "glare/wave_aperture.hpp"
#include "glare/wave_pattern.hpp"

namespace eyestream::glare {

class WaveLines {
 public:
  static constexpr double kContrast = 40.0;
  static constexpr double kSurroundInner_deg = 2.0, kSurroundOuter_deg = 6.0;  // squares' sides

  // optics: the smooth PSF (its flare_lines off); for frames of
  // frame_pixels_per_degree. Frames finer than 35 px/deg are reduced by a
  // whole factor to at most that (the pattern's detail is 0.02-0.04 deg).
  WaveLines(const EyeOptics& optics, double frame_pixels_per_degree);

  // `retinal` with the lines of the lights in `rgb` (cd/m^2, CV_32FC3, the
  // light the engine spread) added, into `result` (which may be `retinal`;
  // otherwise (re)allocated), for weights w, the optics' pupil, the frame's
  // time and the gaze (frame pixels). Returns whether any light showed
  // lines; if none did, `result` is left as it was.
  bool add(const cv::Mat& rgb, const PsfWeights& w, double pupil_mm, double time_s, cv::Point2d gaze,
           const cv::Mat& retinal, cv::Mat& result) const;
  bool add(const cv::Mat& rgb, const PsfWeights& w, double pupil_mm, double time_s, cv::Point2d gaze,
           cv::Mat& retinal) const {
    return add(rgb, w, pupil_mm, time_s, gaze, retinal, retinal);
  }

  // How the lights' lines are spread: the cheaper way (automatic), or one
  // way always (the tests compare the two).
  enum class Spread { automatic, scatter, fft };
  void set_spread(Spread s) { spread_ = s; }

  // The state add() would use (for the report and the tests).
  WaveState state(double pupil_mm, double time_s, double light_x_deg, double light_y_deg) const;

 private:
  // The lines of the lights of rgb in delta (a plane per channel), which
  // covers their reach (rgb's pixels).
  using Planes = std::array<cv::Mat, 3>;
  bool lines(const cv::Mat& rgb, const PsfWeights& w, double pupil_mm, double time_s, cv::Point2d gaze,
             Planes& delta, cv::Rect& reach) const;
  struct Light {
    int x, y;
    cv::Vec3f rgb;
    float luminance;
  };
  int factor_;
  double ppd_, haze_;
  int radius_;
  ComponentKernels smooth_;  // (2 radius + 1) squared
  WaveAperture aperture_;
  Hippus hippus_;
  Spread spread_ = Spread::automatic;
};

// The line part of channel c's kernel (inner, outer and halo with their
// weights; CV_64F, centred) times 1 + (1 - haze)(M'_c - 1) within the
// pattern's radius, M' scaled per 1 px ring to keep the ring's light.
cv::Mat with_wave_lines(const cv::Mat& lines, const WavePattern& pattern, int channel, double haze);

// That line part of channel c (without the core).
cv::Mat line_part(const ComponentKernels& k, const PsfWeights& w, int channel);

}  // namespace eyestream::glare
