// The split glare engine: the PSF's sharp centre at full resolution, its
// smoother parts at reduced resolutions (docs/model.md). Level l runs at a
// reduction f_l (1, then `factor`, then 4 factor); with the windows
// w_l(r) = 1 within S_l pixels of the source, falling linearly to 0 at
// R_l, level l holds K (w_l - w_(l-1)), integrated over its f_l x f_l
// pixel footprints, and the last level holds K (1 - w_(l-1)):
//   near   (full resolution, S_0 = R_0 / 2, R_0 = 8 factor pixels),
//   middle (1/factor, out to R_1 = S_1 + the larger of S_1 / 2 and 32
//           factor pixels, S_1 = the larger of 32 factor pixels and 4.5
//           deg, padded by that reach),
//   tail   (1/(4 factor), the whole frame's reach).
// A level takes over where its blocks are small against the PSF's change
// (R_0 = 8 f_middle; S_1 >= 8 f_tail, as a hand-over from 4 to 8 f_tail
// cost twice the stated error), and the tail only beyond the lenticular
// halo (rings to 4.5 deg, whose colour order its blocks would repaint:
// tests/split_engine_test.cpp), in a ramp at least 8 of its blocks wide.
// Until the fourteenth session the tail's ramp ran from R_1 / 2 to R_1,
// 9 deg where the halo set S_1: `balanced`'s middle level transforms at
// 1080p were 1280 x 864 instead of 1200 x 768, for the same bench
// accuracy (docs/performance.md).
// The windows are applied at pixel centres (near) and block centres, so the
// levels together hold the undivided kernel's energy to within 0.05 %
// (tests/split_engine_test.cpp); each coarse level is enlarged keeping its
// block energies, so the engine moves light without adding any. Near
// sources are scattered directly when the input is sparse (the excess over
// the display peak usually is), else by FFT: over tiles of the frame
// (tiled_convolver.hpp) where a tile's window is mostly output, as at
// factor 2, else over the whole frame.
#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "glare/fft_convolver.hpp"
#include "glare/linear_taps.hpp"
#include "glare/psf_kernel.hpp"
#include "glare/tiled_convolver.hpp"

namespace eyestream::glare {

class SplitConvolver {
 public:
  // For width x height frames at pixels_per_degree; `factor` >= 2 is the
  // middle level's reduction, R_0 = 8 factor pixels. Without the centre,
  // the kernel's centre pixel is 0: only the light that leaves its pixel
  // is spread.
  SplitConvolver(int width, int height, double pixels_per_degree, int factor, const EyeOptics& optics = EyeOptics(),
                 bool with_centre = true);
  ~SplitConvolver();

  // As FftConvolver::convolve.
  cv::Mat convolve(const cv::Mat& rgb, const PsfWeights& w) const { return convolve(rgb, same_in_every_channel(w)); }
  cv::Mat convolve(const cv::Mat& rgb, const ChannelWeights& w) const;

  int factor() const { return factor_; }
  int near_radius() const { return radius_; }

 private:
  struct Level {
    int factor = 1;          // reduction against the frame
    cv::Size size;           // the frame at this level, padded to whole coarsest blocks
    std::unique_ptr<FftConvolver> engine;
  };
  cv::Mat spread_near(const cv::Mat& rgb, const ChannelWeights& w) const;
  // Adds the coarse levels' spread light to `out` (the near part), and
  // sets what rounding left negative to 0.
  void add_coarse(const cv::Mat& rgb, const ChannelWeights& w, cv::Mat& out) const;

  int width_, height_, factor_, radius_;
  ComponentKernels near_;  // windowed, (2R+1) x (2R+1)
  // The near part of a dense frame: by tiles where they waste little
  // (tile_output_share), else by one whole-frame transform.
  std::unique_ptr<TiledConvolver> near_tiles_;
  std::unique_ptr<FftConvolver> near_fft_;
  size_t dense_from_ = 0;  // sources beyond which the near part is dense
  std::vector<Level> coarse_;  // middle, tail
  // An enlargement by bilinear taps (as cv::resize): each output column's
  // and row's taps, and the weight each input column and row gets over the
  // whole output (its total is the input's weighted by these).
  struct Enlargement {
    std::vector<LinearTap> x, y;
    std::vector<double> column_weight, row_weight;
    Enlargement(cv::Size from, cv::Size to);
    struct Totals {
      cv::Vec3d input, enlarged;
    };
    Totals totals(const cv::Mat& m) const;  // of m (CV_32FC3, `from`-sized) and of m enlarged
  };
  Enlargement tail_up_;    // the tail level to the middle level's size
  Enlargement middle_up_;  // the middle level to the padded frame
};

}  // namespace eyestream::glare
