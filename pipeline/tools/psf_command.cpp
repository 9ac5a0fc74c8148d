#include "pipeline/tools/psf_command.hpp"

#include <cmath>
#include <filesystem>
#include <optional>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "glare/psf_kernel.hpp"
#include "glare/wave_lines.hpp"
#include "io/error.hpp"
#include "io/exr_file.hpp"
#include "io/png_file.hpp"
#include "io/staged_file.hpp"
#include "pipeline/settings/plan.hpp"

namespace eyestream::pipeline {

std::string PsfSummary::text() const {
  std::ostringstream o;
  o.precision(4);
  o << "pupil " << pupil_mm << " mm\n";
  const double radii[3] = {0.05, 1.0, 10.0};
  for (int i = 0; i < 3; ++i)
    o << "energy within " << radii[i] << " deg: " << within[i] << ", beyond: " << 1.0 - within[i] << "\n";
  return o.str();
}

ViewerPsf viewer_psf(const Settings& s, int width, int height, double adaptation_log) {
  io::SourceInfo frame;
  frame.width = width;
  frame.height = height;
  frame.frames_per_second = 30.0;
  const Plan plan = compile_plan(s, frame);
  const double ppd = plan.pixels_per_degree;
  const glare::EyeOptics optics = plan.eye_optics();
  ViewerPsf psf;
  psf.pixels_per_degree = ppd;
  psf.summary.pupil_mm = optics.pupil_mm(adaptation_log);
  std::vector<cv::Mat> channels;
  const cv::Point centre(width - 1, height - 1);
  if (plan.glare.gaussian) {
    // Yoshida et al. 2008's kernel, sigma in degrees, unit sum within the frame's reach.
    cv::Mat g(2 * height - 1, 2 * width - 1, CV_32F);
    const double sigma = plan.glare.gaussian_sigma_deg * ppd;
    g.forEach<float>([&](float& v, const int* p) {
      v = float(std::exp(-(std::pow(p[1] - centre.x, 2) + std::pow(p[0] - centre.y, 2)) / (2 * sigma * sigma)));
    });
    g /= cv::sum(g)[0];
    channels.assign(3, g);
  } else {
    const glare::ComponentKernels k = glare::build_component_kernels(width, height, ppd, optics);
    const glare::PsfWeights w = optics.weights(adaptation_log);
    // With wave-optics lines: their pattern for this pupil, the light on
    // the eye's axis, at time 0 (no hippus).
    std::optional<glare::WavePattern> wave;
    if (plan.glare.wave_lines) {
      glare::WaveState state;
      state.pupil_mm = psf.summary.pupil_mm;
      wave = glare::wave_pattern(glare::viewer_aperture(plan.glare.viewer.seed, plan.glare.viewer.eyelid_mrd1_mm), state, ppd,
                                 int(glare::kWavePatternReach_deg * ppd));
    }
    for (int c = 0; c < 3; ++c) {
      cv::Mat kc = glare::combined_kernel(k, w, c);
      if (wave) kc = k.core * w.core + glare::with_wave_lines(glare::line_part(k, w, c), *wave, c, plan.glare.viewer.haze);
      kc.convertTo(kc, CV_32F);
      channels.push_back(kc);
    }
  }
  const double radii[3] = {0.05, 1.0, 10.0};
  for (int y = 0; y < channels[1].rows; ++y)
    for (int x = 0; x < channels[1].cols; ++x) {
      const double t = std::hypot(x - centre.x, y - centre.y) / ppd;
      for (int i = 0; i < 3; ++i)
        if (t <= radii[i]) psf.summary.within[i] += channels[1].at<float>(y, x);
    }
  cv::merge(channels, psf.kernel);
  return psf;
}

PsfSummary write_psf(const Settings& s, const PsfRequest& r) {
  if (r.output.empty()) throw UsageError("psf: -o FILE.exr is required");
  const ViewerPsf psf = viewer_psf(s, r.width, r.height, r.adaptation_log);
  const cv::Mat& rgb = psf.kernel;
  std::vector<cv::Mat> channels;
  cv::split(rgb, channels);
  const PsfSummary summary = psf.summary;
  io::StagedFile exr(r.output);
  io::write_exr(exr.temp_path().string(), rgb, io::ExrWriteOptions{false, std::nullopt, std::nullopt});
  // The picture: log10(K / K_max) from -8 to 0, per channel, as 8-bit BGR.
  double peak;
  cv::minMaxLoc(channels[1], nullptr, &peak);
  cv::Mat flat = rgb.reshape(1) / peak, picture;
  cv::max(flat, 1e-8, flat);
  cv::log(flat, flat);
  flat.convertTo(picture, CV_8U, 255.0 / 8.0 / std::log(10.0), 255.0);
  picture = picture.reshape(3);
  cv::cvtColor(picture, picture, cv::COLOR_RGB2BGR);
  const std::vector<unsigned char> png = io::encode_png(picture);  // tagged as the other pictures are
  io::StagedFile png_file(std::filesystem::path(r.output).replace_extension(".png"));
  io::write_all(png_file, png);
  exr.commit();
  png_file.commit();
  return summary;
}

}  // namespace eyestream::pipeline
