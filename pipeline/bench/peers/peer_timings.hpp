// Two peers of eyestream, timed on the bench's own frames for `eyestream
// bench --peers`:
// - pfstools' pfstmo_pattanaik00 -t: Pattanaik, Tumblin, Yee and Greenberg,
//   "Time-dependent visual adaptation for fast realistic image display"
//   (SIGGRAPH 2000), global temporal adaptation only. The EXR frames become
//   one pfs stream first (pfsinexr, untimed); the time is the operator's
//   whole run over that stream (reading and writing pfs included), per
//   frame, with the time of copying the stream (`cat`) beside it.
// - Blender's compositor Glare node, Fog Glow (quality high, size 9, the
//   largest; threshold 0, so every pixel's light spreads; mix 0, the input
//   plus its glare): glare only. The time is the fastest of the compositing
//   runs after the first (which also loads the image); no file is written.
#pragma once

#include <filesystem>
#include <string>

namespace eyestream::pipeline {

struct PeerTiming {
  double ms_per_frame = 0.0;
  std::string failure;  // why the peer gave no time ("" when it did)
  double floor_ms_per_frame = -1.0;  // copying its input to its output with `cat`; -1: not measured
};

// pfsinexr and pfstmo_pattanaik00 as found on PATH; `frames` EXR frames
// dir/00000.exr on at `fps`; `work` takes the pfs streams.
PeerTiming time_pattanaik(const std::string& pfsinexr, const std::string& pfstmo,
                          const std::filesystem::path& frames_dir, int frames, double fps,
                          const std::filesystem::path& work);

// blender as found on PATH; `runs` compositing runs (at least 2) of one
// EXR frame; `work` takes the Python script Blender runs.
PeerTiming time_fog_glow(const std::string& blender, const std::filesystem::path& exr, int runs,
                         const std::filesystem::path& work);

}  // namespace eyestream::pipeline
