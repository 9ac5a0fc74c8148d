#include "pipeline/eye/glare_stage.hpp"

#include <array>
#include <cstring>
#include <utility>
#include <opencv2/imgproc.hpp>

#include "glare/uniform_field.hpp"
#include "glare/veiling_luminance.hpp"
#include "pipeline/eye/pixel_checks.hpp"
#include "pipeline/eye/surround_row.hpp"
#include "retina/enlarged_rows.hpp"
#include "retina/halve_frame.hpp"
#include "retina/luminance.hpp"
#include "retina/parallel_fill.hpp"
#include "retina/vector_clones.hpp"

namespace eyestream::pipeline {

namespace {

// Halved when the plane has at most half the frame's px/deg (and the frame
// is big enough to halve).
cv::Size halved_frame(const Plan& plan) {
  if (plan.glare.plane_scale > 0.5 || plan.width < 64 || plan.height < 64) return {};
  // An equidistant plane at exactly half would be the halved frame itself.
  if (plan.projection->kind() == Projection::equidistant && plan.glare.plane_scale == 0.5) return {};
  return {(plan.width + 1) / 2, (plan.height + 1) / 2};
}

std::shared_ptr<const FrameProjection> glare_plane(const Plan& plan) {
  const cv::Size halved = halved_frame(plan);
  if (!halved.empty())  // the halved frame spans the same angles at half the pixels per degree
    return std::make_shared<const FrameProjection>(halved.width, halved.height, plan.fov_deg, plan.projection->kind(),
                                                   2.0 * plan.glare.plane_scale);
  if (plan.glare.plane_scale == 1.0) return plan.projection;
  return std::make_shared<const FrameProjection>(plan.width, plan.height, plan.fov_deg, plan.projection->kind(),
                                                 plan.glare.plane_scale);
}

// A frame row: the moved light (two widened rows of the halved frame,
// blended down with weight fy of b) plus the light the PSF keeps on the
// frame's own pixel, kept x in.
EYESTREAM_VECTOR_CLONES
void add_kept_row(const float* a, const float* b, float fy, const float* in, cv::Vec3f kept, float* out, int pixels) {
  const float k0 = kept[0], k1 = kept[1], k2 = kept[2];
  for (int x = 0; x < pixels; ++x) {
    out[3 * x] = a[3 * x] * (1.0f - fy) + b[3 * x] * fy + k0 * in[3 * x];
    out[3 * x + 1] = a[3 * x + 1] * (1.0f - fy) + b[3 * x + 1] * fy + k1 * in[3 * x + 1];
    out[3 * x + 2] = a[3 * x + 2] * (1.0f - fy) + b[3 * x + 2] * fy + k2 * in[3 * x + 2];
  }
}

// A frame row: the moved light already in `out`, plus the light the PSF
// keeps on the frame's own pixel, kept x in (each channel o + k i, as
// cv::Vec3f's own arithmetic gives it).
EYESTREAM_VECTOR_CLONES
void add_kept(const float* in, cv::Vec3f kept, float* out, int pixels) {
  const float k0 = kept[0], k1 = kept[1], k2 = kept[2];
  for (int x = 0; x < pixels; ++x) {
    out[3 * x] = out[3 * x] + k0 * in[3 * x];
    out[3 * x + 1] = out[3 * x + 1] + k1 * in[3 * x + 1];
    out[3 * x + 2] = out[3 * x + 2] + k2 * in[3 * x + 2];
  }
}

}  // namespace

GlareStage::GlareStage(const Plan& plan)
    : plan_(plan),
      optics_(plan.eye_optics()),
      halved_(halved_frame(plan)),
      plane_(glare_plane(plan)),
      ppd_(plane_->pixels_per_degree()) {
  const cv::Size plane = plane_->plane_size();
  // The plane's maps at set-up (in every glare mode): the run empties the
  // buffer pool after it, and the first frame does not wait for them.
  if (!plane_->identity()) plane_->make_carriage_now();
  if (!halved_.empty()) {  // the halved glare frame's taps to the frame (spread())
    up_cols_ = std::make_shared<const retina::BilinearAxis>(plan.width, halved_.width,
                                                            float(halved_.width) / float(plan.width));
    up_rows_ = std::make_shared<const retina::BilinearAxis>(plan.height, halved_.height,
                                                            float(halved_.height) / float(plan.height));
  }
  if (plan.glare.gaussian) {  // no kernels: a separable blur does the work
    const double sigma = plan.glare.gaussian_sigma_deg * ppd_;
    const cv::Mat g = cv::getGaussianKernel(cvRound(sigma * 8 + 1) | 1, sigma, CV_64F);  // GaussianBlur's, for floats
    const double centre = g.at<double>(g.rows / 2) * g.at<double>(g.rows / 2);
    for (cv::Vec3d& c : centre_) c = cv::Vec3d::all(centre);
    if (plan.glare.full)
      in_frame_.push_back(in_frame_share(in_frame_source(), {}));  // weights unused
    return;
  }
  if (plan.glare.wave_lines) wave_ = std::make_unique<glare::WaveLines>(optics_, plan.pixels_per_degree);
  // The full kernels also give the report its veil (veiling_luminance.hpp).
  // On an angle plane the engines spread only the light that leaves its
  // pixel (their kernels' centre pixel 0); the rest stays on the frame's
  // pixels (spread()).
  const bool with_centre = plane_->identity();
  const glare::ComponentKernels centre = glare::build_component_kernels(1, 1, ppd_, optics_);
  for (int ch = 0; ch < 3; ++ch) {
    centre_[0][ch] = centre.core.at<double>(0, 0);
    centre_[1][ch] = centre.inner.at<double>(0, 0);
    centre_[2][ch] = centre.outer.at<double>(0, 0);
    centre_[3][ch] = centre.halo[ch].at<double>(0, 0);
  }
  if (plan.glare.tail_factor <= 1 || plan.report)
    kernels_ = glare::build_component_kernels(plane.width, plane.height, ppd_, optics_);
  if (plan.glare.tail_factor > 1) {
    split_ = std::make_unique<glare::SplitConvolver>(plane.width, plane.height, ppd_,
                                                     plan.glare.tail_factor, optics_, with_centre);
  } else {
    // The engine copies the kernels' spectra: the centre is dropped for it
    // and put back for the report.
    const cv::Point c = kernels_.centre();
    cv::Mat* ks[6] = {&kernels_.core, &kernels_.inner, &kernels_.outer,
                      &kernels_.halo[0], &kernels_.halo[1], &kernels_.halo[2]};
    double kept[6];
    for (int i = 0; i < 6; ++i) {
      kept[i] = ks[i]->at<double>(c);
      if (!with_centre) ks[i]->at<double>(c) = 0.0;
    }
    convolver_ = std::make_unique<glare::FftConvolver>(kernels_);
    for (int i = 0; i < 6; ++i) ks[i]->at<double>(c) = kept[i];
  }
  if (!plan.glare.full) return;
  // The in-frame share of each component, by the engine itself, so that a
  // uniform scene and surround come out uniform to the engine's rounding.
  // The core, inner and outer components are the same in every channel
  // (only the halo's rings are coloured), so one pass spreads all three,
  // one per channel, each channel computed as it would be alone; the
  // surround reads them as that pass leaves them (SurroundShares::triple),
  // not split into three maps (a serial copy of 25 MB at 1080p).
  const cv::Mat source = in_frame_source();  // made once for both passes
  glare::ChannelWeights grey;
  grey[0].core = grey[1].inner = grey[2].outer = 1.0;
  in_frame_.push_back(in_frame_share(source, grey));
  triple_ = true;
  // The halo's share is coloured where its rings reach the frame's edge,
  // else the same in every channel: then one channel holds it (the core,
  // inner and outer shares are grey by construction: one channel each,
  // above).
  glare::PsfWeights halo;
  halo.halo = 1.0;
  in_frame_.push_back(one_channel_if_grey(in_frame_share(source, glare::same_in_every_channel(halo))));
}

cv::Mat GlareStage::in_frame_source() const {
  const auto frame_ones = [&] {
    return retina::filled_in_parallel({plan_.width, plan_.height}, CV_32FC3, cv::Scalar::all(1.0));
  };
  if (plane_->identity()) return frame_ones();
  // The glare frame's ones are ones exactly when it is the frame or an
  // even-sized frame halved ((0 + (1 + 1 + 1 + 1)) x 0.25,
  // halve_frame.hpp): then their flux comes from the plane's own weights
  // (FrameProjection::flux_of_ones), the same bytes without a frame-sized
  // image (25 MB at 1080p, each page's first touch a cost) or its pass.
  // Odd sizes halve with other weights at their last row and column.
  const bool exact = halved_.empty() || (plan_.width % 2 == 0 && plan_.height % 2 == 0);
  return exact ? plane_->flux_of_ones() : plane_->to_plane_flux(to_glare_frame(frame_ones()));
}

std::optional<double> GlareStage::veil_at(const cv::Mat& luminance, double adaptation_log, double pupil_mm, double x,
                                          double y, double exclusion_deg) const {
  if (plan_.glare.gaussian || kernels_.core.empty()) return std::nullopt;
  const glare::PsfWeights w = optics_.weights(adaptation_log, pupil_mm);
  const double exclusion_px = exclusion_deg * ppd_;
  const FrameProjection& p = *plane_;
  if (p.identity()) return glare::veiling_luminance(luminance, kernels_, w, x, y, exclusion_px);
  // On the angle plane (each pixel's luminance times its solid angle),
  // between the four plane pixels around the point, as the picture is.
  const cv::Mat frame = to_glare_frame(luminance);
  const cv::Point2d at = p.to_plane({x * frame.cols / luminance.cols, y * frame.rows / luminance.rows});
  return glare::veiling_luminance_between(p.to_plane_flux(frame), kernels_, w, at.x, at.y, exclusion_px);
}

cv::Mat GlareStage::to_glare_frame(const cv::Mat& frame) const {
  if (halved_.empty() || frame.size() == halved_) return frame;
  cv::Mat out;
  retina::halve_frame(frame, out);
  CV_Assert(out.size() == halved_);
  return out;
}

cv::Vec3f GlareStage::kept_share(const glare::PsfWeights& w) const {
  const cv::Vec3d k = w.core * centre_[0] + w.inner * centre_[1] + w.outer * centre_[2] + w.halo * centre_[3];
  return plan_.glare.gaussian ? cv::Vec3f::all(float(centre_[0][0])) : cv::Vec3f(float(k[0]), float(k[1]), float(k[2]));
}

cv::Mat GlareStage::in_frame_share(const cv::Mat& source, const glare::ChannelWeights& w) const {
  return plane_->identity() ? spread_plane(source, w) : moved_light_of_flux(source, w);
}

cv::Mat GlareStage::moved_light(const cv::Mat& rgb, const glare::ChannelWeights& w,
                                const FrameProjection::RowFinish& finish) const {
  return moved_light_of_flux(plane_->to_plane_flux(to_glare_frame(rgb)), w, finish);
}

cv::Mat GlareStage::moved_light_of_flux(cv::Mat flux, const glare::ChannelWeights& w,
                                        const FrameProjection::RowFinish& finish) const {
  const FrameProjection& p = *plane_;
  cv::Mat scattered = spread_plane(flux, w);
  if (plan_.glare.gaussian) {  // a blur keeps its centre: take it out (the same share whatever the weights)
    const cv::Vec3f kept = kept_share(w[0]);
    cv::Mat centre;
    cv::multiply(flux, cv::Scalar(kept[0], kept[1], kept[2]), centre);
    scattered -= centre;
    scattered = cv::max(scattered, 0.0);
  }
  flux.release();  // one plane fewer held while the frame image is made
  cv::Mat out;
  p.to_frame_image(scattered, out, finish);
  return out;
}

cv::Mat GlareStage::spread(const cv::Mat& rgb, const glare::PsfWeights& w, double surround) const {
  if (plane_->identity()) {
    cv::Mat out = spread_plane(rgb, glare::same_in_every_channel(w));
    add_surround(out, w, surround);
    return out;
  }
  // The plane carries the light that leaves its pixel; the light the PSF
  // keeps there stays on the frame's pixels, sharp. The moved light (and
  // the surround's, which is as smooth) comes back to the frame's size in
  // the same sweep that adds the kept light: the back-projection's own
  // when the glare frame is the frame, else the enlargement's.
  const cv::Vec3f kept = kept_share(w);
  const FrameProjection::RowFinish surround_row = surround_rows(w, surround);
  if (halved_.empty())
    return moved_light(rgb, glare::same_in_every_channel(w), [&](int y, float* row) {
      if (surround_row) surround_row(y, row);
      add_kept(rgb.ptr<float>(y), kept, row, rgb.cols);
    });
  cv::Mat moved = moved_light(rgb, glare::same_in_every_channel(w), surround_row);
  CV_Assert(moved.size() == halved_ && up_cols_ && up_rows_ && rgb.cols == int(up_cols_->w.size()) &&
            rgb.rows == int(up_rows_->w.size()));
  cv::Mat out(rgb.size(), CV_32FC3);
  const retina::BilinearAxis& down = *up_rows_;
  cv::parallel_for_(cv::Range(0, out.rows), [&](const cv::Range& range) {
    retina::EnlargedRows widened(moved, *up_cols_, out.cols);  // each halved row widened once per stripe
    for (int y = range.start; y < range.end; ++y) {
      const size_t iy = size_t(y);
      const float* a = widened.row(down.lo[iy]);
      const float* b = widened.row(down.hi[iy]);
      add_kept_row(a, b, down.w[iy], rgb.ptr<float>(y), kept, out.ptr<float>(y), out.cols);
    }
  }, double(std::max(1, cv::getNumThreads()) * 4));
  return out;
}

cv::Mat GlareStage::spread_plane(const cv::Mat& rgb, const glare::ChannelWeights& w) const {
  if (plan_.glare.gaussian) {
    // Yoshida et al. 2008: a Gaussian of sigma 0.34 deg; light leaving the frame is lost.
    const double sigma = plan_.glare.gaussian_sigma_deg * ppd_;
    cv::Mat out;
    cv::GaussianBlur(rgb, out, cv::Size(0, 0), sigma, sigma, cv::BORDER_CONSTANT);
    return out;
  }
  return split_ ? split_->convolve(rgb, w) : convolver_->convolve(rgb, w);
}

void GlareStage::add_surround(cv::Mat& light, const glare::PsfWeights& w, double surround) const {
  const FrameProjection::RowFinish row = surround_rows(w, surround);
  if (!row) return;
  CV_Assert(light.type() == CV_32FC3 && light.size() == in_frame_[0].size());
  cv::parallel_for_(cv::Range(0, light.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) row(y, light.ptr<float>(y));
  });
}

FrameProjection::RowFinish GlareStage::surround_rows(const glare::PsfWeights& w, double surround) const {
  if (!(surround > 0.0) || in_frame_.empty()) return {};
  CV_Assert(in_frame_.size() <= (triple_ ? 2 : 4));
  // Each finished row is a frame row: the maps must be frame-sized.
  for (const cv::Mat& m : in_frame_)
    CV_Assert(m.depth() == CV_32F && m.isContinuous() && m.size() == plane_->frame_size());
  const float s = float(surround);
  const std::array<float, 4> weights = {float(w.core), float(w.inner), float(w.outer), float(w.halo)};
  // The maps hold the moved light only when the kept light is added later.
  const cv::Vec3f kept = plane_->identity() ? cv::Vec3f(0, 0, 0) : kept_share(w);
  return [this, s, weights, kept](int y, float* row) {
    SurroundShares shares;
    const size_t first = triple_ ? 1 : 0;
    if (triple_) shares.triple = in_frame_[0].ptr<float>(y);
    shares.count = in_frame_.size() - first;
    for (size_t c = 0; c < shares.count; ++c)
      shares.maps[c] = in_frame_[first + c].ptr<float>(y), shares.strides[c] = in_frame_[first + c].channels();
    add_surround_row(shares, weights, kept, s, row, in_frame_[0].cols);
  };
}

bool GlareStage::Cache::seen(const FrameDigest& rgb, const glare::PsfWeights& w, double s) const {
  return rgb == scene && w.core == weights.core && w.inner == weights.inner && w.outer == weights.outer &&
         w.halo == weights.halo && s == surround;
}

bool GlareStage::Cache::matches(const FrameDigest& rgb, const glare::PsfWeights& w, double s) const {
  return !retinal.empty() && seen(rgb, w, s);
}

void GlareStage::Cache::keep(const FrameDigest& rgb, const glare::PsfWeights& w, double s, const cv::Mat& out) {
  const bool again = rgb == scene;  // the frame itself: the optics may still be settling
  scene = rgb;
  weights = w;
  surround = s;
  retinal = again ? out : cv::Mat();
}

cv::Mat GlareStage::with_wave_lines(const cv::Mat& light, const glare::PsfWeights& w, double pupil_mm, cv::Mat retinal,
                                    bool shared) {
  if (!wave_) return retinal;
  cv::Mat out;  // a new image when the cache holds the smooth glare, else in place
  if (!shared) out = retinal;
  return wave_->add(light, w, pupil_mm, moment_.time_s, moment_.gaze, retinal, out) ? out : retinal;
}

cv::Mat GlareStage::apply(const cv::Mat& rgb, double adaptation_log, double surround, double pupil_mm,
                          bool* ran, bool* reused, const FrameDigest* given) {
  if (reused) *reused = false;
  // The optics' inputs are quantised (1e-4 log10 units, 1e-3 mm: weight
  // changes below 1e-5), so a still frame reuses its glare until they move,
  // and a run resumed from a checkpoint computes exactly what it reused.
  const double a = std::round(adaptation_log * 1e4) / 1e4;
  const glare::PsfWeights w =
      pupil_mm > 0.0 ? optics_.weights(a, std::round(pupil_mm * 1e3) / 1e3) : optics_.weights(a);
  if (wave_ && !(pupil_mm > 0.0)) pupil_mm = optics_.pupil_mm(a);  // the lines follow the pupil
  if (plan_.glare.full) {
    // A uniform field (and surround) comes back as it is, within
    // kUniformTolerance; a frame and optics equal to the last ones give the
    // last result.
    const bool uniform = glare::is_uniform_field(rgb, surround, kUniformTolerance);
    if (plan_.skip && uniform) {
      if (ran) *ran = false;
      return rgb;
    }
    CV_Assert(!given || (given->rows == rgb.rows && given->cols == rgb.cols && given->type == rgb.type()));
    const FrameDigest digest = plan_.skip ? (given ? *given : frame_digest(rgb)) : FrameDigest();
    if (plan_.skip && cache_.matches(digest, w, surround)) {
      if (ran) *ran = false;
      if (reused) *reused = true;
      return with_wave_lines(rgb, w, pupil_mm, cache_.retinal, true);
    }
    if (ran) *ran = true;
    cache_.retinal.release();  // not this frame's: no need to hold it through the spread
    cv::Mat out = spread(rgb, w, surround);
    if (plan_.skip) cache_.keep(digest, w, surround, out);
    return with_wave_lines(rgb, w, pupil_mm, out, plan_.skip && cache_.retinal.data == out.data);
  }
  // The excess over the display peak, with the pixel's colour (Spencer et
  // al. 1995 sec. 3.2; Yoshida et al. 2008): dL = max(L - L_dmax, 0),
  // spread, added back.
  const float peak = float(plan_.glare.display_peak_cd_m2);
  cv::Mat excess(rgb.size(), CV_32FC3), kept(rgb.size(), CV_32FC3);
  std::vector<unsigned char> row_has(size_t(rgb.rows), 0);
  cv::parallel_for_(cv::Range(0, rgb.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      const cv::Vec3f* in = rgb.ptr<cv::Vec3f>(y);
      cv::Vec3f* e = excess.ptr<cv::Vec3f>(y);
      cv::Vec3f* k = kept.ptr<cv::Vec3f>(y);
      for (int x = 0; x < rgb.cols; ++x) {
        const float l = retina::photopic_luminance(in[x]);
        const float share = l > peak ? (l - peak) / l : 0.0f;
        e[x] = in[x] * share;
        k[x] = in[x] - e[x];
        row_has[size_t(y)] |= share > 0.0f;
      }
    }
  });
  const bool any = std::any_of(row_has.begin(), row_has.end(), [](unsigned char v) { return v != 0; });
  if (ran) *ran = any;
  if (!any && plan_.skip) return rgb;
  if (ran) *ran = true;
  return with_wave_lines(excess, w, pupil_mm, kept + spread(excess, w), false);
}

}  // namespace eyestream::pipeline
