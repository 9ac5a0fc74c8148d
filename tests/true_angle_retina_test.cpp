// A wide rectilinear frame gets true angles beyond the optics: an
// afterimage keeps its angular size wherever the gaze takes it, the
// adaptation patch is 1.5 deg of true angle at the gaze, and the pupil
// responds to the field's mean luminance over solid angle. The oracle is a
// pinhole camera written out in the test (true_angle_oracle.hpp).
#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "glare/pupil.hpp"
#include "io/exr_file.hpp"
#include "io/gaze_csv.hpp"
#include "pipeline/eye/eye_simulator.hpp"
#include "tests/test_support.hpp"
#include "tests/true_angle_oracle.hpp"

namespace eyestream::pipeline {
namespace {

// The spread (second central moments, px) of an image's green channel.
cv::Vec2d spread_of(const cv::Mat& rgb) {
  cv::Mat g;
  cv::extractChannel(rgb, g, 1);
  const cv::Moments m = cv::moments(g);
  return {std::sqrt(m.mu20 / m.m00), std::sqrt(m.mu02 / m.m00)};
}

// After a flash fixated at the centre, the afterimage drawn with the gaze
// 40 deg to the right covers as many degrees: in frame pixels it is wider
// by the frame's local scale there (1.70 across, 1.31 down on a 120 deg
// frame), where an equidistant reading keeps it as many pixels wide.
TEST(TrueAngles, AnAfterimageKeepsItsAngularSizeAcrossAWideFrame) {
  constexpr int kW = 480, kH = 270;
  const test::PinholeFrame pinhole{kW, kH, 120.0};
  const cv::Point2d centre(0.5 * kW, 0.5 * kH), right(pinhole.x_at_deg(40.0), 0.5 * kH);
  const auto local_scale = [&](cv::Point2d q, cv::Point2d step) { return 1.0 / pinhole.angle_deg(q - step, q + step); };
  const double expected_x = local_scale(right, {0.5, 0}) / local_scale(centre, {0.5, 0});
  const double expected_y = local_scale(right, {0, 0.5}) / local_scale(centre, {0, 0.5});
  for (const char* projection : {"rectilinear", "equidistant"}) {
    Settings s;
    s.state_sites_per_pixel = 1.0;
    s.glare = false;
    s.geometry.fov_deg = 120.0;
    s.geometry.projection = projection;
    EyeSimulator eye(test::plan_for(s, kW, kH, 60.0));
    cv::Mat flash(kH, kW, CV_32FC3, cv::Scalar::all(0.0)), dark = flash.clone();
    cv::circle(flash, cv::Point(kW / 2, kH / 2), 5, cv::Scalar::all(1e7), cv::FILLED);
    double t = 0.0;
    std::int64_t index = 0;
    const auto see = [&](const cv::Mat& rgb, cv::Point2d gaze) {
      const io::SceneFrame f{rgb, t, index++, "test"};
      const double t0 = t;
      t += 1.0 / 60.0;
      return eye.process(f, {{t0, t, gaze.x, gaze.y, false}}).linear;
    };
    for (int i = 0; i < 8; ++i) see(flash, centre);
    const cv::Vec2d at_centre = spread_of(see(dark, centre)), at_right = spread_of(see(dark, right));
    const cv::Vec2d ratio(at_right[0] / at_centre[0], at_right[1] / at_centre[1]);
    std::cout << projection << ": the afterimage at 40 deg is " << ratio[0] << " x " << ratio[1]
              << " its size at the centre (the pinhole's scale " << expected_x << " x " << expected_y << ")\n";
    if (std::string(projection) == "rectilinear") {
      EXPECT_NEAR(ratio[0] / expected_x, 1.0, 0.05) << ratio[0] << " wider, the pinhole's scale " << expected_x;
      EXPECT_NEAR(ratio[1] / expected_y, 1.0, 0.05) << ratio[1] << " taller, the pinhole's scale " << expected_y;
    } else {
      EXPECT_NEAR(ratio[0], 1.0, 0.02) << "equidistant: as many pixels wherever the gaze is";
    }
  }
}

// Through the command line, 960x540 at 120 deg, glare off: the first
// frame's adaptation is the mean over 1.5 x 1.5 deg of true angle around a
// gaze 50 deg off axis (where a 1000 cd/m^2 stripe half the patch wide
// stands on 1 cd/m^2), and its pupil is the model's for the solid-angle
// mean of the frame (a 100 cd/m^2 band within 30 deg of the axis).
TEST(TrueAngles, TheAdaptationPatchAndThePupilFieldAreTrueAngles) {
  constexpr int kW = 960, kH = 540;
  const test::PinholeFrame pinhole{kW, kH, 120.0};
  const cv::Point2d gaze(pinhole.x_at_deg(50.0), 0.5 * kH);
  const double patch_px = 1.5 / pinhole.angle_deg(gaze - cv::Point2d(0.5, 0), gaze + cv::Point2d(0.5, 0));
  cv::Mat scene(kH, kW, CV_32FC3, cv::Scalar::all(1.0));
  const int band = int(pinhole.focal_px() * std::tan(M_PI / 6));
  scene.colRange(kW / 2 - band, kW / 2 + band).setTo(cv::Scalar::all(100.0));
  const int stripe = int(std::lround(patch_px / 2));
  scene.colRange(int(gaze.x) - stripe / 2, int(gaze.x) - stripe / 2 + stripe).setTo(cv::Scalar::all(1000.0));
  // The oracle: the patch is the pixels within 0.75 deg of the gaze across
  // and down; the field is weighted by each pixel's solid angle.
  double patch_sum = 0.0, patch_n = 0.0, field = 0.0, sr = 0.0, plain = 0.0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const double l = scene.at<cv::Vec3f>(y, x)[1];
      field += l * pinhole.pixel_sr(x, y);
      sr += pinhole.pixel_sr(x, y);
      plain += l / (double(kW) * kH);
      if (pinhole.angle_deg({x + 0.5, gaze.y}, gaze) <= 0.75 && pinhole.angle_deg({gaze.x, y + 0.5}, gaze) <= 0.75) {
        patch_sum += l;
        patch_n += 1.0;
      }
    }
  const double patch_mean = patch_sum / patch_n;
  const glare::ViewerProfile viewer;
  const double pupil = glare::pupil_mm(viewer, std::log10(field / sr), 0.0);
  ASSERT_GT(std::abs(pupil - glare::pupil_mm(viewer, std::log10(plain), 0.0)), 0.05) << "the weighting matters here";
  test::ScratchDir dir;
  std::filesystem::create_directory(dir / "frames");
  io::write_exr(dir / "frames/f000.exr", scene, {false, 1.0, 30.0});
  io::write_gaze_csv(dir / "gaze.csv", {{0.0, gaze.x, gaze.y}, {0.02, gaze.x, gaze.y}});
  const auto r = test::run_eyestream("run -i " + (dir / "frames") + " -g " + (dir / "gaze.csv") + " -o " +
                                     (dir / "out/%05d.png") + " --fov-deg 120 --no-glare --report " + (dir / "r.csv"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream in(dir / "r.csv");
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  const std::vector<std::string> names = test::csv_fields(header), f = test::csv_fields(row);
  const auto col = [&](const std::string& n) { return size_t(std::find(names.begin(), names.end(), n) - names.begin()); };
  EXPECT_NEAR(std::stod(f[col("adaptation_cd_m2")]) / patch_mean, 1.0, 0.1)
      << "the patch's mean " << patch_mean << " cd/m^2 (1000 if the patch were 1.5 deg at the centre's scale)";
  EXPECT_NEAR(std::stod(f[col("pupil_mm")]), pupil, 0.01) << "the solid-angle mean " << field / sr << " cd/m^2";
}

}  // namespace
}  // namespace eyestream::pipeline
