#include "retina/retina_state.hpp"

#include "retina/afterimage_row.hpp"
#include "retina/cone_step_row.hpp"
#include "retina/diffusion.hpp"
#include "retina/parallel_fill.hpp"
#include "retina/pow_table.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace eyestream::retina {

namespace {

template <typename T>
using Px = cv::Vec<T, 3>;

template <typename T>
T stimulus(T v) {
  return (std::isfinite(v) && v > T(0)) ? v : T(0);
}

// Equilibrium bleaching B_inf and response R of each site for a stimulus.
template <typename T>
void equilibrium(const cv::Mat& lms, const ToneCurve& curve, const PhotoreceptorParams& p, cv::Mat& b_inf,
                 cv::Mat& response) {
  b_inf.create(lms.size(), lms.type());
  response.create(lms.size(), lms.type());
  cv::parallel_for_(cv::Range(0, lms.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      const Px<T>* s = lms.ptr<Px<T>>(y);
      Px<T>* b = b_inf.ptr<Px<T>>(y);
      Px<T>* r = response.ptr<Px<T>>(y);
      for (int x = 0; x < lms.cols; ++x)
        for (int c = 0; c < 3; ++c) {
          const T i = stimulus(s[x][c]);
          // Jacobs et al. 2015 eqs. 6 and 1.
          b[x][c] = bleach_equilibrium<T>(i, T(p.bleach_rate[c]), T(p.regen_rate_per_s[c]));
          r[x][c] = T(curve.response(float(i)));
        }
    }
  });
}

// One time step of every site in double (reference precision; float
// steps by step_sites_float), with the equilibrium it relaxes toward
// (b_inf, response) written on the way: one sweep.
void step_sites(const cv::Mat& lms, const ToneCurve& curve, const PhotoreceptorParams& p, double c_max, double dt,
                cv::Mat& b_inf, cv::Mat& response, cv::Mat& bleached, cv::Mat& deficit) {
  b_inf.create(lms.size(), lms.type());
  response.create(lms.size(), lms.type());
  const double decay = std::exp(-p.calcium_efflux_per_s * dt);
  cv::parallel_for_(cv::Range(0, lms.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      const Px<double>* s = lms.ptr<Px<double>>(y);
      Px<double>* rest = b_inf.ptr<Px<double>>(y);
      Px<double>* r = response.ptr<Px<double>>(y);
      Px<double>* b = bleached.ptr<Px<double>>(y);
      Px<double>* d = deficit.ptr<Px<double>>(y);
      Px<double> b_in, d_in;  // the state the last computed site started from
      for (int x = 0; x < lms.cols; ++x) {
        // A site with the stimulus and state of the one before it (the
        // uniform surround most of the grid sees) takes its results: the
        // same inputs give the same bytes.
        if (x > 0 && s[x] == s[x - 1] && b[x] == b_in && d[x] == d_in) {
          rest[x] = rest[x - 1];
          r[x] = r[x - 1];
          b[x] = b[x - 1];
          d[x] = d[x - 1];
          continue;
        }
        b_in = b[x];
        d_in = d[x];
        for (int c = 0; c < 3; ++c) {
          const double i = stimulus(s[x][c]);
          // Jacobs et al. 2015 eqs. 6 and 1.
          rest[x][c] = bleach_equilibrium<double>(i, p.bleach_rate[c], p.regen_rate_per_s[c]);
          r[x][c] = double(curve.response(float(i)));
          b[x][c] =
              std::clamp(bleach_step<double>(b[x][c], i, dt, p.bleach_rate[c], p.regen_rate_per_s[c]), 0.0, 1.0);
          const double d_inf = c_max * r[x][c];  // Jacobs et al. 2015 eq. 10 as a deficit
          d[x][c] = std::clamp((d[x][c] - d_inf) * decay + d_inf, 0.0, c_max);  // Jacobs et al. 2015 eq. 9
        }
      }
    }
  });
}

// The same step in float, a row at a time by cone_step_row.hpp's vector
// loops (there every site is computed: no test against its neighbour).
void step_sites_float(const cv::Mat& lms, const ToneCurve& curve, const PhotoreceptorParams& p, double c_max,
                      double dt, cv::Mat& b_inf, cv::Mat& response, cv::Mat& bleached, cv::Mat& deficit) {
  b_inf.create(lms.size(), lms.type());
  response.create(lms.size(), lms.type());
  ConeStep k;
  for (int c = 0; c < 3; ++c) {
    k.bleach_rate[c] = float(p.bleach_rate[c]);
    k.regen_rate[c] = float(p.regen_rate_per_s[c]);
  }
  k.dt = float(dt);
  k.calcium_decay = std::exp(-float(p.calcium_efflux_per_s) * float(dt));
  k.c_max = float(c_max);
  k.sigma = curve.sigma();
  k.power = &curve.power();
  cv::parallel_for_(cv::Range(0, lms.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y)
      step_cone_row(k, lms.ptr<float>(y), b_inf.ptr<float>(y), response.ptr<float>(y), bleached.ptr<float>(y),
                    deficit.ptr<float>(y), lms.cols);
  });
}

void afterimage_sites(const PhotoreceptorParams& p, double c_max, const AfterimageOptions& o, const cv::Mat& bleached,
                      const cv::Mat& deficit, const cv::Mat& bleached_rest, const cv::Mat& response,
                      const cv::Mat& visibility, AfterimageMaps& maps, bool with_maps) {
  if (with_maps) {
    maps.gain_excess.create(bleached.size(), CV_32FC3);
    maps.bleach.create(bleached.size(), CV_32FC3);
  }
  // alpha^j2 by table in float: 2e-7 relative (pow_table.hpp), far below
  // what a display shows of a gain.
  const PowTable& power = shared_pow_table(p.adaptation_strength);
  std::vector<float> row_largest(size_t(bleached.rows), 0.0f);
  cv::parallel_for_(cv::Range(0, bleached.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      float largest = 0.0f;
      const Px<double>* b = bleached.ptr<Px<double>>(y);
      const Px<double>* d = deficit.ptr<Px<double>>(y);
      const Px<double>* b_inf = bleached_rest.ptr<Px<double>>(y);
      const Px<double>* r = response.ptr<Px<double>>(y);
      const float* visible = visibility.ptr<float>(y);
      cv::Vec3f* gain = with_maps ? maps.gain_excess.ptr<cv::Vec3f>(y) : nullptr;
      cv::Vec3f* bleach = with_maps ? maps.bleach.ptr<cv::Vec3f>(y) : nullptr;
      for (int x = 0; x < bleached.cols; ++x)
        for (int c = 0; c < 3; ++c) {
          double g = 1.0, j = 0.0;
          if (o.local_adaptation)  // Jacobs et al. 2015 eqs. 11-12: alpha^j2
            g = power.any(float(local_gain<double>(d[x][c], r[x][c], c_max, p.gain_epsilon)));
          if (o.bleaching)  // Jacobs et al. 2015 eq. 12: j1 (C / C_max) max(B - B_inf, 0)
            j = p.bleaching_strength * (1.0 - double(d[x][c]) / c_max) * std::max(double(b[x][c] - b_inf[x][c]), 0.0);
          const float gain_xc = float(visible[x] * (g - 1.0)), bleach_xc = float(visible[x] * j);
          if (with_maps) {
            gain[x][c] = gain_xc;
            bleach[x][c] = bleach_xc;
          }
          largest = std::max({largest, std::abs(gain_xc), std::abs(bleach_xc)});
        }
      row_largest[size_t(y)] = largest;
    }
  });
  for (float v : row_largest) maps.largest = std::max(maps.largest, v);
}

// The same terms in float, a row at a time by afterimage_row.hpp's vector
// loops.
void afterimage_sites_float(const PhotoreceptorParams& p, double c_max, const AfterimageOptions& o,
                            const cv::Mat& bleached, const cv::Mat& deficit, const cv::Mat& bleached_rest,
                            const cv::Mat& response, const cv::Mat& visibility, AfterimageMaps& maps, bool with_maps) {
  if (with_maps) {
    maps.gain_excess.create(bleached.size(), CV_32FC3);
    maps.bleach.create(bleached.size(), CV_32FC3);
  }
  AfterimageTerms k;
  k.gain = o.local_adaptation;
  k.bleach = o.bleaching;
  k.c_max = c_max;
  k.epsilon = float(p.gain_epsilon);
  k.strength = p.bleaching_strength;
  k.power = &shared_pow_table(p.adaptation_strength);  // alpha^j2 by table: 2e-7 relative (pow_table.hpp)
  std::vector<float> row_largest(size_t(bleached.rows), 0.0f);
  cv::parallel_for_(cv::Range(0, bleached.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y)
      row_largest[size_t(y)] =
          afterimage_row(k, bleached.ptr<float>(y), deficit.ptr<float>(y), bleached_rest.ptr<float>(y),
                         response.ptr<float>(y), visibility.ptr<float>(y),
                         with_maps ? maps.gain_excess.ptr<float>(y) : nullptr,
                         with_maps ? maps.bleach.ptr<float>(y) : nullptr, bleached.cols);
  });
  for (float v : row_largest) maps.largest = std::max(maps.largest, v);
}

bool is_double(const cv::Mat& m) { return m.depth() == CV_64F; }

}  // namespace

RetinaState::RetinaState(cv::Size grid, const PhotoreceptorParams& params, bool double_precision)
    : params_(params), c_max_(params.calcium_influx_per_s / params.calcium_efflux_per_s) {
  const int type = double_precision ? CV_64FC3 : CV_32FC3;
  bleached_ = filled_in_parallel(grid, type, cv::Scalar::all(0.0));
  deficit_ = filled_in_parallel(grid, type, cv::Scalar::all(0.0));
}

void RetinaState::rest(const cv::Mat& lms, const ToneCurve& curve) {
  CV_Assert(lms.size() == bleached_.size() && lms.type() == bleached_.type());
  if (is_double(lms))
    equilibrium<double>(lms, curve, params_, bleached_rest_, response_);
  else
    equilibrium<float>(lms, curve, params_, bleached_rest_, response_);
  bleached_rest_.copyTo(bleached_);
  deficit_ = response_ * c_max_;
}

void RetinaState::step(const cv::Mat& lms, const ToneCurve& curve, double dt_s) {
  CV_Assert(lms.size() == bleached_.size() && lms.type() == bleached_.type());
  if (!(dt_s > 0)) {
    if (is_double(lms))
      equilibrium<double>(lms, curve, params_, bleached_rest_, response_);
    else
      equilibrium<float>(lms, curve, params_, bleached_rest_, response_);
    return;
  }
  if (is_double(lms))
    step_sites(lms, curve, params_, c_max_, dt_s, bleached_rest_, response_, bleached_, deficit_);
  else
    step_sites_float(lms, curve, params_, c_max_, dt_s, bleached_rest_, response_, bleached_, deficit_);
}

void RetinaState::release_rest() {
  bleached_rest_.release();
  response_.release();
}

RestOfStimulus RetinaState::rest_for(const cv::Mat& lms, const ToneCurve& curve) const {
  CV_Assert(lms.size() == bleached_.size() && lms.type() == bleached_.type());
  RestOfStimulus rest;
  if (is_double(lms))
    equilibrium<double>(lms, curve, params_, rest.bleached, rest.response);
  else
    equilibrium<float>(lms, curve, params_, rest.bleached, rest.response);
  return rest;
}

void RetinaState::recall_rest(const cv::Mat& lms, const ToneCurve& curve) {
  RestOfStimulus rest = rest_for(lms, curve);
  bleached_rest_ = rest.bleached;
  response_ = rest.response;
}

void RetinaState::soften(double variance_sites2) {
  if (!(variance_sites2 > 0.0)) return;
  CV_Assert(holds_rest());  // after step() and before release_rest(): not a silent no-op
  diffuse_departure(bleached_, bleached_rest_, 1.0, variance_sites2, 1.0);
  diffuse_departure(deficit_, response_, c_max_, variance_sites2, c_max_);
}

AfterimageMaps RetinaState::afterimages(const AfterimageOptions& options, const cv::Mat& visibility,
                                        std::optional<cv::Rect> within) const {
  return afterimage_terms(options, visibility, within, true);
}

float RetinaState::largest_afterimage(const AfterimageOptions& options, const cv::Mat& visibility) const {
  return afterimage_terms(options, visibility, std::nullopt, false).largest;
}

AfterimageMaps RetinaState::afterimage_terms(const AfterimageOptions& options, const cv::Mat& visibility,
                                             std::optional<cv::Rect> within, bool with_maps) const {
  CV_Assert(!response_.empty() && visibility.size() == bleached_.size() && visibility.type() == CV_32F);
  const cv::Rect grid(cv::Point(0, 0), bleached_.size());
  const cv::Rect region = within ? *within : grid;
  CV_Assert(!region.empty() && (region & grid) == region);
  AfterimageMaps maps;
  if (is_double(bleached_))
    afterimage_sites(params_, c_max_, options, bleached_(region), deficit_(region), bleached_rest_(region),
                             response_(region), visibility(region), maps, with_maps);
  else
    afterimage_sites_float(params_, c_max_, options, bleached_(region), deficit_(region), bleached_rest_(region),
                           response_(region), visibility(region), maps, with_maps);
  return maps;
}

cv::Mat RetinaState::calcium() const {
  cv::Mat c;
  cv::subtract(cv::Scalar::all(c_max_), deficit_, c);
  return c;
}

void RetinaState::restore(const std::vector<cv::Mat>& mats) {
  CV_Assert(mats.size() == 4 && mats[0].size() == bleached_.size() && mats[0].type() == bleached_.type());
  bleached_ = mats[0].clone();
  deficit_ = mats[1].clone();
  bleached_rest_ = mats[2].clone();
  response_ = mats[3].clone();
}

}  // namespace eyestream::retina
