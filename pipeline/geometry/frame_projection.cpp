#include "pipeline/geometry/frame_projection.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <vector>
#include <opencv2/imgproc.hpp>

#include "io/error.hpp"
#include "pipeline/geometry/bilinear_splat.hpp"
#include "pipeline/geometry/remap_maps.hpp"
#include "retina/parallel_fill.hpp"

namespace eyestream::pipeline {

namespace {

constexpr double kDeg = M_PI / 180.0;

}  // namespace

Projection projection_from_name(const std::string& name) {
  if (name == "rectilinear") return Projection::rectilinear;
  if (name == "equidistant") return Projection::equidistant;
  throw UsageError("--projection must be rectilinear or equidistant, not '" + name + "'");
}

const char* projection_name(Projection p) { return p == Projection::rectilinear ? "rectilinear" : "equidistant"; }

struct FrameProjection::Carriage {
  std::once_flag made;
  cv::Mat positions;         // CV_32FC2, frame-sized
  cv::Mat remap1, remap2;    // positions as cv::remap's fixed-point maps
  cv::Mat flux_ratio;        // CV_32F, plane-sized: sin(theta) / theta
  cv::Mat flux_norm;         // CV_32F, plane-sized: flux_ratio over the sum of splat weights; 0 beyond the frame
  std::shared_ptr<const FixedSplat> flux_splat;  // the frame's pixels onto the plane, by fixed runs
};

FrameProjection::FrameProjection(int width, int height, double fov_deg, Projection kind, double scale)
    : kind_(kind), frame_(width, height), plane_(width, height), fov_deg_(fov_deg), scale_(scale),
      frame_ppd_(width / fov_deg), ppd_(width / fov_deg) {
  CV_Assert(scale > 0.0 && scale <= 1.0);
  if (identity()) return;
  if (kind == Projection::equidistant) {
    ppd_ = frame_ppd_ * scale;
    plane_ = cv::Size(int(std::ceil(width * scale)), int(std::ceil(height * scale)));
  } else {
    f_px_ = 0.5 * width / std::tan(0.5 * fov_deg * kDeg);
    fp_ = f_px_ * scale;
    frame_ppd_ = f_px_ * kDeg;
    ppd_ = fp_ * kDeg;
    plane_ = cv::Size(int(std::ceil(2.0 * fp_ * std::atan(0.5 * width / f_px_))),
                      int(std::ceil(2.0 * fp_ * std::atan(0.5 * height / f_px_))));
  }
  carriage_ = std::make_shared<Carriage>();
}

const FrameProjection::Carriage& FrameProjection::carriage() const {
  CV_Assert(carriage_);  // (the identity has none: nothing is carried)
  std::call_once(carriage_->made, [&] { make_carriage(*carriage_); });
  return *carriage_;
}

const cv::Mat& FrameProjection::plane_positions() const { return carriage().positions; }

void FrameProjection::make_carriage(Carriage& m) const {
  const int width = frame_.width, height = frame_.height;
  const Projection kind = kind_;
  m.positions.create(frame_, CV_32FC2);
  // A rectilinear frame's pixels mirrored about its centre share their
  // scale (radial_scale: X of column width - 1 - x is exactly -X of column
  // x, and likewise for rows), so it is computed for one quarter and
  // placed four times, each position as to_plane gives it.
  cv::parallel_for_(cv::Range(0, (height + 1) / 2), [&](const cv::Range& r) {
    for (int y = r.start; y < r.end; ++y)
      for (int x = 0; x < (width + 1) / 2; ++x) {
        const double s = kind == Projection::equidistant ? scale_
                                                         : radial_scale((x + 0.5) - 0.5 * width, (y + 0.5) - 0.5 * height);
        for (int py : {y, height - 1 - y})
          for (int px : {x, width - 1 - x}) {
            const double X = (px + 0.5) - 0.5 * width, Y = (py + 0.5) - 0.5 * height;
            const cv::Point2d q = kind == Projection::equidistant
                                      ? cv::Point2d(px + 0.5, py + 0.5) * scale_
                                      : cv::Point2d(0.5 * plane_.width + X * s, 0.5 * plane_.height + Y * s);
            m.positions.at<cv::Vec2f>(py, px) = cv::Vec2f(float(q.x), float(q.y));
          }
      }
  });
  remap_maps(m.positions, m.remap1, m.remap2);
  // Every pixel of these maps is independent of the others: computed by
  // rows in parallel, the same values whatever the split.
  // The same for each quarter of the plane's mirror images.
  m.flux_ratio.create(plane_, CV_32F);
  cv::parallel_for_(cv::Range(0, (plane_.height + 1) / 2), [&](const cv::Range& r) {
    for (int v = r.start; v < r.end; ++v)
      for (int u = 0; u < (plane_.width + 1) / 2; ++u) {
        const double theta = kind_ == Projection::equidistant
                                 ? 0.0  // angle-uniform: one solid angle per pixel, as the identity takes it
                                 : std::hypot(u + 0.5 - 0.5 * plane_.width, v + 0.5 - 0.5 * plane_.height) / fp_;
        const float ratio = float(theta > 0.0 ? std::sin(theta) / theta : 1.0);
        for (int pv : {v, plane_.height - 1 - v})
          for (int pu : {u, plane_.width - 1 - u}) m.flux_ratio.at<float>(pv, pu) = ratio;
      }
  });
  // The fixed splat and its normalisation (the sum of b over the frame
  // pixels landing on each plane pixel: the same every frame).
  m.flux_splat = std::make_shared<const FixedSplat>(m.positions, plane_);
  const cv::Mat weight = bilinear_splat(retina::filled_in_parallel(frame_, CV_32FC1, cv::Scalar(1.0)), m.positions,
                                        SplatAffine{1, 1, -0.5}, plane_, cv::Scalar(0.0),
                                        cv::Mat());  // 1 where covered, 0 beyond
  // The sums made in place of the normalisation, each read before it is
  // replaced (no plane-sized image beside it).
  m.flux_splat->weight_sums(m.flux_norm);
  cv::parallel_for_(cv::Range(0, plane_.height), [&](const cv::Range& r) {
    for (int v = r.start; v < r.end; ++v)
      for (int u = 0; u < plane_.width; ++u) {
        const float b = m.flux_norm.at<float>(v, u);
        m.flux_norm.at<float>(v, u) =
            weight.at<float>(v, u) > 0.0f && b > 0.0f ? m.flux_ratio.at<float>(v, u) / b : 0.0f;
      }
  });
}

cv::Size2d FrameProjection::retina_reach() const {
  if (kind_ == Projection::equidistant) return {frame_.width * scale_, frame_.height * scale_};
  // The largest offsets, across and down, of any frame point seen from any
  // gaze on the frame: both on its edge (the offsets grow outward), so
  // sampled densely along the edge for the gaze and for the point.
  std::vector<cv::Point2d> edge;
  constexpr int kPerSide = 96;
  for (int i = 0; i <= kPerSide; ++i) {
    const double u = double(i) / kPerSide;
    edge.push_back({u * frame_.width, 0.0});
    edge.push_back({u * frame_.width, double(frame_.height)});
    edge.push_back({0.0, u * frame_.height});
    edge.push_back({double(frame_.width), u * frame_.height});
  }
  // Each gaze's axes once for all its points; the gazes in parallel (a
  // largest value does not depend on the order it is found in).
  double across = 0.0, down = 0.0;
  std::mutex m;
  cv::parallel_for_(cv::Range(0, int(edge.size())), [&](const cv::Range& r) {
    double a = 0.0, d = 0.0;
    for (int g = r.start; g < r.end; ++g) {
      const GazeAxes axes = gaze_axes(edge[size_t(g)]);
      for (const cv::Point2d& p : edge) {
        const cv::Vec2d o = offset_from(axes, p);
        a = std::max(a, std::abs(o[0]));
        d = std::max(d, std::abs(o[1]));
      }
    }
    const std::lock_guard<std::mutex> lock(m);
    across = std::max(across, a);
    down = std::max(down, d);
  });
  return {across + 1.0, down + 1.0};  // a pixel's margin for the interpolation
}

FrameProjection::GazeAxes FrameProjection::gaze_axes(cv::Point2d gaze) const {
  GazeAxes g;
  g.ez = cv::normalize(cv::Vec3d(gaze.x - 0.5 * frame_.width, gaze.y - 0.5 * frame_.height, f_px_));
  g.ex = cv::normalize(cv::Vec3d(1, 0, 0) - g.ez[0] * g.ez);
  g.ey = g.ez.cross(g.ex);
  return g;
}

cv::Vec2d FrameProjection::gaze_offset(cv::Point2d gaze, cv::Point2d p) const {
  if (kind_ == Projection::equidistant) return {(p.x - gaze.x) * scale_, (p.y - gaze.y) * scale_};
  return offset_from(gaze_axes(gaze), p);
}

cv::Vec2d FrameProjection::offset_from(const GazeAxes& g, cv::Point2d p) const {
  const cv::Vec3d d(p.x - 0.5 * frame_.width, p.y - 0.5 * frame_.height, f_px_);
  const double a = d.dot(g.ex), b = d.dot(g.ey), c = d.dot(g.ez), s = std::hypot(a, b);
  const double k = s > 0.0 ? fp_ * std::atan2(s, c) / s : 0.0;
  return {k * a, k * b};
}

double FrameProjection::radial_scale(double X, double Y) const {
  const double r = std::hypot(X, Y);
  return r > 0.0 ? fp_ * std::atan(r / f_px_) / r : scale_;
}

cv::Point2d FrameProjection::to_plane(cv::Point2d p) const {
  if (identity()) return p;
  if (kind_ == Projection::equidistant) return p * scale_;
  const double X = p.x - 0.5 * frame_.width, Y = p.y - 0.5 * frame_.height, s = radial_scale(X, Y);
  return {0.5 * plane_.width + X * s, 0.5 * plane_.height + Y * s};
}

cv::Point2d FrameProjection::to_frame(cv::Point2d q) const {
  if (identity()) return q;
  if (kind_ == Projection::equidistant) return q / scale_;
  const double U = q.x - 0.5 * plane_.width, V = q.y - 0.5 * plane_.height, rho = std::hypot(U, V);
  const double theta = std::min(rho / fp_, 0.5 * M_PI - 1e-6);
  const double s = rho > 0.0 ? f_px_ * std::tan(theta) / rho : 1.0 / scale_;
  return {0.5 * frame_.width + U * s, 0.5 * frame_.height + V * s};
}

double FrameProjection::angle_deg(cv::Point2d a, cv::Point2d b) const {
  if (kind_ == Projection::equidistant) return std::hypot(a.x - b.x, a.y - b.y) / frame_ppd_;
  const auto direction = [&](cv::Point2d p) {
    return cv::Vec3d(p.x - 0.5 * frame_.width, p.y - 0.5 * frame_.height, f_px_) /
           std::sqrt(std::pow(p.x - 0.5 * frame_.width, 2) + std::pow(p.y - 0.5 * frame_.height, 2) + f_px_ * f_px_);
  };
  const cv::Vec3d da = direction(a), db = direction(b);
  return std::atan2(cv::norm(da.cross(db)), da.dot(db)) / kDeg;
}

cv::Vec2d FrameProjection::local_pixels_per_degree(cv::Point2d p) const {
  if (kind_ == Projection::equidistant) return {frame_ppd_, frame_ppd_};
  const double x = (p.x - 0.5 * frame_.width) / f_px_, y = (p.y - 0.5 * frame_.height) / f_px_;
  const double n2 = 1.0 + x * x + y * y;
  return {frame_ppd_ * n2 / std::sqrt(1.0 + y * y), frame_ppd_ * n2 / std::sqrt(1.0 + x * x)};
}

double FrameProjection::solid_angle_deg2() const {
  if (kind_ == Projection::equidistant) return (frame_.width / frame_ppd_) * (frame_.height / frame_ppd_);
  const double a = 0.5 * frame_.width / f_px_, b = 0.5 * frame_.height / f_px_;
  return 4.0 * std::atan(a * b / std::sqrt(1.0 + a * a + b * b)) / (kDeg * kDeg);
}

cv::Mat FrameProjection::solid_angle_weights() const {
  if (kind_ == Projection::equidistant) return retina::filled_in_parallel(frame_, CV_32F, cv::Scalar(1.0));
  cv::Mat w(frame_, CV_32F);  // every value written below
  // cos^3 of the angle off axis, (1 + X^2 + Y^2)^-1.5. A column's X and its
  // mirror's are exact negatives (halves and integers), and likewise for
  // rows, so each value is computed once for a quarter of the frame and
  // placed four times; the squares are each column's and row's own.
  const auto squares = [&](int n) {
    std::vector<double> s(size_t(n + 1) / 2);
    for (int i = 0; i < int(s.size()); ++i) {
      const double t = (i + 0.5 - 0.5 * n) / f_px_;
      s[size_t(i)] = t * t;
    }
    return s;
  };
  const std::vector<double> xx = squares(frame_.width), yy = squares(frame_.height);
  cv::parallel_for_(cv::Range(0, int(yy.size())), [&](const cv::Range& r) {
    for (int y = r.start; y < r.end; ++y) {
      float* top = w.ptr<float>(y);
      float* bottom = w.ptr<float>(frame_.height - 1 - y);
      for (int x = 0; x < int(xx.size()); ++x) {
        const float v = float(std::pow(1.0 + xx[size_t(x)] + yy[size_t(y)], -1.5));
        top[x] = top[frame_.width - 1 - x] = bottom[x] = bottom[frame_.width - 1 - x] = v;
      }
    }
  });
  return w;
}

cv::Mat FrameProjection::splat(const cv::Mat& image, const cv::Mat& positions, cv::Size size,
                               const cv::Scalar& outside) {
  return bilinear_splat(image, positions, SplatAffine(), size, outside, cv::Mat());
}

cv::Mat FrameProjection::to_plane_mean(const cv::Mat& frame, const cv::Scalar& outside, cv::Size size) const {
  CV_Assert(frame.size() == frame_);
  if (size.empty()) size = plane_;
  if (identity() && size == frame_) return frame;
  CV_Assert(!identity());
  const SplatAffine a{double(size.width) / plane_.width, double(size.height) / plane_.height, -0.5};
  return bilinear_splat(frame, carriage().positions, a, size, outside, cv::Mat());
}

cv::Mat FrameProjection::to_plane_flux(const cv::Mat& frame) const {
  CV_Assert(frame.size() == frame_);
  if (identity()) return frame;
  const Carriage& m = carriage();
  if (frame.type() != CV_32FC3)
    return bilinear_splat(frame, m.positions, SplatAffine{1, 1, -0.5}, plane_, cv::Scalar::all(0.0), m.flux_ratio);
  cv::Mat out;
  m.flux_splat->apply(frame, m.flux_norm, out);
  return out;
}

cv::Mat FrameProjection::flux_of_ones() const {
  CV_Assert(!identity());
  // A frame of ones splatted is each plane pixel's weight sum in every
  // channel (FixedSplat::weight_sums, bit for bit); times the factor as
  // FixedSplat::apply multiplies it.
  const Carriage& m = carriage();
  cv::Mat sums;
  m.flux_splat->weight_sums(sums);
  cv::Mat out(plane_, CV_32FC3);
  cv::parallel_for_(cv::Range(0, plane_.height), [&](const cv::Range& r) {
    for (int v = r.start; v < r.end; ++v) {
      const float* s = sums.ptr<float>(v);
      const float* f = m.flux_norm.ptr<float>(v);
      cv::Vec3f* o = out.ptr<cv::Vec3f>(v);
      for (int u = 0; u < plane_.width; ++u) o[u] = cv::Vec3f::all(s[u] * f[u]);
    }
  });
  return out;
}

cv::Mat FrameProjection::gaze_positions(cv::Point2d gaze, cv::Size size, double scale, cv::Point2d origin) const {
  const double sx = double(frame_.width) / size.width, sy = double(frame_.height) / size.height;
  cv::Mat out(size, CV_32FC2);
  if (identity()) {  // a translation
    for (int y = 0; y < size.height; ++y)
      for (int x = 0; x < size.width; ++x)
        out.at<cv::Vec2f>(y, x) = cv::Vec2f(float(origin.x + scale * ((x + 0.5) * sx - gaze.x)),
                                            float(origin.y + scale * ((y + 0.5) * sy - gaze.y)));
    return out;
  }
  const GazeAxes axes = gaze_axes(gaze);
  const auto exact = [&](double X, double Y) {
    const cv::Vec2d o = kind_ == Projection::equidistant ? gaze_offset(gaze, {X, Y}) : offset_from(axes, {X, Y});
    return cv::Vec2d(origin.x + scale * o[0], origin.y + scale * o[1]);
  };
  // Exact at nodes every kStep pixels (and the last), bilinear between.
  constexpr int kStep = 4;
  const auto nodes = [](int n) {
    std::vector<int> v;
    for (int i = 0; i < std::max(n - 1, 1); i += kStep) v.push_back(i);
    v.push_back(std::max(n - 1, 1));  // a one-pixel image: node 0 and a virtual neighbour at 1
    return v;
  };
  const std::vector<int> nx = nodes(size.width), ny = nodes(size.height);
  cv::Mat grid(int(ny.size()), int(nx.size()), CV_64FC2);
  cv::parallel_for_(cv::Range(0, grid.rows), [&](const cv::Range& r) {
    for (int j = r.start; j < r.end; ++j)
      for (int i = 0; i < grid.cols; ++i)
        grid.at<cv::Vec2d>(j, i) = exact((nx[size_t(i)] + 0.5) * sx, (ny[size_t(j)] + 0.5) * sy);
  });
  // Each column's node and weight, once for every row.
  std::vector<int> column_node(size_t(size.width));
  std::vector<double> column_weight(size_t(size.width));
  for (int x = 0; x < size.width; ++x) {
    const int i = std::min(x / kStep, grid.cols - 2);
    column_node[size_t(x)] = i;
    column_weight[size_t(x)] = double(x - nx[size_t(i)]) / (nx[size_t(i) + 1] - nx[size_t(i)]);
  }
  cv::parallel_for_(cv::Range(0, size.height), [&](const cv::Range& r) {
    for (int y = r.start; y < r.end; ++y) {
      const int j = std::min(y / kStep, grid.rows - 2);
      const double fy = double(y - ny[size_t(j)]) / (ny[size_t(j) + 1] - ny[size_t(j)]);
      const cv::Vec2d* g0 = grid.ptr<cv::Vec2d>(j);
      const cv::Vec2d* g1 = grid.ptr<cv::Vec2d>(j + 1);
      cv::Vec2f* o = out.ptr<cv::Vec2f>(y);
      for (int x = 0; x < size.width; ++x) {
        const int i = column_node[size_t(x)];
        const double fx = column_weight[size_t(x)];
        const cv::Vec2d v = (g0[i] * (1 - fx) + g0[i + 1] * fx) * (1 - fy) + (g1[i] * (1 - fx) + g1[i + 1] * fx) * fy;
        o[x] = cv::Vec2f(float(v[0]), float(v[1]));
      }
    }
  });
  return out;
}

cv::Mat FrameProjection::to_frame_image(const cv::Mat& plane) const {
  if (identity()) return plane;
  cv::Mat out;
  to_frame_image(plane, out, {});
  return out;
}

void FrameProjection::to_frame_image(const cv::Mat& plane, cv::Mat& out, const RowFinish& finish) const {
  CV_Assert(!identity() && plane.size() == plane_ && plane.type() == CV_32FC3);
  const Carriage& m = carriage();
  out.create(frame_, CV_32FC3);
  // Each stripe of rows through cv::remap (every pixel computed on its
  // own from the plane, so any split gives the same values; the stripes
  // are fixed, 8 rows whatever the threads), then to `finish` while in
  // the cache.
  constexpr int kStripeRows = 8;
  const int stripes = (frame_.height + kStripeRows - 1) / kStripeRows;
  cv::parallel_for_(cv::Range(0, stripes), [&](const cv::Range& r) {
    for (int s = r.start; s < r.end; ++s) {
      const cv::Range rows(s * kStripeRows, std::min(frame_.height, (s + 1) * kStripeRows));
      cv::Mat stripe = out.rowRange(rows);
      cv::remap(plane, stripe, m.remap1.rowRange(rows), m.remap2.rowRange(rows), cv::INTER_LINEAR,
                cv::BORDER_REPLICATE);
      if (finish)
        for (int y = rows.start; y < rows.end; ++y) finish(y, out.ptr<float>(y));
    }
  });
}

}  // namespace eyestream::pipeline
