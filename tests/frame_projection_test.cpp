// The angle plane of a rectilinear frame, checked against a pinhole camera
// written out in the test (true_angle_oracle.hpp): distances from the
// centre are true angles, local scales and solid angles are the camera's,
// carrying a frame into the plane keeps its light and gives each plane
// pixel its frame pixels' bilinear shares, and the way back samples the
// plane bilinearly.
#include "pipeline/geometry/frame_projection.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <tuple>
#include <opencv2/core/utility.hpp>
#include <vector>

#include "tests/bilinear_share_oracle.hpp"
#include "tests/true_angle_oracle.hpp"

namespace eyestream::pipeline {
namespace {

constexpr int kW = 960, kH = 540;
const test::PinholeFrame kPinhole{kW, kH, 120.0};

TEST(FrameProjection, PlaneDistanceFromTheCentreIsTheTrueAngle) {
  const FrameProjection p(kW, kH, 120.0, Projection::rectilinear);
  const cv::Point2d centre(0.5 * kW, 0.5 * kH), plane_centre = p.to_plane(centre);
  EXPECT_NEAR(p.pixels_per_degree(), kPinhole.focal_px() * M_PI / 180.0, 1e-9);
  for (const cv::Point2d q : {cv::Point2d(10, 10), cv::Point2d(900, 30), cv::Point2d(480, 500), cv::Point2d(700, 300)}) {
    const cv::Point2d a = p.to_plane(q);
    EXPECT_NEAR(cv::norm(a - plane_centre) / p.pixels_per_degree(), kPinhole.angle_deg(centre, q), 1e-9);
    EXPECT_NEAR(p.angle_deg(q, centre), kPinhole.angle_deg(q, centre), 1e-9);
    const cv::Point2d back = p.to_frame(a);
    EXPECT_NEAR(back.x, q.x, 1e-6);
    EXPECT_NEAR(back.y, q.y, 1e-6);
  }
  // Along a line through the centre, any two points are their true angle apart.
  const cv::Point2d left(kPinhole.x_at_deg(-30), 0.5 * kH), right(kPinhole.x_at_deg(50), 0.5 * kH);
  EXPECT_NEAR(cv::norm(p.to_plane(right) - p.to_plane(left)) / p.pixels_per_degree(), 80.0, 1e-9);
  // The plane spans the frame's 120 deg.
  EXPECT_NEAR(p.plane_size().width / p.pixels_per_degree(), 120.0, 1.0 / p.pixels_per_degree());
}

TEST(FrameProjection, EveryPixelsPlanePositionIsItsTrueAngle) {
  // Every pixel of the positions map (computed for a quarter of the frame
  // and mirrored), at even and odd sizes and two plane scales: at its true
  // angle from the centre along its own direction (the pinhole oracle),
  // and the float of to_plane's position bit for bit.
  for (const cv::Size size : {cv::Size(96, 54), cv::Size(97, 55)})
    for (const double scale : {1.0, 0.5}) {
      const test::PinholeFrame pinhole{size.width, size.height, 120.0};
      const FrameProjection p(size.width, size.height, 120.0, Projection::rectilinear, scale);
      const cv::Point2d centre(0.5 * size.width, 0.5 * size.height), plane_centre = p.to_plane(centre);
      int wrong = 0;
      for (int y = 0; y < size.height; ++y)
        for (int x = 0; x < size.width; ++x) {
          const cv::Point2d q(x + 0.5, y + 0.5), direct = p.to_plane(q);
          const cv::Vec2f got = p.plane_positions().at<cv::Vec2f>(y, x);
          wrong += got != cv::Vec2f(float(direct.x), float(direct.y));
          const cv::Point2d d(got[0] - plane_centre.x, got[1] - plane_centre.y), f = q - centre;
          EXPECT_NEAR(cv::norm(d) / p.pixels_per_degree(), pinhole.angle_deg(centre, q), 1e-4) << x << "," << y;
          EXPECT_NEAR(d.x * f.y - d.y * f.x, 0.0, 1e-3 * cv::norm(d) * cv::norm(f) + 1e-9) << x << "," << y;
        }
      EXPECT_EQ(wrong, 0) << size << " scale " << scale;
    }
  // An equidistant frame's positions (its own branch of the same loop),
  // at an odd size and a plane at half its px/deg: to_plane's bit for bit.
  const FrameProjection e(97, 55, 120.0, Projection::equidistant, 0.5);
  int wrong = 0;
  for (int y = 0; y < 55; ++y)
    for (int x = 0; x < 97; ++x) {
      const cv::Point2d direct = e.to_plane({x + 0.5, y + 0.5});
      wrong += e.plane_positions().at<cv::Vec2f>(y, x) != cv::Vec2f(float(direct.x), float(direct.y));
    }
  EXPECT_EQ(wrong, 0);
}

TEST(FrameProjection, LocalScaleAndSolidAngleAreThePinholesOwn) {
  const FrameProjection p(kW, kH, 120.0, Projection::rectilinear);
  for (const cv::Point2d q : {cv::Point2d(480, 270), cv::Point2d(850, 270), cv::Point2d(700, 60)}) {
    const cv::Vec2d ppd = p.local_pixels_per_degree(q);
    EXPECT_NEAR(ppd[0] * kPinhole.angle_deg(q - cv::Point2d(0.5, 0), q + cv::Point2d(0.5, 0)), 1.0, 1e-3);
    EXPECT_NEAR(ppd[1] * kPinhole.angle_deg(q - cv::Point2d(0, 0.5), q + cv::Point2d(0, 0.5)), 1.0, 1e-3);
  }
  double sr = 0.0;
  const cv::Mat w = p.solid_angle_weights();
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      sr += kPinhole.pixel_sr(x, y);
      if ((x * 7 + y * 13) % 997 == 0) {
        ASSERT_NEAR(w.at<float>(y, x), kPinhole.pixel_sr(x, y) / kPinhole.pixel_sr(kW / 2, kH / 2), 1e-3);
      }
    }
  EXPECT_NEAR(p.solid_angle_deg2() / (sr * std::pow(180.0 / M_PI, 2)), 1.0, 1e-4);
}

// Every pixel's weight is cos^3 of its angle off axis as the formula gives
// it here, bit for bit (the program computes a quarter and mirrors it), on
// frames of even and odd sizes.
TEST(FrameProjection, SolidAngleWeightsAreTheCubedCosineOfEveryPixel) {
  for (const cv::Size size : {cv::Size(64, 36), cv::Size(61, 37)}) {
    const FrameProjection p(size.width, size.height, 90.0, Projection::rectilinear);
    const double f = 0.5 * size.width / std::tan(0.5 * 90.0 * (M_PI / 180.0));  // f_px, as the projection has it
    const cv::Mat w = p.solid_angle_weights();
    ASSERT_EQ(w.size(), size);
    int wrong = 0;
    for (int y = 0; y < size.height; ++y)
      for (int x = 0; x < size.width; ++x) {
        const double X = (x + 0.5 - 0.5 * size.width) / f, Y = (y + 0.5 - 0.5 * size.height) / f;
        wrong += w.at<float>(y, x) != float(std::pow(1.0 + X * X + Y * Y, -1.5));
      }
    EXPECT_EQ(wrong, 0) << size;
  }
}

// A small light 50 deg off axis lands on the plane with its flux (luminance
// times solid angle) kept, and a uniform frame reads uniform.
TEST(FrameProjection, CarryingAFrameIntoThePlaneKeepsItsLight) {
  const FrameProjection p(kW, kH, 120.0, Projection::rectilinear);
  cv::Mat frame(kH, kW, CV_32F, cv::Scalar(0.0));
  const int lx = int(kPinhole.x_at_deg(50.0));
  frame(cv::Rect(lx - 2, kH / 2 - 2, 5, 5)).setTo(1000.0);
  double frame_flux = 0.0;
  for (int y = kH / 2 - 2; y <= kH / 2 + 2; ++y)
    for (int x = lx - 2; x <= lx + 2; ++x) frame_flux += 1000.0 * kPinhole.pixel_sr(x, y);
  const double plane_pixel_sr = std::pow(M_PI / 180.0 / p.pixels_per_degree(), 2);
  const double plane_flux = cv::sum(p.to_plane_flux(frame))[0] * plane_pixel_sr;
  EXPECT_NEAR(plane_flux / frame_flux, 1.0, 0.03);
  // The same light in colour goes through the fixed splat, each channel alike.
  cv::Mat colour;
  cv::merge(std::vector<cv::Mat>{frame, frame * 0.5, frame * 0.25}, colour);
  const cv::Scalar colour_flux = cv::sum(p.to_plane_flux(colour)) * plane_pixel_sr;
  EXPECT_NEAR(colour_flux[0] / frame_flux, 1.0, 0.03);
  EXPECT_NEAR(colour_flux[1] / frame_flux, 0.5, 0.015);
  EXPECT_NEAR(colour_flux[2] / frame_flux, 0.25, 0.0075);
  EXPECT_NEAR(colour_flux[1] / colour_flux[0], 0.5, 1e-6);  // the same shares in every channel
  EXPECT_NEAR(colour_flux[2] / colour_flux[0], 0.25, 1e-6);
  const cv::Mat ones(kH, kW, CV_32FC3, cv::Scalar::all(2.0));
  const cv::Mat mean = p.to_plane_mean(ones, cv::Scalar::all(-1.0));
  EXPECT_FLOAT_EQ(mean.at<cv::Vec3f>(mean.rows / 2, mean.cols / 2)[1], 2.0f);
  EXPECT_FLOAT_EQ(mean.at<cv::Vec3f>(0, mean.cols / 2)[0], 2.0f) << "the top edge's middle is inside";
  EXPECT_FLOAT_EQ(mean.at<cv::Vec3f>(0, 0)[0], -1.0f) << "the plane's corner lies beyond the frame's";
}

// Seen from a gaze 40 deg off axis, every frame point lies its true angle
// from the gaze (in any direction: an eye's rotation, not the plane's
// stretch), to 0.01 px between the exactly computed nodes.
TEST(FrameProjection, GazePositionsAreTrueAnglesFromTheGaze) {
  const FrameProjection p(kW, kH, 120.0, Projection::rectilinear);
  const cv::Point2d gaze(kPinhole.x_at_deg(40.0), 200.0), origin(1000.0, 700.0);
  const cv::Mat pos = p.gaze_positions(gaze, p.frame_size(), 0.5, origin);
  for (int y = 3; y < kH; y += 61)
    for (int x = 5; x < kW; x += 73) {
      const cv::Vec2f q = pos.at<cv::Vec2f>(y, x);
      const double angle = kPinhole.angle_deg(gaze, {x + 0.5, y + 0.5});
      ASSERT_NEAR(std::hypot(q[0] - origin.x, q[1] - origin.y), 0.5 * angle * p.pixels_per_degree(), 0.01)
          << "pixel " << x << ", " << y;
    }
  // From the centre, they are the plane's positions.
  const cv::Point2d middle(0.5 * kW, 0.5 * kH);
  const cv::Mat central = p.gaze_positions(middle, p.frame_size(), 1.0, p.to_plane(middle));
  EXPECT_LT(cv::norm(central, p.plane_positions(), cv::NORM_INF), 0.01);
}

// The retinal grid reaches every frame point from every gaze on the frame,
// corners included; and images one pixel wide or high have positions too.
TEST(FrameProjection, TheRetinasReachCoversEveryGazeAndPoint) {
  for (const double fov : {29.3, 120.0, 170.0}) {
    const FrameProjection p(kW, kH, fov, Projection::rectilinear);
    const cv::Size2d reach = p.retina_reach();
    double across = 0.0, down = 0.0;
    for (int gy = 0; gy <= kH; gy += kH / 6)
      for (int gx = 0; gx <= kW; gx += kW / 8)
        for (int y = 0; y <= kH; y += kH / 9)
          for (int x = 0; x <= kW; x += kW / 12) {
            const cv::Vec2d o = p.gaze_offset({double(gx), double(gy)}, {double(x), double(y)});
            across = std::max(across, std::abs(o[0]));
            down = std::max(down, std::abs(o[1]));
          }
    EXPECT_LE(across, reach.width) << fov << " deg";
    EXPECT_LE(down, reach.height) << fov << " deg";
    EXPECT_GT(down, p.plane_size().height) << fov << " deg: more than the plane's own height from a corner";
  }
  const FrameProjection p(kW, kH, 120.0, Projection::rectilinear);
  for (const cv::Size size : {cv::Size(1, 7), cv::Size(9, 1), cv::Size(1, 1)}) {
    const cv::Mat pos = p.gaze_positions({100, 100}, size, 1.0, {0, 0});
    EXPECT_EQ(pos.size(), size);
    EXPECT_TRUE(cv::checkRange(pos));
  }
}

TEST(FrameProjection, ThePlaneIsTheSameWhateverTheThreadCount) {
  const FrameProjection p(kW, kH, 120.0, Projection::rectilinear);
  cv::Mat frame(kH, kW, CV_32FC3);
  cv::randu(frame, cv::Scalar::all(0.0), cv::Scalar::all(100.0));
  const int threads = cv::getNumThreads();
  cv::setNumThreads(1);
  const cv::Mat one = p.to_plane_flux(frame), one_small = p.to_plane_mean(frame, cv::Scalar::all(0), {300, 200});
  cv::setNumThreads(std::max(2, threads));
  const cv::Mat many = p.to_plane_flux(frame), many_small = p.to_plane_mean(frame, cv::Scalar::all(0), {300, 200});
  cv::setNumThreads(threads);
  EXPECT_EQ(cv::norm(one, many, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(one_small, many_small, cv::NORM_INF), 0.0);
}

// Where the pinhole puts frame pixel (x, y) on the plane: its true angle
// from the axis, times the plane's px per radian, from the plane's centre
// in the ray's direction (index coordinates: pixel centres at integers).
cv::Point2d plane_index(const FrameProjection& p, int x, int y) {
  const cv::Vec3d r = kPinhole.ray(x + 0.5, y + 0.5);
  const double theta = std::acos(r[2]), s = std::hypot(r[0], r[1]);
  const double fp = p.pixels_per_degree() * 180.0 / M_PI;
  const double k = s > 0.0 ? fp * theta / s : 0.0;
  return {0.5 * p.plane_size().width + k * r[0] - 0.5, 0.5 * p.plane_size().height + k * r[1] - 0.5};
}

// Each plane pixel is the bilinear-weighted mean of the frame pixels that
// land on it, times sin(theta) / theta at its own angle: summed here in
// double, pixel by pixel, from the pinhole's positions.
TEST(FrameProjection, TheFluxSplatIsEachPixelsBilinearShare) {
  constexpr int w = 320, h = 180;
  const FrameProjection p(w, h, 120.0, Projection::rectilinear);
  ASSERT_EQ(kPinhole.width * h, kPinhole.height * w);  // the same camera, smaller
  const test::PinholeFrame pinhole{w, h, 120.0};
  cv::Mat frame(h, w, CV_32FC3);
  cv::randu(frame, cv::Scalar::all(0.0), cv::Scalar::all(100.0));
  const cv::Size plane = p.plane_size();
  cv::Mat sums(plane, CV_64FC3, cv::Scalar::all(0.0)), weights(plane, CV_64F, cv::Scalar(0.0));
  const double fp = p.pixels_per_degree() * 180.0 / M_PI;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const cv::Vec3d r = pinhole.ray(x + 0.5, y + 0.5);
      const double theta = std::acos(r[2]), s = std::hypot(r[0], r[1]), k = s > 0.0 ? fp * theta / s : 0.0;
      const double tx = 0.5 * plane.width + k * r[0] - 0.5, ty = 0.5 * plane.height + k * r[1] - 0.5;
      const cv::Vec3d value(frame.at<cv::Vec3f>(y, x));
      test::for_each_bilinear_share(tx, ty, plane, [&](int i, int j, double b) {
        sums.at<cv::Vec3d>(j, i) += b * value;
        weights.at<double>(j, i) += b;
      });
    }
  const cv::Mat got = p.to_plane_flux(frame);
  ASSERT_EQ(got.size(), plane);
  int checked = 0;
  for (int v = 0; v < plane.height; ++v)
    for (int u = 0; u < plane.width; ++u) {
      const double b = weights.at<double>(v, u);
      if (b < 0.25) continue;  // the frame's edge: a ray's rounding moves a share across
      const double theta = std::hypot(u + 0.5 - 0.5 * plane.width, v + 0.5 - 0.5 * plane.height) / fp;
      const double ratio = theta > 0.0 ? std::sin(theta) / theta : 1.0;
      for (int c = 0; c < 3; ++c) {
        const double want = sums.at<cv::Vec3d>(v, u)[c] / b * ratio;
        ASSERT_NEAR(got.at<cv::Vec3f>(v, u)[c], want, 1e-4 * std::max(want, 1.0)) << u << "," << v << " c" << c;
      }
      ++checked;
    }
  EXPECT_GT(checked, plane.area() / 2);
}

// The flux of a frame of ones made from the splat's weights (the glare
// stage's in-frame shares): to_plane_flux's own bytes, with the weights
// summed or the factor applied differently a last bit would move.
TEST(FrameProjection, TheFluxOfOnesIsToPlaneFluxsBitForBit) {
  for (const auto& [w, h, kind, scale] : {std::tuple{97, 55, Projection::rectilinear, 1.0},
                                          std::tuple{160, 90, Projection::rectilinear, 0.5},
                                          std::tuple{97, 55, Projection::equidistant, 0.5}}) {
    const FrameProjection p(w, h, 120.0, kind, scale);
    const cv::Mat want = p.to_plane_flux(cv::Mat(h, w, CV_32FC3, cv::Scalar::all(1.0)));
    const cv::Mat got = p.flux_of_ones();
    ASSERT_EQ(got.size(), want.size());
    ASSERT_EQ(got.type(), want.type());
    for (int y = 0; y < got.rows; ++y)
      ASSERT_EQ(std::memcmp(got.ptr(y), want.ptr(y), size_t(got.cols) * got.elemSize()), 0) << w << "x" << h << " row " << y;
    EXPECT_GT(cv::norm(got, cv::NORM_INF), 0.5);
  }
}

// The way back: a plane holding a linear ramp comes back as the ramp at
// each frame pixel's pinhole position (to cv::remap's 1/32 px steps), and
// each row is handed to the finishing step once, as it was sampled.
TEST(FrameProjection, TheWayBackSamplesThePlaneAndFinishesEachRowOnce) {
  const FrameProjection p(kW, kH, 120.0, Projection::rectilinear);
  const cv::Size plane = p.plane_size();
  cv::Mat ramp(plane, CV_32FC3);
  const double a = 0.5, b = -0.25, c = 1000.0;
  for (int v = 0; v < plane.height; ++v)
    for (int u = 0; u < plane.width; ++u)
      ramp.at<cv::Vec3f>(v, u) = cv::Vec3f::all(float(a * u + b * v + c));
  std::vector<std::atomic<int>> finished(static_cast<size_t>(kH));
  cv::Mat out;
  p.to_frame_image(ramp, out, [&](int y, float* row) {
    ++finished[size_t(y)];
    for (int x = 0; x < kW; ++x) row[3 * x + 1] += 1.0f;  // the green channel, once
  });
  const cv::Mat plain = p.to_frame_image(ramp);
  int checked = 0;
  for (int y = 0; y < kH; ++y) {
    EXPECT_EQ(finished[size_t(y)].load(), 1) << "row " << y;
    for (int x = 0; x < kW; ++x) {
      const cv::Vec3f got = out.at<cv::Vec3f>(y, x);
      ASSERT_EQ(got[1], plain.at<cv::Vec3f>(y, x)[1] + 1.0f);
      ASSERT_EQ(got[0], plain.at<cv::Vec3f>(y, x)[0]);
      const cv::Point2d q = plane_index(p, x, y);
      if (q.x < 0 || q.y < 0 || q.x > plane.width - 1 || q.y > plane.height - 1) continue;  // the border repeats
      ASSERT_NEAR(got[0], a * q.x + b * q.y + c, (std::abs(a) + std::abs(b)) / 32.0 + 1e-3) << x << "," << y;
      ++checked;
    }
  }
  EXPECT_GT(checked, kW * kH / 2);
}

TEST(FrameProjection, AnEquidistantFrameIsItsOwnPlane) {
  const FrameProjection p(kW, kH, 120.0, Projection::equidistant);
  EXPECT_TRUE(p.identity());
  EXPECT_DOUBLE_EQ(p.pixels_per_degree(), kW / 120.0);
  EXPECT_EQ(p.plane_size(), cv::Size(kW, kH));
  EXPECT_EQ(p.to_plane({12.5, 40.0}), cv::Point2d(12.5, 40.0));
}

}  // namespace
}  // namespace eyestream::pipeline
