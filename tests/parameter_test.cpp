#include "pipeline/settings/parameter.hpp"

#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <fstream>

#include "io/error.hpp"
#include "pipeline/settings/settings.hpp"
#include "tests/test_support.hpp"

namespace eyestream::pipeline {
namespace {

// Parses `args` (after the program name) into fresh settings.
Settings parse(std::vector<std::string> args, const std::string& config = "") {
  Settings s;
  ParamSet params = run_parameters(s);
  CLI::App app;
  params.bind(app);
  std::reverse(args.begin(), args.end());
  app.parse(args);
  params.apply(config);
  return s;
}

std::string usage_error(std::vector<std::string> args, const std::string& config = "") {
  try {
    parse(std::move(args), config);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(Parameters, DefaultsComeFromTheModelStructs) {
  const Settings s = parse({});
  EXPECT_DOUBLE_EQ(s.adaptation.rate_up_log_per_s, 0.75);
  EXPECT_DOUBLE_EQ(s.adaptation.rate_down_log_per_s, 0.2);
  EXPECT_DOUBLE_EQ(s.tone.exponent, 0.7);
  EXPECT_DOUBLE_EQ(s.encoding.gamma, 0.455);
  EXPECT_TRUE(s.encoding.dither);
  EXPECT_FALSE(s.exr.scale.has_value());
}

TEST(Parameters, CommandLineSetsValuesOfEveryKind) {
  const Settings s = parse({"--adapt-rate-up", "1.5", "--crf", "23", "--no-dither", "--gaze-units", "norm", "--scale",
                            "250", "--png-bits", "16"});
  EXPECT_DOUBLE_EQ(s.adaptation.rate_up_log_per_s, 1.5);
  EXPECT_EQ(s.sink.video.crf, 23);
  EXPECT_FALSE(s.encoding.dither);
  EXPECT_EQ(s.gaze_units, "norm");
  EXPECT_DOUBLE_EQ(*s.exr.scale, 250.0);
  EXPECT_EQ(s.sink.png_bits, 16);
}

TEST(Parameters, OutOfRangeAndMalformedValuesNameTheParameter) {
  EXPECT_NE(usage_error({"--crf", "99"}).find("--crf"), std::string::npos);
  EXPECT_NE(usage_error({"--crf", "99"}).find("0 to 51"), std::string::npos);
  EXPECT_NE(usage_error({"--crf", "1.5"}).find("whole number"), std::string::npos);
  EXPECT_NE(usage_error({"--gamma", "abc"}).find("--gamma"), std::string::npos);
  EXPECT_NE(usage_error({"--gaze-units", "mm"}).find("px|norm"), std::string::npos);
  EXPECT_NE(usage_error({"--png-bits", "12"}).find("--png-bits"), std::string::npos);
}

TEST(Parameters, ConfigFileAppliesAndTheCommandLineWins) {
  test::ScratchDir dir;
  std::ofstream(dir / "c.json") << R"({"adapt-rate-down": 0.5, "crf": 30, "dither": false, "x264-preset": "fast"})";
  const Settings s = parse({"--crf", "20"}, dir / "c.json");
  EXPECT_DOUBLE_EQ(s.adaptation.rate_down_log_per_s, 0.5);
  EXPECT_EQ(s.sink.video.crf, 20);
  EXPECT_FALSE(s.encoding.dither);
  EXPECT_EQ(s.sink.video.preset, "fast");
}

TEST(Parameters, ConfigFileErrorsNameTheFileAndKey) {
  test::ScratchDir dir;
  std::ofstream(dir / "bad.json") << R"({"no-such-thing": 1})";
  std::ofstream(dir / "range.json") << R"({"crf": 80})";
  EXPECT_NE(usage_error({}, dir / "bad.json").find("no-such-thing"), std::string::npos);
  const std::string range = usage_error({}, dir / "range.json");
  EXPECT_NE(range.find("range.json"), std::string::npos);
  EXPECT_NE(range.find("--crf"), std::string::npos);
  std::ofstream(dir / "broken.json") << "{";
  EXPECT_THROW(parse({}, dir / "broken.json"), InputError);
}

// A misspelt key names the parameter it was probably meant to be.
TEST(Parameters, AnUnknownKeySuggestsTheNearestOne) {
  test::ScratchDir dir;
  std::ofstream(dir / "typo.json") << R"({"viewer_age": 70})";
  EXPECT_NE(usage_error({}, dir / "typo.json").find("did you mean 'viewer-age'?"), std::string::npos)
      << usage_error({}, dir / "typo.json");
  std::ofstream(dir / "close.json") << R"({"adapt-rate-upp": 1})";
  EXPECT_NE(usage_error({}, dir / "close.json").find("did you mean 'adapt-rate-up'?"), std::string::npos);
  std::ofstream(dir / "far.json") << R"({"zzzzzzzzzz": 1})";
  EXPECT_EQ(usage_error({}, dir / "far.json").find("did you mean"), std::string::npos) << "nothing near";
  std::ofstream(dir / "gazes.json") << R"({"Gaz": "g.csv"})";
  EXPECT_NE(usage_error({}, dir / "gazes.json").find("the run's --gaze"), std::string::npos)
      << usage_error({}, dir / "gazes.json");
  std::ofstream(dir / "gaze.json") << R"({"gaze": "g.csv"})";
  EXPECT_NE(usage_error({}, dir / "gaze.json").find("'gaze' is the run's --gaze, which goes on the command line"), std::string::npos)
      << usage_error({}, dir / "gaze.json");
}

TEST(Parameters, EveryDeclarationHasHelpAndAValidDefault) {
  Settings s;
  const ParamSet params = run_parameters(s);
  for (const Param& p : params.params()) {
    EXPECT_FALSE(p.help.empty()) << p.name;
    const std::string value = ParamSet::value_text(p);
    if (value != "unset") {
      EXPECT_NO_THROW(ParamSet::set_text(p, value, "")) << p.name << " default " << value;
    }
  }
}

}  // namespace
}  // namespace eyestream::pipeline
