// The same inputs and settings give the same bytes for every output kind,
// whatever the thread count, with the machine's cores kept busy by other
// work while the runs go on (x264's AVX-512 kernels read past their
// buffers, so its output once depended on timing: io/video_writer.cpp).
#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

#include "tests/test_support.hpp"

namespace eyestream {
namespace {

// Spins one thread per core until destroyed.
class BusyCores {
 public:
  BusyCores() {
    const unsigned n = std::max(1u, std::thread::hardware_concurrency());
    for (unsigned i = 0; i < n; ++i)
      threads_.emplace_back([this] {
        volatile double x = 1.0;
        while (!stop_) x = x * 1.0000001 + 1e-9;
      });
  }
  ~BusyCores() {
    stop_ = true;
    for (std::thread& t : threads_) t.join();
  }

 private:
  std::atomic<bool> stop_{false};
  std::vector<std::thread> threads_;
};

TEST(Determinism, EveryOutputKindIsByteIdenticalAcrossThreadCountsUnderLoad) {
  test::ScratchDir dir;
  ASSERT_EQ(test::run_eyestream("sample night-drive -o " + (dir / "s") + " --width 96 --height 54 --duration 0.5")
                .exit_code,
            0);
  const std::string in = "run -i " + (dir / "s/frames") + " -g " + (dir / "s/gaze.csv");
  const struct {
    const char* name;
    std::string output;  // with %T for the run's tag
    std::string first;   // the file compared
  } kinds[] = {
      {"H.264", "-o " + (dir / "%T.mp4"), "%T.mp4"},
      {"H.264, side by side", "-o " + (dir / "%T.mp4") + " --side-by-side", "%T.mp4"},
      {"H.264 on standard output", "-o - --format mp4 | cat > " + (dir / "%T.mp4"), "%T.mp4"},
      {"HEVC 10-bit", "-o " + (dir / "%T.mkv") + " --bit-depth 10", "%T.mkv"},
      {"HDR10", "-o " + (dir / "%T.mkv") + " --hdr10 --display-peak 1000", "%T.mkv"},
      {"PNG", "-o " + (dir / "%T/%05d.png"), "%T/00007.png"},
      {"EXR", "-o " + (dir / "%T/%05d.exr"), "%T/00007.exr"},
  };
  const auto tagged = [](std::string text, const std::string& tag) {
    for (size_t at; (at = text.find("%T")) != std::string::npos;) text.replace(at, 2, tag);
    return text;
  };
  BusyCores busy;
  int k = 0;
  for (const auto& kind : kinds) {
    // Under ASan (a tenth of the speed) the H.264 and EXR outputs only: 67 s for all seven.
    if (test::kSanitized && &kind != &kinds[0] && &kind != &kinds[6]) continue;
    std::string bytes[2];
    for (int t = 0; t < 2; ++t) {
      const std::string tag = "k" + std::to_string(k) + "t" + std::to_string(t);
      const auto r = test::run_eyestream(in + " --threads " + std::to_string(t + 1) + " " + tagged(kind.output, tag));
      ASSERT_EQ(r.exit_code, 0) << kind.name << ": " << r.output;
      bytes[t] = test::read_bytes(dir / tagged(kind.first, tag));
    }
    EXPECT_GT(bytes[0].size(), 100u) << kind.name;
    EXPECT_TRUE(bytes[0] == bytes[1]) << kind.name << ": --threads 1 and 2 differ under load";
    ++k;
  }
}

}  // namespace
}  // namespace eyestream
