// Glare convolution with a small kernel (the split engine's near part, a
// few tens of pixels across) by FFT over tiles of the frame (overlap-save,
// FFTW, double precision), not over the whole frame. Each tile's output
// block is T - 2R pixels square, read from a T x T window reaching R pixels
// beyond it (zero outside the frame), so nothing wraps. The whole-frame
// transform moved its padded spectrum (17 MB a channel at 1080p) through
// memory three times; a tile's transform stays in the core's cache, and
// its kernel spectra take 1.6 MB instead of 52 (at 1080p, R = 16). A tile
// whose window holds no light in a channel is not transformed. The tiles
// go in one share per thread, each with its arrays (a window per channel
// and a spectrum: 2.1 MB at T = 256) kept with the engine, so the frame
// loop asks the allocator for nothing; one engine convolves one frame at
// a time.
#pragma once

#include <memory>
#include <opencv2/core.hpp>

#include "glare/psf_kernel.hpp"
#include "glare/psf_weights.hpp"

namespace eyestream::glare {

class TiledConvolver {
 public:
  // For width x height frames and centred, point-symmetric kernels of any
  // odd size (reach R = half the size).
  TiledConvolver(const ComponentKernels& kernels, int width, int height);
  ~TiledConvolver();
  TiledConvolver(const TiledConvolver&) = delete;
  TiledConvolver& operator=(const TiledConvolver&) = delete;

  // As FftConvolver::convolve: each channel of `rgb` (CV_32FC3, finite)
  // with that channel's combined kernel, light leaving the frame lost,
  // negative rounding residue set to 0. Tiles are fixed and each is
  // computed alike on any thread: results do not depend on the thread count.
  void convolve(const cv::Mat& rgb, const ChannelWeights& w, cv::Mat& out) const;

  // The tile's transform size T (a power of two).
  int tile_size() const;

  struct Engine;

 private:
  std::unique_ptr<Engine> engine_;
};

// The power-of-two tile side for a kernel of reach `radius`: the one of
// least transform work per output pixel, T^2 log2(T^2) / (T - 2R)^2,
// among 64 to 512 (at most 256 while a 256 tile's output block is half
// its side or more, so that a tile's arrays stay in a core's cache); then
// doubled while its output block is under a quarter of its side (reaches
// of 193 px or more, which the split engine never has).
int tile_size_for(int radius);

// The share of that tile's window that is output, ((T - 2R) / T)^2: the
// tiles' transform work against a whole-frame transform's is about its
// inverse (the split engine uses tiles from 0.7 up: tests and bench in
// docs/performance.md).
double tile_output_share(int radius);

}  // namespace eyestream::glare
