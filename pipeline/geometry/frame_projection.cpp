#include "pipeline/geometry/frame_projection.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <mutex>
#include <opencv2/imgproc.hpp>

#include "io/error.hpp"
#include "pipeline/geometry/remap_maps.hpp"
#include "retina/pixel_vector.hpp"

namespace eyestream::pipeline {

namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr int kBlockRows = 32;  // plane rows per splat task

// A target position: t = pos * k + offset (pixel centres at integers).
struct Affine {
  double kx = 1, ky = 1, offset = 0;
};

// A target row's normalised means: each sum over its weight (times the
// multiplier when given), `outside` where nothing landed.
template <typename T, int C>
void normalise_row(const cv::Vec<T, C + 1>* sums, const float* m, const cv::Scalar& outside, T* o, int cols) {
  for (int i = 0; i < cols; ++i) {
    const cv::Vec<T, C + 1>& s = sums[i];
    for (int c = 0; c < C; ++c) o[i * C + c] = s[C] > T(0) ? s[c] / s[C] * (m ? T(m[i]) : T(1)) : T(outside[c]);
  }
}

// Three float channels and the weight as one four-float vector (GCC's and
// Clang's vector extension): one division a pixel instead of three, the
// same quotients.
typedef float Quad __attribute__((vector_size(16)));

template <>
void normalise_row<float, 3>(const cv::Vec4f* sums, const float* m, const cv::Scalar& outside, float* o, int cols) {
  const float away[3] = {float(outside[0]), float(outside[1]), float(outside[2])};
  for (int i = 0; i < cols; ++i) {
    Quad s;
    std::memcpy(&s, &sums[i], sizeof s);
    if (s[3] > 0.0f) {
      Quad q = s / Quad{s[3], s[3], s[3], s[3]};
      if (m) q = q * m[i];
      o[3 * i] = q[0], o[3 * i + 1] = q[1], o[3 * i + 2] = q[2];
    } else {
      o[3 * i] = away[0], o[3 * i + 1] = away[1], o[3 * i + 2] = away[2];
    }
  }
}

// sum += value x share, each channel and the weight alone.
template <typename T, int N>
inline void add_share(cv::Vec<T, N>& sum, const cv::Vec<T, N>& value, T share) {
  sum += value * share;
}

// The same for three float channels and the weight as one vector
// (retina/pixel_vector.hpp): the same products and sums, one multiply and
// one add instead of four of each.
inline void add_share(cv::Vec4f& sum, const cv::Vec4f& value, float share) {
  retina::PixelVector s, v;
  std::memcpy(&s, sum.val, sizeof s);
  std::memcpy(&v, value.val, sizeof v);
  s = s + v * share;
  std::memcpy(sum.val, &s, sizeof s);
}

// One image row's bilinear splat into a block's sums (target rows [r0,
// r0 + rows), each sum the pixel's channels and its weight): every share
// value x ((1 - fx or fx) x (1 - fy or fy)), added in the row's order.
template <typename T, int C>
void splat_row(const T* in, const cv::Vec2f* pos, int pixels, float kx, float ky, float offset, int r0, int rows,
               int cols, cv::Vec<T, C + 1>* sums) {
  using Acc = cv::Vec<T, C + 1>;
  for (int x = 0; x < pixels; ++x) {
    const float tx = pos[x][0] * kx + offset, ty = pos[x][1] * ky + offset;
    const int i0 = int(std::floor(tx)), j0 = int(std::floor(ty));
    if (j0 + 1 < r0 || j0 >= r0 + rows) continue;
    const T fx = T(tx - i0), fy = T(ty - j0);
    Acc value;
    for (int c = 0; c < C; ++c) value[c] = in[x * C + c];
    value[C] = T(1);
    for (int dj = 0; dj < 2; ++dj) {
      const int j = j0 + dj - r0;
      if (j < 0 || j >= rows) continue;
      const T wy = dj ? fy : T(1) - fy;
      for (int di = 0; di < 2; ++di) {
        const int i = i0 + di;
        if (i < 0 || i >= cols) continue;
        add_share(sums[size_t(j) * size_t(cols) + size_t(i)], value, (di ? fx : T(1) - fx) * wy);
      }
    }
  }
}

// `outside` in target pixels [from, to) of a row.
template <typename T, int C>
void fill_outside(const cv::Scalar& outside, T* o, int from, int to) {
  for (int i = from; i < to; ++i)
    for (int c = 0; c < C; ++c) o[i * C + c] = T(outside[c]);
}

// Accumulates the bilinear splat of image rows [first_row, last_row] into
// the target rows [r0, r0 + kBlockRows), then writes their normalised means
// to `out` (times `multiplier` when given; `outside` where nothing lands).
// Only target columns [lo, hi) can be reached (the rows' positions
// across): the sums are kept and normalised there only; the rest of the
// block is `outside` (the retina's grid is twice the frame each way).
template <typename T, int C>
void splat_block(const cv::Mat& image, const cv::Mat& positions, Affine a, int r0, int first_row, int last_row,
                 int lo, int hi, const cv::Scalar& outside, const cv::Mat& multiplier, cv::Vec<T, C + 1>* sums,
                 cv::Mat& out) {
  using Acc = cv::Vec<T, C + 1>;
  const int rows = std::min(kBlockRows, out.rows - r0), cols = out.cols;
  if (last_row < first_row || lo >= hi) {  // nothing lands on the block: all outside
    for (int j = 0; j < rows; ++j) fill_outside<T, C>(outside, out.ptr<T>(r0 + j), 0, cols);
    return;
  }
  for (int j = 0; j < rows; ++j)
    std::fill(sums + size_t(j) * size_t(cols) + size_t(lo), sums + size_t(j) * size_t(cols) + size_t(hi), Acc::all(0));
  const float kx = float(a.kx), ky = float(a.ky), offset = float(a.offset);
  for (int y = first_row; y <= last_row; ++y)
    splat_row<T, C>(image.ptr<T>(y), positions.ptr<cv::Vec2f>(y), image.cols, kx, ky, offset, r0, rows, cols, sums);
  for (int j = 0; j < rows; ++j) {
    T* o = out.ptr<T>(r0 + j);
    const float* m = multiplier.empty() ? nullptr : multiplier.ptr<float>(r0 + j) + lo;
    fill_outside<T, C>(outside, o, 0, lo);
    normalise_row<T, C>(sums + size_t(j) * size_t(cols) + size_t(lo), m, outside, o + size_t(lo) * C, hi - lo);
    fill_outside<T, C>(outside, o, hi, cols);
  }
}

// Splats `image` onto `out` in blocks of target rows, each block a task
// that scans only the image rows reaching it: the sums at each target
// pixel come in one order whatever the thread count.
template <typename T, int C>
void splat_rows(const cv::Mat& image, const cv::Mat& positions, Affine a, const cv::Scalar& outside,
                const cv::Mat& multiplier, cv::Mat& out) {
  // Each image row's reach: the target rows [top, bottom] its footprints
  // can touch, and the columns [left, right), from the footprints' own
  // left columns (splat_block's arithmetic: the same floors).
  std::vector<int> top(size_t(image.rows)), bottom(size_t(image.rows)), left(size_t(image.rows)),
      right(size_t(image.rows));
  const float kx = float(a.kx), offset = float(a.offset);
  cv::parallel_for_(cv::Range(0, image.rows), [&](const cv::Range& r) {
    for (int y = r.start; y < r.end; ++y) {
      const cv::Vec2f* pos = positions.ptr<cv::Vec2f>(y);
      float low = 1e30f, high = -1e30f, west = 1e30f, east = -1e30f;
      for (int x = 0; x < image.cols; ++x) {
        low = std::min(low, pos[x][1]);
        high = std::max(high, pos[x][1]);
        const float tx = pos[x][0] * kx + offset;
        west = std::min(west, tx);
        east = std::max(east, tx);
      }
      top[size_t(y)] = int(std::floor(low * a.ky + a.offset));
      bottom[size_t(y)] = int(std::floor(high * a.ky + a.offset)) + 1;
      left[size_t(y)] = int(std::floor(west));
      right[size_t(y)] = int(std::floor(east)) + 2;
    }
  });
  const int blocks = (out.rows + kBlockRows - 1) / kBlockRows;
  // One accumulator per share of the blocks, made here, not per thread as
  // a thread first comes: the frame loop then asks the allocator for the
  // same blocks every frame, whichever threads run (the pool has them).
  const int shares = std::min(blocks, std::max(1, cv::getNumThreads()));
  std::vector<cv::Mat> accumulators(static_cast<size_t>(shares));
  for (cv::Mat& m : accumulators) m.create(1, int(sizeof(cv::Vec<T, C + 1>)) * kBlockRows * out.cols, CV_8U);
  cv::parallel_for_(cv::Range(0, shares), [&](const cv::Range& r) {
    for (int k = r.start; k < r.end; ++k)
    for (int b = k; b < blocks; b += shares) {
      const int r0 = b * kBlockRows, r1 = std::min(out.rows, r0 + kBlockRows);
      int first = image.rows, last = -1, lo = out.cols, hi = 0;
      for (int y = 0; y < image.rows; ++y) {
        if (bottom[size_t(y)] < r0 || top[size_t(y)] >= r1) continue;
        first = std::min(first, y);
        last = std::max(last, y);
        lo = std::min(lo, std::max(left[size_t(y)], 0));
        hi = std::max(hi, std::min(right[size_t(y)], out.cols));
      }
      splat_block<T, C>(image, positions, a, r0, first, last, lo, hi, outside, multiplier,
                        accumulators[size_t(k)].ptr<cv::Vec<T, C + 1>>(), out);
    }
  });
}

cv::Mat splat_any(const cv::Mat& image, const cv::Mat& positions, Affine a, cv::Size size, const cv::Scalar& outside,
                  const cv::Mat& multiplier) {
  CV_Assert(positions.type() == CV_32FC2 && positions.size() == image.size());
  cv::Mat out(size, image.type());
  switch (image.type()) {
    case CV_32FC1: splat_rows<float, 1>(image, positions, a, outside, multiplier, out); break;
    case CV_32FC3: splat_rows<float, 3>(image, positions, a, outside, multiplier, out); break;
    case CV_64FC3: splat_rows<double, 3>(image, positions, a, outside, multiplier, out); break;
    default: CV_Error(cv::Error::StsUnsupportedFormat, "splat: CV_32FC1, CV_32FC3 or CV_64FC3");
  }
  return out;
}

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
  const cv::Mat weight = splat_any(cv::Mat(frame_, CV_32FC1, cv::Scalar(1.0)), m.positions, Affine{1, 1, -0.5}, plane_,
                                   cv::Scalar(0.0), cv::Mat());  // 1 where covered, 0 beyond
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
  double across = 0.0, down = 0.0;
  for (const cv::Point2d& gaze : edge) {
    for (const cv::Point2d& p : edge) {
      const cv::Vec2d o = gaze_offset(gaze, p);
      across = std::max(across, std::abs(o[0]));
      down = std::max(down, std::abs(o[1]));
    }
  }
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
  cv::Mat w(frame_, CV_32F, cv::Scalar(1.0));
  if (kind_ == Projection::equidistant) return w;
  for (int y = 0; y < frame_.height; ++y)
    for (int x = 0; x < frame_.width; ++x) {
      const double X = (x + 0.5 - 0.5 * frame_.width) / f_px_, Y = (y + 0.5 - 0.5 * frame_.height) / f_px_;
      w.at<float>(y, x) = float(std::pow(1.0 + X * X + Y * Y, -1.5));  // cos^3 of the angle off axis
    }
  return w;
}

cv::Mat FrameProjection::splat(const cv::Mat& image, const cv::Mat& positions, cv::Size size,
                               const cv::Scalar& outside) {
  return splat_any(image, positions, Affine(), size, outside, cv::Mat());
}

cv::Mat FrameProjection::to_plane_mean(const cv::Mat& frame, const cv::Scalar& outside, cv::Size size) const {
  CV_Assert(frame.size() == frame_);
  if (size.empty()) size = plane_;
  if (identity() && size == frame_) return frame;
  CV_Assert(!identity());
  const Affine a{double(size.width) / plane_.width, double(size.height) / plane_.height, -0.5};
  return splat_any(frame, carriage().positions, a, size, outside, cv::Mat());
}

cv::Mat FrameProjection::to_plane_flux(const cv::Mat& frame) const {
  CV_Assert(frame.size() == frame_);
  if (identity()) return frame;
  const Carriage& m = carriage();
  if (frame.type() != CV_32FC3)
    return splat_any(frame, m.positions, Affine{1, 1, -0.5}, plane_, cv::Scalar::all(0.0), m.flux_ratio);
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
