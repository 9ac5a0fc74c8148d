#include "pipeline/bench/peers/peer_timings.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include "pipeline/bench/peers/peer_program.hpp"

namespace eyestream::pipeline {

namespace {

// The Blender script: the frame through a Glare node into the Composite
// node, nothing rendered in 3D (no Render Layers node), each run timed.
constexpr const char* kFogGlowScript = R"(import sys, time
import bpy
args = sys.argv[sys.argv.index("--") + 1:]
image = bpy.data.images.load(args[0])
scene = bpy.context.scene
scene.render.resolution_x, scene.render.resolution_y = image.size
scene.render.resolution_percentage = 100
scene.render.use_compositing = True
scene.render.use_sequencer = False
scene.use_nodes = True
tree = scene.node_tree
for node in list(tree.nodes):
    tree.nodes.remove(node)
picture = tree.nodes.new("CompositorNodeImage")
picture.image = image
glare = tree.nodes.new("CompositorNodeGlare")
glare.glare_type = "FOG_GLOW"
glare.quality = "HIGH"
glare.size = 9
glare.mix = 0.0
glare.threshold = 0.0
out = tree.nodes.new("CompositorNodeComposite")
tree.links.new(picture.outputs["Image"], glare.inputs["Image"])
tree.links.new(glare.outputs["Image"], out.inputs["Image"])
for run in range(int(args[1])):
    start = time.perf_counter()
    bpy.ops.render.render(write_still=False)
    print("fog glow run %d: %.3f ms" % (run, 1000 * (time.perf_counter() - start)))
)";

std::string failed(const ProgramRun& run) {
  std::string tail = run.output.substr(run.output.size() > 300 ? run.output.size() - 300 : 0);
  std::replace(tail.begin(), tail.end(), '\n', ' ');
  return "exit " + std::to_string(run.exit_code) + ": " + tail;
}

}  // namespace

PeerTiming time_pattanaik(const std::string& pfsinexr, const std::string& pfstmo,
                          const std::filesystem::path& frames_dir, int frames, double fps,
                          const std::filesystem::path& work) {
  PeerTiming t;
  const std::string in = (work / "in.pfs").string(), out = (work / "out.pfs").string();
  const ProgramRun read = run_program(shell_quoted(pfsinexr) + " " + shell_quoted((frames_dir / "%05d.exr").string()) +
                                      " --frames 0:" + std::to_string(frames - 1) + " > " + shell_quoted(in));
  if (read.exit_code != 0) return {0.0, "pfsinexr " + failed(read), -1.0};
  char rate[32];
  std::snprintf(rate, sizeof rate, "%g", fps);
  const ProgramRun tmo = run_program(shell_quoted(pfstmo) + " -t --fps " + rate + " < " + shell_quoted(in) + " > " +
                                     shell_quoted(out));
  if (tmo.exit_code != 0) return {0.0, failed(tmo), -1.0};
  std::error_code ec;
  if (std::filesystem::file_size(out, ec) == 0 || ec) return {0.0, "wrote no frames", -1.0};
  t.ms_per_frame = tmo.wall_ms / frames;
  const ProgramRun copy = run_program("cat " + shell_quoted(in) + " > " + shell_quoted(out));
  if (copy.exit_code == 0) t.floor_ms_per_frame = copy.wall_ms / frames;
  std::filesystem::remove(in, ec);  // a 1080p frame is 25 MB of pfs each way
  std::filesystem::remove(out, ec);
  return t;
}

PeerTiming time_fog_glow(const std::string& blender, const std::filesystem::path& exr, int runs,
                         const std::filesystem::path& work) {
  const std::filesystem::path script = work / "fog_glow.py";
  std::ofstream(script) << kFogGlowScript;
  const ProgramRun run = run_program(shell_quoted(blender) + " -b --factory-startup --python-exit-code 1 --python " +
                                     shell_quoted(script.string()) + " -- " + shell_quoted(exr.string()) + " " +
                                     std::to_string(std::max(runs, 2)));
  if (run.exit_code != 0) return {0.0, failed(run), -1.0};
  double fastest = std::numeric_limits<double>::infinity();
  std::istringstream lines(run.output);
  for (std::string line; std::getline(lines, line);) {
    int index = 0;
    double ms = 0.0;
    if (std::sscanf(line.c_str(), "fog glow run %d: %lf ms", &index, &ms) == 2 && index > 0)
      fastest = std::min(fastest, ms);
  }
  if (!(fastest < std::numeric_limits<double>::infinity())) return {0.0, "printed no timed run", -1.0};
  return {fastest, "", -1.0};
}

}  // namespace eyestream::pipeline
