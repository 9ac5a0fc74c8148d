// Layered EXRs as renderers write them (Blender's multilayer files name
// channels "ViewLayer.Combined.R", with depth, normal and other passes
// beside): the beauty pass by default, any colour layer by --layer, and a
// refusal listing the layers when the choice is not clear.
#include <gtest/gtest.h>

#include "io/error.hpp"
#include "io/exr_file.hpp"
#include "tests/test_support.hpp"

namespace eyestream::io {
namespace {

cv::Mat plane(float v) { return cv::Mat(4, 6, CV_32F, cv::Scalar(v)); }

void write_blender_like(const std::string& path) {
  write_exr_channels(path, {{"ViewLayer.Combined.R", plane(1)},
                            {"ViewLayer.Combined.G", plane(2)},
                            {"ViewLayer.Combined.B", plane(3)},
                            {"ViewLayer.Combined.A", plane(1)},
                            {"ViewLayer.Depth.Z", plane(7)},
                            {"ViewLayer.Emit.R", plane(10)},
                            {"ViewLayer.Emit.G", plane(20)},
                            {"ViewLayer.Emit.B", plane(30)},
                            {"ViewLayer.Normal.X", plane(0.5)},
                            {"ViewLayer.Normal.Y", plane(0.5)},
                            {"ViewLayer.Normal.Z", plane(0.5)}});
}

TEST(ExrLayers, TheBeautyPassByDefaultAndAnyColourLayerByName) {
  test::ScratchDir dir;
  write_blender_like(dir / "f.exr");
  ExrImage beauty = read_exr(dir / "f.exr", 1000);
  EXPECT_EQ(beauty.layer, "ViewLayer.Combined");
  EXPECT_EQ(beauty.channels, "RGBA");
  EXPECT_EQ(beauty.rgb.at<cv::Vec3f>(2, 3), cv::Vec3f(1, 2, 3));
  const ExrImage emit = read_exr(dir / "f.exr", 1000, "ViewLayer.Emit");
  EXPECT_EQ(emit.rgb.at<cv::Vec3f>(0, 0), cv::Vec3f(10, 20, 30));
  try {
    read_exr(dir / "f.exr", 1000, "ViewLayer.Glossy");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("holds ViewLayer.Combined, ViewLayer.Emit"), std::string::npos) << e.what();
  }
}

// Blender with two view layers writes a Combined for each: no guessing.
// A normal pass (X, Y, Z) is a vector, not a colour layer.
TEST(ExrLayers, TwoViewLayersBeautyPassesAreRefusedAndNormalsAreNotColour) {
  test::ScratchDir dir;
  write_exr_channels(dir / "views.exr",
                     {{"ViewLayer.Combined.R", plane(10)}, {"ViewLayer.Combined.G", plane(10)},
                      {"ViewLayer.Combined.B", plane(10)}, {"Background.Combined.R", plane(90)},
                      {"Background.Combined.G", plane(90)}, {"Background.Combined.B", plane(90)}});
  try {
    read_exr(dir / "views.exr", 1000);
    FAIL() << "two beauty passes (EXR lists channels by name)";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("several beauty passes (Background.Combined, ViewLayer.Combined)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(read_exr(dir / "views.exr", 1000, "Background.Combined").rgb.at<cv::Vec3f>(0, 0), cv::Vec3f(90, 90, 90));
  write_blender_like(dir / "f.exr");
  EXPECT_THROW(read_exr(dir / "f.exr", 1000, "ViewLayer.Normal"), InputError);
}

TEST(ExrLayers, SeveralColourLayersAndNoBeautyPassAreRefusedListingThem) {
  test::ScratchDir dir;
  write_exr_channels(dir / "two.exr", {{"left.R", plane(1)}, {"left.G", plane(1)}, {"left.B", plane(1)},
                                       {"right.R", plane(2)}, {"right.G", plane(2)}, {"right.B", plane(2)}});
  try {
    read_exr(dir / "two.exr", 1000);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("several colour layers (left, right)"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--layer"), std::string::npos);
  }
  EXPECT_EQ(read_exr(dir / "two.exr", 1000, "right").rgb.at<cv::Vec3f>(1, 1), cv::Vec3f(2, 2, 2));
  write_exr_channels(dir / "one.exr", {{"main.R", plane(4)}, {"main.G", plane(5)}, {"main.B", plane(6)}});
  EXPECT_EQ(read_exr(dir / "one.exr", 1000).rgb.at<cv::Vec3f>(0, 0), cv::Vec3f(4, 5, 6)) << "the only colour layer";
}

TEST(ExrLayers, TheCommandLineChoosesTheLayer) {
  test::ScratchDir dir;
  std::filesystem::create_directory(dir / "in");
  write_blender_like(dir / "in/f_0000.exr");
  write_blender_like(dir / "in/f_0001.exr");
  auto r = test::run_eyestream("run -i " + (dir / "in") + " -o " + (dir / "a/%05d.png") + " --layer ViewLayer.Emit");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  r = test::run_eyestream("run -i " + (dir / "in") + " -o " + (dir / "b/%05d.png") + " --layer Glossy");
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("no colour layer 'Glossy' (--layer)"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace eyestream::io
