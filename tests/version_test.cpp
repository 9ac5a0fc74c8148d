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
