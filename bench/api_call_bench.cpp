// The C++ side of bench/api_overhead.py: the time of eyestream::Eye::process
// per frame, on the frames and gaze that script feeds the Python module (a
// 1e4 cd/m^2 lamp moving across a 0.3 cd/m^2 road, the gaze on it). Times,
// never asserts.
//   eyestream_api_call_bench WIDTH HEIGHT FRAMES QUALITY
// prints "cpp_ms_per_frame X faults_per_frame Y" (minor page faults).
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <eyestream/eye.hpp>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: eyestream_api_call_bench WIDTH HEIGHT FRAMES QUALITY\n");
    return 2;
  }
  const int width = std::atoi(argv[1]), height = std::atoi(argv[2]), frames = std::atoi(argv[3]);
  const double fps = 30.0;
  eyestream::Eye eye(width, height, fps, {{"quality", argv[4]}});
  std::vector<cv::Mat> input;
  std::vector<std::vector<eyestream::Gaze>> gaze;
  for (int n = 0; n <= frames; ++n) {  // frame 0 warms up, untimed
    cv::Mat frame(height, width, CV_32FC3, cv::Scalar::all(0.3));
    const int lamp = width / 8 + (n * width / 40) % (width * 3 / 4), side = std::max(2, width / 80);
    frame(cv::Rect(lamp, height / 2 - side / 2, side, side)) = cv::Scalar::all(1e4);
    input.push_back(frame);
    gaze.push_back({{n / fps, lamp + side / 2.0, height / 2.0}});
  }
  eye.process(input[0], gaze[0]);
  const auto faults = [] {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_minflt);
  };
  const double faults0 = faults();
  const auto start = std::chrono::steady_clock::now();
  for (int n = 1; n <= frames; ++n) eye.process(input[size_t(n)], gaze[size_t(n)]);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("cpp_ms_per_frame %.3f faults_per_frame %.0f\n", 1e3 * s / frames, (faults() - faults0) / frames);
  return 0;
}
