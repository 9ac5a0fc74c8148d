// The version: `eyestream --version`, --print-plan and the report's JSON
// all give the version CMakeLists.txt's project() declares (read here from
// the file itself).
#include <gtest/gtest.h>

#include <regex>

#include "tests/test_support.hpp"

namespace eyestream {
namespace {

std::string declared_version() {
  const std::string cmake = test::read_bytes(std::string(EYESTREAM_SOURCE_DIR) + "/CMakeLists.txt");
  std::smatch m;
  if (!std::regex_search(cmake, m, std::regex(R"(project\(eyestream VERSION ([0-9.]+))"))) return "";
  return m[1];
}

TEST(Version, CommandLinePlanAndReportGiveTheDeclaredVersion) {
  const std::string v = declared_version();
  ASSERT_FALSE(v.empty());
  auto r = test::run_eyestream("--version");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.output, "eyestream " + v + "\n");
  test::ScratchDir dir;
  ASSERT_EQ(test::run_eyestream("sample headlights -o " + (dir / "h") + " --width 64 --height 36 --duration 0.2")
                .exit_code,
            0);
  const std::string in = "run -i " + (dir / "h/frames") + " -o " + (dir / "v.mp4");
  r = test::run_eyestream(in + " --print-plan");
  EXPECT_NE(r.output.find("eyestream = " + v + "\n"), std::string::npos) << r.output;
  r = test::run_eyestream(in + " --report " + (dir / "r.csv"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(test::read_bytes(dir / "r.json").find("\"eyestream\": \"" + v + "\""), std::string::npos);
}

}  // namespace
}  // namespace eyestream

namespace eyestream {
namespace {

// --help shows the defaults the chosen preset runs with (balanced by
// default: the split engine), not the table's bare ones.
TEST(Help, ShowsThePresetsDefaults) {
  const auto balanced = test::run_eyestream("run --help");
  EXPECT_NE(balanced.output.find("defaults shown for --quality balanced"), std::string::npos) << balanced.output;
  const auto line = [](const std::string& help, const std::string& option) {
    const size_t at = help.find(option);
    return at == std::string::npos ? std::string() : help.substr(at, help.find('\n', at) - at);
  };
  EXPECT_NE(line(balanced.output, "--glare-engine").find("(default split;"), std::string::npos)
      << line(balanced.output, "--glare-engine");
  const auto reference = test::run_eyestream("run --quality reference --help");
  EXPECT_NE(line(reference.output, "--glare-engine").find("(default exact;"), std::string::npos)
      << line(reference.output, "--glare-engine");
  EXPECT_NE(line(test::run_eyestream("run --quality=fast --help").output, "--state-resolution").find("(default 0.25;"),
            std::string::npos);
}

}  // namespace
}  // namespace eyestream
