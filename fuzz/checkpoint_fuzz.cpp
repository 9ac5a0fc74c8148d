// libFuzzer target: the checkpoint reader and the state validation behind
// --resume, for a 32x18 run with default settings (the seed corpus's). The
// checksum is recomputed over the mutated body, so mutations reach the
// parser and the validation behind it. A checkpoint that passes both is
// restored and a frame is filtered with it: no input may read or write
// past a buffer (the sanitizers watch).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "fuzz/fuzz_file.hpp"
#include "io/error.hpp"
#include "pipeline/run/checkpoint.hpp"
#include "pipeline/eye/eye_simulator.hpp"

using namespace eyestream;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool one_thread = [] {
    cv::setNumThreads(0);  // the same coverage on every run (scripts/fuzz.sh ci)
    return true;
  }();
  (void)one_thread;
  static const pipeline::Plan plan = [] {
    io::SourceInfo info;
    info.width = 32;
    info.height = 18;
    info.frames_per_second = 30;
    pipeline::Settings s;
    s.state_sites_per_pixel = 0.5;  // the grid of the seeds' checkpoints
    s.state_least_sites_per_deg = 0.0;
    return pipeline::compile_plan(s, info);
  }();
  std::vector<std::uint8_t> bytes(data, data + size);
  constexpr std::size_t kMagic = 23, kBody = kMagic + 8;  // "EYESTREAM-CHECKPOINT-2\n", then the checksum
  if (bytes.size() >= kBody) {
    std::uint64_t h = 1469598103934665603ULL;  // FNV-1a, as checkpoint.cpp
    for (std::size_t i = kBody; i < bytes.size(); ++i) h = (h ^ bytes[i]) * 1099511628211ULL;
    std::memcpy(bytes.data() + kMagic, &h, 8);
  }
  try {
    const pipeline::Checkpoint c = pipeline::read_checkpoint(fuzz::write_input(bytes.data(), bytes.size(), ".ckp"));
    for (const pipeline::EyeMemory& m : c.panels) {
      pipeline::EyeSimulator eye(plan);
      if (!eye.memory_error(m).empty()) continue;
      eye.restore(m);
      const cv::Mat frame(18, 32, CV_32FC3, cv::Scalar::all(1.0));
      eye.process({frame, 0.0, 0, "fuzz"}, {{0.0, 1.0 / 30, 16, 9, false}});
    }
  } catch (const InputError&) {
  }
  return 0;
}
