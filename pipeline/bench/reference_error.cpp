#include "pipeline/bench/reference_error.hpp"

#include <opencv2/imgproc.hpp>

#include "retina/colour_difference.hpp"

namespace eyestream::pipeline {

namespace {

// `state` (on a grid of `spp` sites per pixel) at the sites of a grid of
// `ref_spp` sites per pixel and `ref_size`; both grids are centred on the
// fovea (retinal_grid.hpp).
cv::Mat on_reference_sites(const cv::Mat& state, double spp, cv::Size ref_size, double ref_spp) {
  cv::Mat s64, out;
  state.convertTo(s64, CV_64FC3);
  if (state.size() == ref_size) return s64;
  const double k = spp / ref_spp;
  const double cx = (state.cols - 1) / 2.0, cy = (state.rows - 1) / 2.0;
  const double rx = (ref_size.width - 1) / 2.0, ry = (ref_size.height - 1) / 2.0;
  const cv::Matx23d to_run(k, 0, cx - k * rx, 0, k, cy - k * ry);
  cv::warpAffine(s64, out, to_run, ref_size, cv::INTER_LINEAR | cv::WARP_INVERSE_MAP, cv::BORDER_REPLICATE);
  return out;
}

double state_difference(const cv::Mat& reference, double ref_spp, const cv::Mat& run, double spp, double scale) {
  cv::Mat ref64;
  reference.convertTo(ref64, CV_64FC3);
  return cv::norm(ref64, on_reference_sites(run, spp, reference.size(), ref_spp), cv::NORM_INF) / scale;
}

}  // namespace

ReferenceError error_against(const BenchCase& reference, const BenchCase& run) {
  CV_Assert(reference.shown.size() == run.shown.size());
  retina::DeltaEHistogram histogram;
  for (size_t i = 0; i < run.shown.size(); ++i) histogram.add(retina::ciede2000_map(reference.shown[i], run.shown[i], 1.0));
  ReferenceError e;
  e.de_p99 = histogram.quantile(0.99);
  e.de_max = histogram.max();
  e.state = std::max(
      state_difference(reference.bleached, reference.sites_per_pixel, run.bleached, run.sites_per_pixel, 1.0),
      state_difference(reference.deficit, reference.sites_per_pixel, run.deficit, run.sites_per_pixel,
                       reference.calcium_max));
  return e;
}

}  // namespace eyestream::pipeline
