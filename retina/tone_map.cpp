#include "retina/tone_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "retina/bit_masks.hpp"
#include "retina/luminance.hpp"
#include "retina/vector_clones.hpp"

namespace eyestream::retina {

void tone_map(const cv::Mat& rgb, const ToneCurve& curve, cv::Mat& out) {
  // Photopic: rho = 1, photopic weights, nothing of the tint.
  MesopicColour photopic;
  photopic.rho = 1.0f;
  photopic.scotopic_weights = cv::Vec3f(kPhotopicR, kPhotopicG, kPhotopicB);
  photopic.tint_ratio = cv::Vec3f(0, 0, 0);
  photopic.hue_shift = false;
  tone_map(rgb, curve, photopic, out);
}

namespace {

// What a row's pixels need: the photopic luminance Yp, the mesopic Ym and
// the tone curve's power argument (sigma / Ym or its inverse, whichever is
// at most 1; 1 for a pixel shown black).
EYESTREAM_VECTOR_CLONES
void luminances_row(const float* in, const float* rho, float w0, float w1, float w2, float sigma, float* yp_out,
                    float* ym_out, float* arg, int n) {
  for (int x = 0; x < n; ++x) {
    const float p0 = in[3 * x], p1 = in[3 * x + 1], p2 = in[3 * x + 2];
    const float yp = kPhotopicR * p0 + kPhotopicG * p1 + kPhotopicB * p2;
    const float ys = ((0.0f + w0 * p0) + w1 * p1) + w2 * p2;  // as cv::Vec::dot
    const float ym = rho[x] * yp + (1.0f - rho[x]) * ys;  // Purkinje: Jacobs et al. 2015 sec. 2.3.1
    const float ratio = sigma / ym;
    const bool shown = (yp > 0.0f) & (ym > 0.0f) & finite_bits(ym);
    arg[x] = pick(mask_if(shown), pick(mask_if(ratio <= 1.0f), ratio, 1.0f / ratio), 1.0f);
    yp_out[x] = yp;
    ym_out[x] = ym;
  }
}

// The colour back from the response R(Ym) (from q, the power of arg):
// rgb (share R / Yp) + tint_ratio (1 - rho) R (hue shift: Jacobs et al.
// 2015 sec. 2.3.2), share = rho with the hue shift, else 1.
EYESTREAM_VECTOR_CLONES
void colour_row(const float* in, const float* rho, const float* yp, const float* ym, const float* q, float sigma,
                float t0, float t1, float t2, bool hue_shift, float* out, int n) {
  for (int x = 0; x < n; ++x) {
    const float ratio = sigma / ym[x];
    const float r = pick(mask_if(ratio <= 1.0f), 1.0f / (1.0f + q[x]), q[x] / (q[x] + 1.0f));
    const bool shown = (yp[x] > 0.0f) & (ym[x] > 0.0f) & finite_bits(ym[x]);
    const std::uint32_t keep = mask_if(shown);
    const float dim = 1.0f - rho[x];
    const float share = pick(mask_if(hue_shift), rho[x], 1.0f);
    const float s = share * r / yp[x];
    out[3 * x] = pick(keep, in[3 * x] * s + (t0 * dim) * r, 0.0f);
    out[3 * x + 1] = pick(keep, in[3 * x + 1] * s + (t1 * dim) * r, 0.0f);
    out[3 * x + 2] = pick(keep, in[3 * x + 2] * s + (t2 * dim) * r, 0.0f);
  }
}

}  // namespace

void tone_map(const cv::Mat& rgb, const ToneCurve& curve, const MesopicColour& m, cv::Mat& out) {
  CV_Assert(rgb.type() == CV_32FC3);
  out.create(rgb.size(), CV_32FC3);
  CV_Assert(!m.rho_map || (m.rho_map->size() == rgb.size() && m.rho_map->type() == CV_32F));
  const cv::Vec3f tint = m.hue_shift ? m.tint_ratio : cv::Vec3f(0, 0, 0);
  const cv::Vec3f w = m.scotopic_weights;
  const int n = rgb.cols;
  cv::parallel_for_(cv::Range(0, rgb.rows), [&](const cv::Range& rows) {
    const size_t values = size_t(n);
    std::vector<float> constant_rho(m.rho_map ? 0 : values, m.rho), yp(values), ym(values), arg(values), q(values);
    for (int y = rows.start; y < rows.end; ++y) {
      const float* in = rgb.ptr<float>(y);
      const float* rho = m.rho_map ? m.rho_map->ptr<float>(y) : constant_rho.data();
      luminances_row(in, rho, w[0], w[1], w[2], curve.sigma(), yp.data(), ym.data(), arg.data(), n);
      curve.power().batch(arg.data(), q.data(), n);
      colour_row(in, rho, yp.data(), ym.data(), q.data(), curve.sigma(), tint[0], tint[1], tint[2], m.hue_shift,
                 out.ptr<float>(y), n);
    }
  }, double(std::max(1, cv::getNumThreads()) * 4));  // stripes of rows, each with its row buffers
}

}  // namespace eyestream::retina
