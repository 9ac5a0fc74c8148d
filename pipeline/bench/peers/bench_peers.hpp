// `eyestream bench --peers`: eyestream beside two programs that model part
// of what it does (peer_timings.hpp), on the same frames of each bench
// scene and size, in one run:
// - pfstmo_pattanaik00 -t per frame against eyestream `fast` with every
//   effect on every frame (--no-skip), the filter and the 8-bit display
//   encoding (the bytes a sink is given), per frame;
// - Blender's Fog Glow on the scene's middle frame against eyestream
//   `fast`'s glare stage per frame (Blender's fastest run against
//   eyestream's mean), with that stage's energy error: the difference of
//   the total light of `fast`'s retinal image and `reference`'s exact
//   engine's on the same frame, relative to the light the exact engine
//   moved out of its pixels (the largest over the three channels).
// A peer not on PATH is reported as skipped, not as a failure.
#pragma once

#include <string>
#include <vector>

#include "pipeline/bench/bench_command.hpp"

namespace eyestream::pipeline {

struct PeerRow {
  std::string peer, scene, size;
  std::string skipped;          // why there is no time ("" when there is)
  double peer_ms = 0.0;         // the peer, per frame
  double floor_ms = -1.0;       // of which copying its input and output; -1: not measured
  double eyestream_ms = 0.0;    // what it is measured against, per frame
  double target = 0.0;          // the ratio asked for (issue #18)
  double energy_error = -1.0;   // glare only; -1 elsewhere
};

// Every peer on every scene and size of the request.
std::vector<PeerRow> run_peers(const BenchRequest& request);

// The rows as an aligned text table, with what each compares.
std::string peers_table(const std::vector<PeerRow>& rows);

}  // namespace eyestream::pipeline
