// One second of a 64x36 night scene with a lamp, through a 70-year-old
// viewer's eye; prints what the eye did to the last frame.
#include <cstdio>
#include <eyestream/eye.hpp>

int main() {
  try {
    eyestream::Eye eye(64, 36, 30.0, {{"quality", "fast"}, {"viewer-age", "70"}});
    cv::Mat scene(36, 64, CV_32FC3, cv::Scalar::all(0.3));
    scene(cv::Rect(30, 16, 3, 3)).setTo(cv::Scalar::all(1e4));
    eyestream::Frame out;
    for (int n = 0; n < 30; ++n) out = eye.process(scene, {{n / 30.0, 31.0, 17.0}});
    std::printf("eyestream consumer: adaptation %.3g cd/m^2, pupil %.2f mm, lamp shown at %.3f of the display peak\n",
                out.report.adaptation_cd_m2, out.report.pupil_mm, out.linear.at<cv::Vec3f>(17, 31)[0]);
  } catch (const eyestream::Error& e) {
    std::fprintf(stderr, "consumer: %s (exit %d)\n", e.what(), e.exit_code());
    return e.exit_code();
  }
  return 0;
}
