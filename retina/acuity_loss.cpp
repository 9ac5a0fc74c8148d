#include "retina/acuity_loss.hpp"

#include "retina/acuity_curve.hpp"
#include "retina/bilinear_axis.hpp"
#include "retina/gaussian_blur.hpp"
#include "retina/halve_frame.hpp"
#include "retina/bilinear_rows.hpp"
#include "retina/enlarged_rows.hpp"
#include "retina/vector_clones.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <memory>
#include <optional>
#include <opencv2/imgproc.hpp>

namespace eyestream::retina {

AcuityLoss::AcuityLoss(const AcuityParams& p, double pixels_per_degree, std::uint64_t seed, double bottom_log,
                       double top_log)
    : params_(p), seed_(seed) {
  CV_Assert(p.bands >= 1 && p.bands <= 31);  // apply() marks a row's levels by bits of 32
  // Bands needing more than the eye's limit at 10^0.75 = 5.6 cd/m^2 (42
  // c/deg; the limit rises only to 44 c/deg at 10 cd/m^2, under one octave
  // step) share the threshold of that level.
  const double finest_cpd = acuity_limit_cpd(0.75);
  for (int i = 0; i < p.bands; ++i) {
    const double sigma_deg = p.sigma0_arcmin * std::pow(2.0, i) / 60.0;
    sigmas_px_.push_back(sigma_deg * pixels_per_degree);
    const double needed = std::min(p.band_margin * gaussian_cutoff_cpd(sigma_deg), finest_cpd);
    tau_.push_back((acuity_log_luminance(needed) - bottom_log) / (top_log - bottom_log));
    // apply() relies on it: a coarser band never needs more light.
    CV_Assert(i == 0 || tau_[size_t(i)] <= tau_[size_t(i) - 1]);
  }
  noise_.cell_px = std::max(1.0, p.noise_cell_deg * pixels_per_degree);
  noise_.period_s = p.noise_period_s;
  noise_.clip = p.noise_clip;
}

namespace {

// The noise's share at rho: whole through the mesopic range, fading to
// nothing across the first decade of photopic light (rho 1 to 1.5).
double noise_share(double rho) { return std::clamp((1.5 - rho) / 0.5, 0.0, 1.0); }

// k_row[x] = the first i with level[x] > tau[i] (n when none). The
// thresholds fall with i, so the bands not kept are a prefix and k counts
// them: vectorised over the row, one threshold at a time. Returns the
// row's largest k.
EYESTREAM_VECTOR_CLONES
std::uint8_t first_kept_row(const float* level, const std::vector<float>& tau, std::uint8_t* k_row, int cols) {
  std::fill(k_row, k_row + cols, std::uint8_t(0));
  for (const float t : tau)
    for (int x = 0; x < cols; ++x) k_row[x] = std::uint8_t(k_row[x] + !(level[x] > t));
  std::uint8_t deepest = 0;
  for (int x = 0; x < cols; ++x) deepest = std::max(deepest, k_row[x]);
  return deepest;
}

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "run_end reads the first differing byte as the lowest");

// The end of the run of equal levels that starts at x: the first e > x
// with k_row[e] != k_row[x] (cols when none), eight bytes at a time.
int run_end(const std::uint8_t* k_row, int x, int cols) {
  const std::uint64_t k = std::uint64_t(k_row[x]) * 0x0101010101010101ull;
  int e = x + 1;
  for (; e + 8 <= cols; e += 8) {
    std::uint64_t bytes;
    std::memcpy(&bytes, k_row + e, 8);
    if (const std::uint64_t differ = bytes ^ k) return e + __builtin_ctzll(differ) / 8;  // little-endian
  }
  while (e < cols && k_row[e] == k_row[x]) ++e;
  return e;
}

// Calls take(x0, x1, k) for each run [x0, x1) of a row's pixels that
// take one level k, left to right.
template <typename Take>
void for_each_run(const std::uint8_t* k_row, int cols, Take take) {
  for (int x = 0; x < cols;) {
    const int e = run_end(k_row, x, cols);
    take(x, e, int(k_row[x]));
    x = e;
  }
}

// A reduced level map read at a frame's pixels a row at a time,
// bilinearly with cv::resize INTER_LINEAR's geometry (the map's pixels
// spread evenly over the frame): its two rows blended down, then the
// blend across.
class LevelRows {
 public:
  LevelRows(const cv::Mat& level, cv::Size frame)
      : level_(level),
        across_(frame.width, level.cols, float(level.cols) / float(frame.width)),
        down_(frame.height, level.rows, float(level.rows) / float(frame.height)) {}
  // Frame row y into `out` (frame width), through `down` (map width).
  void row(int y, float* down, float* out) const {
    const size_t iy = size_t(y);
    blend_rows(level_.ptr<float>(down_.lo[iy]), level_.ptr<float>(down_.hi[iy]), down_.w[iy], down, level_.cols);
    enlarge_row(down, across_, out, int(across_.lo.size()));
  }

 private:
  const cv::Mat& level_;
  BilinearAxis across_, down_;
};

}  // namespace

cv::Mat enlarged_level(const cv::Mat& level, cv::Size frame) {
  CV_Assert(level.type() == CV_32F && !level.empty());
  if (level.size() == frame) return level.clone();
  const LevelRows rows(level, frame);
  cv::Mat out(frame, CV_32F);
  std::vector<float> down(size_t(level.cols));
  for (int y = 0; y < frame.height; ++y) rows.row(y, down.data(), out.ptr<float>(y));
  return out;
}

double AcuityLoss::rho_all_kept() const {
  // The lowest rho whose lowest possible level, rho - g clip share(rho),
  // clears every threshold (the level rises with rho).
  const double tau = *std::max_element(tau_.begin(), tau_.end());
  const auto lowest = [&](double rho) { return rho - params_.noise_gain * params_.noise_clip * noise_share(rho); };
  double lo = tau, hi = tau + params_.noise_gain * params_.noise_clip;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (lowest(mid) > tau ? hi : lo) = mid;
  }
  return hi;
}

int AcuityLoss::level_factor(cv::Size frame) const {
  const double sigma = sigmas_px_.back();
  int f = 1;
  while (params_.pyramid_from_px > 0 && sigma >= params_.pyramid_from_px && sigma / (2 * f) >= 3.0 &&
         frame.width / (2 * f) >= 8 && frame.height / (2 * f) >= 8)
    f *= 2;
  return f;
}

cv::Mat AcuityLoss::level(const cv::Mat& rho, double t_s, double gaze_x, double gaze_y, int factor) const {
  // The reduced map's pixel centres are the frame's at (X + 0.5) factor:
  // the noise's cell and origin scale with it.
  SmoothNoiseParams noise = noise_;
  noise.cell_px /= factor;
  cv::Mat x = smooth_noise(rho.size(), t_s, noise, seed_, RandomStream::kAcuity, {gaze_x / factor, gaze_y / factor});
  // Jacobs et al. 2015 eq. 15: rho + g X, the noise fading out above rho = 1.
  cv::Mat level(rho.size(), CV_32F);
  const float g = float(params_.noise_gain);
  for (int y = 0; y < rho.rows; ++y) {
    const float* r = rho.ptr<float>(y);
    const float* n = x.ptr<float>(y);
    float* o = level.ptr<float>(y);
    for (int i = 0; i < rho.cols; ++i) o[i] = r[i] + g * n[i] * float(noise_share(r[i]));
  }
  return level;
}

cv::Mat acuity_lowpass(const cv::Mat& src, double sigma, int f) {
  cv::Mat out;
  if (f == 1) {
    gaussian_blur(src, out, sigma);
    return out;
  }
  cv::resize(src, out, cv::Size((src.cols + f - 1) / f, (src.rows + f - 1) / f), 0, 0, cv::INTER_AREA);
  // The box reduction and the bilinear enlargement blur by about f^2/12 and
  // f^2/6 px^2 of variance themselves: the reduced blur supplies the rest.
  const double s = std::sqrt(std::max(sigma * sigma - f * f / 4.0, 1.0)) / f;
  gaussian_blur(out, out, s);
  return out;
}

void AcuityLoss::apply(cv::Mat& image, const cv::Mat& level) const {
  CV_Assert(image.type() == CV_32FC3 && level.type() == CV_32F && !level.empty());
  // At the image's size, or reduced by a power of two (as level_factor()).
  const auto reduced_by = [&](int f) {
    return level.cols == (image.cols + f - 1) / f && level.rows == (image.rows + f - 1) / f;
  };
  int by = 1;
  while (!reduced_by(by) && by < image.cols + image.rows) by *= 2;
  CV_Assert(reduced_by(by));
  // Blur levels L_i of sigma_i (L_0 the image); band i = L_(i-1) - L_i is
  // kept where level > tau_i (Jacobs et al. 2015 eq. 14):
  //   out = L_n + sum_i [level > tau_i] (L_(i-1) - L_i).
  // The thresholds fall with i (coarser bands need less light), so the kept
  // bands are those from the first kept one, k, on, and the sum is L_k: each
  // pixel takes one level. A level of sigma_i >= pyramid_from_px is held
  // reduced by a power of two f (sigma_i / f >= pyramid_from_px / 2) and
  // read bilinearly; its blur counts what the reductions (f^2 / 4 px^2 per
  // halving) and the bilinear read (f^2 / 6) add, so every level's variance
  // stays sigma_i^2.
  const std::vector<float> tau(tau_.begin(), tau_.end());
  // The first kept band of each pixel (n: none kept), and the coarsest any
  // pixel takes: levels beyond it are not made.
  cv::Mat first(image.size(), CV_8U);
  std::vector<std::uint8_t> row_deepest(size_t(image.rows), 0);
  const bool reduced = level.size() != image.size();
  const std::optional<LevelRows> level_rows =
      reduced ? std::make_optional<LevelRows>(level, image.size()) : std::nullopt;
  cv::parallel_for_(
      cv::Range(0, image.rows),
      [&](const cv::Range& rows) {
        std::vector<float> down(reduced ? size_t(level.cols) : 0), full(reduced ? size_t(image.cols) : 0);
        for (int y = rows.start; y < rows.end; ++y) {
          const float* lv = reduced ? full.data() : level.ptr<float>(y);
          if (reduced) level_rows->row(y, down.data(), full.data());
          row_deepest[size_t(y)] = first_kept_row(lv, tau, first.ptr<std::uint8_t>(y), image.cols);
        }
      },
      double(std::max(1, cv::getNumThreads()) * 4));  // stripes of rows, each with its two rows' buffers
  const int deepest = *std::max_element(row_deepest.begin(), row_deepest.end());
  if (deepest == 0) return;
  // The levels are made one from the last. A full-resolution level is
  // written to its pixels as soon as the next level is made (the image,
  // level 0, is the first level's source only), so two full-frame levels
  // are held at a time, not every one (100 MB at 1080p in `balanced`);
  // the reduced levels, a quarter of the frame or less, are kept and read
  // bilinearly in one last pass. A level that is a copy of the last shares
  // its buffer; writing a level into the image where it is the image
  // itself leaves the pixels as they were.
  std::vector<cv::Mat> kept(size_t(deepest) + 1);
  std::vector<int> factor(size_t(deepest) + 1, 1);
  cv::Mat last = image;
  int f = 1;
  double variance = 0.0;  // of the stored level, full-resolution px^2
  // Whether level i is held reduced once more than the last.
  const auto halves = [&](int i, int f_now, cv::Size at) {
    return params_.pyramid_from_px > 0 && sigmas_px_[size_t(i - 1)] / (2 * f_now) >= params_.pyramid_from_px / 2 &&
           at.width >= 16 && at.height >= 16;
  };
  int last_k = 0;  // the level `last` holds
  for (int i = 1; i <= deepest; ++i) {
    const double sigma = sigmas_px_[size_t(i - 1)];
    cv::Mat from = last;
    const bool halving = halves(i, f, from.size());
    // A level no pixel can take (band i shares the threshold of band
    // i - 1, so no level lies between them), followed by one at the same
    // resolution, is not made: the next level's blur supplies its variance
    // too, from the last level made (one sweep instead of two). Which
    // levels these are depends on the thresholds alone, never on the
    // frame, so each level is the same blur of the image in every frame.
    // A level halved next is made, so that the reduction reads a blurred
    // image.
    if (!halving && i < deepest && !(tau_[size_t(i)] < tau_[size_t(i - 1)]) && !halves(i + 1, f, from.size())) {
      factor[size_t(i)] = f;
      continue;
    }
    if (halving) {
      cv::Mat reduced;
      halve_frame(from, reduced);
      variance += f * f / 4.0;
      f *= 2;
      from = reduced;
    }
    factor[size_t(i)] = f;
    const double target = sigma * sigma - (f > 1 ? f * f / 6.0 : 0.0);
    const double extra = std::sqrt(std::max(target - variance, 0.0)) / f;  // at the level's own resolution
    // A blur under 0.19 px gives its neighbours a weight under 1e-6
    // (exp(-1 / (2 0.19^2))): a copy, its variance left to the next level.
    cv::Mat made;
    // The last level, when full-resolution and not the image itself, is
    // written to its pixels row by row as this level's blur reads it.
    const bool write_last = last_k > 0 && factor[size_t(last_k)] == 1 && last.data != image.data;
    bool written = false;
    if (extra < 0.19) {
      made = from;
    } else {
      std::function<void(int)> write_row;
      if (write_last && from.data == last.data) {
        write_row = [&](int y) { write_full_row(image, first, row_deepest, last_k, last, y); };
        written = true;
      }
      gaussian_blur(from, made, extra, write_row);
      variance = std::max(variance, target);
    }
    if (write_last && !written)
      write_full_level(image, first, row_deepest, last_k, last);
    else if (last_k > 0 && factor[size_t(last_k)] != 1)
      kept[size_t(last_k)] = last;
    last = made;
    last_k = i;
  }
  kept[size_t(deepest)] = last;
  // The kept levels' pixels; a full-resolution one (the deepest only) is
  // copied, a reduced one read bilinearly, per column and per row.
  std::vector<std::unique_ptr<BilinearAxis>> across(size_t(deepest) + 1), down(size_t(deepest) + 1);
  for (int i = 1; i <= deepest; ++i)
    if (!kept[size_t(i)].empty() && factor[size_t(i)] > 1) {
      across[size_t(i)] = std::make_unique<BilinearAxis>(image.cols, kept[size_t(i)].cols, 1.0f / float(factor[size_t(i)]));
      down[size_t(i)] = std::make_unique<BilinearAxis>(image.rows, kept[size_t(i)].rows, 1.0f / float(factor[size_t(i)]));
    }
  // Row by row, run by run of pixels that take one level: a reduced one's
  // two rows enlarged across (each once per stripe, kept while the
  // stripe's rows read it) and blended down straight into the run's
  // pixels; the same products and sums, in the same order, as a blend of
  // four neighbours. Each pixel is written at most once, by its own level.
  cv::parallel_for_(
      cv::Range(0, image.rows),
      [&](const cv::Range& rows) {
        std::vector<std::optional<EnlargedRows>> enlarged(size_t(deepest) + 1);
        for (int y = rows.start; y < rows.end; ++y) {
          if (row_deepest[size_t(y)] == 0) continue;
          const std::uint8_t* k_row = first.ptr<std::uint8_t>(y);
          float* out = image.ptr<float>(y);
          for_each_run(k_row, image.cols, [&](int x, int e, int k) {
            const cv::Mat& m = kept[size_t(k)];
            // Level 0 (the image), a level written already, or the image
            // itself (every level a copy): nothing to write.
            if (k == 0 || m.empty() || m.data == image.data) return;
            if (factor[size_t(k)] == 1) {
              std::memcpy(out + 3 * x, m.ptr<float>(y) + 3 * x, sizeof(float) * 3 * size_t(e - x));
              return;
            }
            if (!enlarged[size_t(k)]) enlarged[size_t(k)].emplace(m, *across[size_t(k)], image.cols);
            const BilinearAxis& ay = *down[size_t(k)];
            const float* upper = enlarged[size_t(k)]->row(ay.lo[size_t(y)]);
            const float* lower = enlarged[size_t(k)]->row(ay.hi[size_t(y)]);
            blend_rows(upper + 3 * x, lower + 3 * x, ay.w[size_t(y)], out + 3 * x, 3 * (e - x));
          });
        }
      },
      double(std::max(1, cv::getNumThreads()) * 4));  // stripes of rows, each enlarging a level's row once
}

void AcuityLoss::write_full_row(cv::Mat& image, const cv::Mat& first, const std::vector<std::uint8_t>& row_deepest,
                                int k, const cv::Mat& level, int y) {
  if (row_deepest[size_t(y)] < k) return;
  const float* from = level.ptr<float>(y);
  float* out = image.ptr<float>(y);
  for_each_run(first.ptr<std::uint8_t>(y), image.cols, [&](int x0, int x1, int run_k) {
    if (run_k == k) std::memcpy(out + 3 * x0, from + 3 * x0, sizeof(float) * 3 * size_t(x1 - x0));
  });
}

void AcuityLoss::write_full_level(cv::Mat& image, const cv::Mat& first, const std::vector<std::uint8_t>& row_deepest,
                                  int k, const cv::Mat& level) {
  cv::parallel_for_(cv::Range(0, image.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) write_full_row(image, first, row_deepest, k, level, y);
  });
}

}  // namespace eyestream::retina
