// The committed command reference is what the program writes from its
// option declarations, and it names every run parameter: the docs cannot
// drift from the command line.
#include <gtest/gtest.h>

#include "pipeline/settings/parameter.hpp"
#include "pipeline/settings/settings.hpp"
#include "tests/test_support.hpp"

namespace eyestream {
namespace {

TEST(CommandReference, TheCommittedFilesAreWhatTheProgramWrites) {
  test::ScratchDir dir;
  for (const auto& [format, committed] : {std::pair<std::string, std::string>{"md", "docs/commands.md"},
                                          std::pair<std::string, std::string>{"man", "docs/eyestream.1"}}) {
    const auto r = test::run_eyestream("reference --format " + format + " -o " + (dir / format));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(test::read_bytes(dir / format), test::read_bytes(std::string(EYESTREAM_SOURCE_DIR) + "/" + committed))
        << committed << " is stale: run `build/eyestream reference --format " << format << " -y -o " << committed
        << "`";
  }
  const std::string md = test::read_bytes(std::string(EYESTREAM_SOURCE_DIR) + "/docs/commands.md");
  pipeline::Settings s;
  const pipeline::ParamSet params = pipeline::run_parameters(s);
  for (const pipeline::Param& p : params.params())
    EXPECT_NE(md.find("--" + p.name), std::string::npos) << p.name;
}

}  // namespace
}  // namespace eyestream
