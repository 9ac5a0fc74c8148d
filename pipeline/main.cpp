// The eyestream command-line program.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include "io/library_logging.hpp"
#include "io/error.hpp"
#include "io/frame_sequence.hpp"
#include "io/source_factory.hpp"
#include "io/video_concat.hpp"
#include "io/staged_file.hpp"
#include "pipeline/memory/frame_buffer_pool.hpp"
#include "pipeline/memory/malloc_arenas.hpp"
#include "pipeline/bench/bench_chart.hpp"
#include "pipeline/bench/bench_command.hpp"
#include "pipeline/bench/peers/bench_peers.hpp"
#include "pipeline/run/chunk_plan.hpp"
#include "pipeline/tools/command_reference.hpp"
#include "pipeline/tools/compare_command.hpp"
#include "pipeline/tools/curves_command.hpp"
#include "pipeline/run/exit_codes.hpp"
#include "pipeline/run/output_paths.hpp"
#include "pipeline/settings/parameter.hpp"
#include "pipeline/tools/psf_command.hpp"
#include "pipeline/settings/quality_presets.hpp"
#include "pipeline/report/report_charts.hpp"
#include "pipeline/run/run.hpp"
#include "pipeline/settings/settings.hpp"
#include "samples/scene.hpp"

namespace {

using namespace eyestream;
using namespace eyestream::pipeline;

std::string scene_list() {
  std::string text = "Scenes:\n";
  for (const samples::Scene& s : samples::scenes()) text += "  " + s.name + ": " + s.summary + "\n";
  return text;
}

int fail(ExitCode code, const std::string& message) {
  std::fprintf(stderr, "eyestream: error: %s\n", message.c_str());
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  limit_malloc_arenas();
  reuse_frame_buffers();
  CLI::App app{
      "eyestream: filters HDR video through a model of one viewer's eye and writes what that viewer "
      "would see on an ordinary display."};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "every option of every command");
  app.set_version_flag("--version", std::string("eyestream ") + EYESTREAM_VERSION);

  // The defaults --help shows are those of the preset the command line
  // names (or the default one): the table takes its defaults from the
  // settings it is built on.
  Settings settings;
  for (int i = 1; i + 1 < argc; ++i)
    if (std::string(argv[i]) == "--quality") settings.quality = argv[i + 1];
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]).rfind("--quality=", 0) == 0) settings.quality = std::string(argv[i]).substr(10);
  try {
    apply_quality_preset(settings.quality, settings);
  } catch (const UsageError&) {
    apply_quality_preset(Settings().quality, settings);  // reported when the command line is read
  }
  ParamSet params = run_parameters(settings);
  CLI::App* run_cmd = app.add_subcommand(
      "run", "filter an HDR frame sequence with a gaze log (defaults shown for --quality " + settings.quality + ")");
  run_cmd
      ->add_option("-i,--input", settings.input,
                   "EXR sequence (frames/%05d.exr, folder or file), HDR video, .hdr/.pfm stills, or - (raw float "
                   "RGB on standard input, with --size)")
      ->required();
  run_cmd->add_option("-g,--gaze", settings.gaze, "gaze log CSV (t,x,y[,event]); none: fixed gaze at the centre");
  run_cmd->add_option("-o,--output", settings.output,
                      "output: video.mp4 or .mkv, frames/%05d.png, frames/%05d.exr, or - (video on standard output)")
      ->required();
  run_cmd->add_option("--config", settings.config, "JSON file of parameter values (command line wins)");
  bool yes = false;  // -y, the short --overwrite
  run_cmd->add_flag("-y", yes, "replace outputs that exist (as --overwrite)");
  bool run_quiet = false;  // -q, the short --quiet, as the other commands take it
  run_cmd->add_flag("-q", run_quiet, "nothing on stderr but warnings and errors (as --quiet)");
  params.bind(*run_cmd);

  samples::SceneOptions scene;
  std::string scene_name;
  CLI::App* sample_cmd =
      app.add_subcommand("sample", "generate a built-in scene: DIR/frames/%05d.exr and DIR/gaze.csv");
  sample_cmd->footer(scene_list());
  sample_cmd->add_option("scene", scene_name, "scene name")->required();
  sample_cmd->add_option("-o,--output", scene.out_dir, "output folder")->required();
  bool replace_scene = false;
  bool quiet_tool = false;  // --quiet for the commands other than run: no informational line on stderr
  const auto add_quiet = [&quiet_tool](CLI::App* cmd) {
    cmd->add_flag("-q,--quiet", quiet_tool, "nothing on stderr but warnings and errors");
  };
  sample_cmd->add_flag("-y,--overwrite", replace_scene, "replace a scene the folder holds (its old frames go)");
  add_quiet(sample_cmd);
  sample_cmd->add_option("--width", scene.width, "frame width [px]")->check(CLI::Range(16, 8192));
  sample_cmd->add_option("--height", scene.height, "frame height [px]")->check(CLI::Range(16, 8192));
  sample_cmd->add_option("--fps", scene.fps, "frame rate [1/s]")->check(CLI::Range(1.0, 1000.0));
  sample_cmd->add_option("--duration", scene.duration_s, "length [s]; 0: the scene's own")
      ->check(CLI::Range(0.0, 3600.0));
  sample_cmd->add_option("--seed", scene.seed, "seed of the scene's random choices");
  sample_cmd->add_option("--luminance", scene.luminance_cd_m2, "the scene's key luminance [cd/m^2]; 0: its own")
      ->check(CLI::Range(0.0, 1e12));

  Settings psf_settings;
  PsfRequest psf;
  ParamSet psf_params = run_parameters(psf_settings).subset({"Viewing condition", "Glare (the viewer's optics)"});
  bool replace_files = false;  // -y for the commands that write files of their own
  CLI::App* psf_cmd = app.add_subcommand("psf", "write the viewer's point-spread function (EXR and a log-scale PNG)");
  psf_cmd->add_option("-o,--output", psf.output, "kernel EXR; the picture goes beside it as .png")->required();
  psf_cmd->add_flag("-y,--overwrite", replace_files, "replace the outputs if they exist");
  psf_cmd->add_option("--width", psf.width, "frame width the kernel is for [px]")->check(CLI::Range(16, 8192));
  psf_cmd->add_option("--height", psf.height, "frame height [px]")->check(CLI::Range(16, 8192));
  psf_cmd->add_option("--adaptation", psf.adaptation_log, "adaptation level [log10 cd/m^2] (sets pupil and regime)")
      ->check(CLI::Range(-8.0, 10.0));
  psf_params.bind(*psf_cmd);

  Settings curve_settings;
  std::string curves_output;
  ParamSet curve_params = run_parameters(curve_settings).subset({"Retina"});
  CLI::App* curves_cmd = app.add_subcommand("curves", "draw the tone-curve family for the tone settings (PNG)");
  curves_cmd->add_option("-o,--output", curves_output, "PNG file")->required();
  curves_cmd->add_flag("-y,--overwrite", replace_files, "replace the output if it exists");
  curve_params.bind(*curves_cmd);

  std::string report_csv, report_png;
  CLI::App* report_cmd = app.add_subcommand("report", "draw the charts of a run's --report CSV (PNG)");
  report_cmd->add_option("csv", report_csv, "the report CSV of `eyestream run --report`")->required();
  report_cmd->add_option("-o,--output", report_png, "PNG file (default: the CSV's name with .png)");
  report_cmd->add_flag("-y,--overwrite", replace_files, "replace the output if it exists");
  add_quiet(report_cmd);

  CompareOptions cmp;
  CLI::App* compare_cmd = app.add_subcommand(
      "compare", "compare two outputs frame by frame (PNG/EXR sequences or videos); exit 0 pass, 1 warn, 2 fail");
  compare_cmd->add_option("a", cmp.a, "the reference: a PNG or EXR sequence (pattern, folder, file) or a video")
      ->required();
  compare_cmd->add_option("b", cmp.b, "the output to judge, of the same kind")->required();
  compare_cmd
      ->add_option("--metric", cmp.metric,
                   "what --warn and --fail judge, on the worst frame: visible (the share of pixels beyond "
                   "--de-warn and --de-threshold, as idiff judges), de99, demax, max, mean or psnr")
      ->check(CLI::IsMember({"visible", "de99", "demax", "max", "mean", "psnr"}))
      ->capture_default_str();
  compare_cmd->add_option("--warn", cmp.warn,
                          "warn beyond this (visible: a share of pixels, default 0; others default 0.5; psnr: below it)");
  compare_cmd->add_option("--fail", cmp.fail,
                          "fail beyond this (visible: a share of pixels, default 0; others default 1; psnr: below it)");
  compare_cmd->add_option("--de-threshold", cmp.de_threshold, "a pixel beyond this CIEDE2000 differs visibly (fails)")
      ->check(CLI::Range(0.0, 100.0))
      ->capture_default_str();
  compare_cmd->add_option("--de-warn", cmp.de_warn, "a pixel beyond this CIEDE2000 warns (with --metric visible)")
      ->check(CLI::Range(0.0, 100.0))
      ->capture_default_str();
  compare_cmd->add_option("--diff-out", cmp.diff_out, "CIEDE2000 heat maps: a PNG pattern (diff/%05d.png)");
  compare_cmd->add_flag("-y,--overwrite", replace_files, "replace heat maps and the JSON report that exist");
  compare_cmd->add_option("--diff-scale", cmp.diff_scale, "CIEDE2000 at full scale in the heat maps")
      ->check(CLI::Range(0.01, 100.0))
      ->capture_default_str();
  compare_cmd->add_option("--json", cmp.json, "write per-frame and overall metrics here");
  compare_cmd->add_option("--layer", cmp.layer, "layered EXRs: the layer to compare (default: the beauty pass)");
  compare_cmd->add_flag("--verbose", cmp.verbose, "a line per frame");

  ChunkRequest chunks;
  chunks.program = argv[0];
  Settings chunk_input;
  CLI::App* chunks_cmd = app.add_subcommand(
      "chunks", "print one `eyestream run` command per chunk of a long input (for GNU parallel or Slurm)");
  chunks_cmd->add_option("-i,--input", chunks.input, "the input, as for run")->required();
  chunks_cmd->add_option("-o,--output", chunks.output, "chunk videos (chunk_%03d.mp4) or a shared frame pattern")
      ->required();
  chunks_cmd->add_option("--chunk-frames", chunks.chunk_frames, "frames written per chunk")->required();
  chunks_cmd->add_option("--preroll", chunks.preroll_s, "seconds processed before each chunk, not written")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  chunks_cmd->add_option("run-options", chunks.run_options, "options for every chunk's run, after --");
  chunks_cmd->allow_extras(false);
  add_quiet(chunks_cmd);

  std::vector<std::string> concat_inputs;
  std::string concat_output;
  CLI::App* concat_cmd =
      app.add_subcommand("concat", "join chunk videos (made with the same settings) without re-encoding");
  concat_cmd->add_option("-o,--output", concat_output, "the joined video (.mp4 or .mkv)")->required();
  concat_cmd->add_flag("-y,--overwrite", replace_files, "replace the output if it exists");
  concat_cmd->add_option("inputs", concat_inputs, "chunk videos in order")->required();
  add_quiet(concat_cmd);

  BenchRequest bench;
  int bench_threads = 0;
  CLI::App* bench_cmd = app.add_subcommand(
      "bench", "time each quality preset per stage on a built-in scene and measure its error against reference");
  bench_cmd->add_option("--scene", bench.scene, "built-in scenes, comma-separated (the skip study uses the first)")->capture_default_str();
  bench_cmd->add_option("--sizes", bench.sizes, "frame sizes: 720p, 1080p, 4k or WxH, comma-separated")
      ->capture_default_str();
  bench_cmd->add_option("--presets", bench.presets, "presets, comma-separated (reference first: the yardstick)")
      ->capture_default_str();
  bench_cmd->add_option("--frames", bench.frames, "frames per case at 30 frames/s (the scene's gaze story compressed into them)")
      ->check(CLI::Range(2, 100000))
      ->capture_default_str();
  bench_cmd->add_flag("!--no-skip-study", bench.skip_study,
                      "leave out balanced with and without --no-skip on a dim still frame and on the scene");
  bench_cmd->add_option("--flare-model", bench.flare_model, "every case's flare lines: drawn or wave (run --help)")
      ->check(CLI::IsMember({"drawn", "wave"}))
      ->capture_default_str();
  bench_cmd->add_flag("--peers", bench.peers,
                      "also time pfstmo_pattanaik00 -t and Blender's Fog Glow on the same frames, where installed");
  bench_cmd->add_option("--csv", bench.csv, "write the table as CSV");
  bench_cmd->add_option("--png", bench.png, "draw error against time per frame (PNG)");
  bench_cmd->add_flag("-y,--overwrite", replace_files, "replace the CSV and the chart if they exist");
  bench_cmd->add_option("--threads", bench_threads, "worker threads; 0 uses all cores")->check(CLI::Range(0, 1024));
  add_quiet(bench_cmd);

  std::string reference_format = "md", reference_output;
  CLI::App* reference_cmd = app.add_subcommand(
      "reference", "write this command reference, generated from the option declarations (Markdown or a man page)");
  reference_cmd->add_option("--format", reference_format, "md (docs/commands.md) or man (docs/eyestream.1)")
      ->check(CLI::IsMember({"md", "man"}))
      ->capture_default_str();
  reference_cmd->add_option("-o,--output", reference_output, "file (default: standard output)");
  reference_cmd->add_flag("-y,--overwrite", replace_files, "replace the file if it exists");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e) == 0 ? kExitOk : kExitUsage;
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e) == 0 ? kExitOk : kExitUsage;
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e) == 0 ? kExitOk : kExitUsage;
  } catch (const CLI::ParseError& e) {
    // One line, as for every other refusal: the parser's message, and where
    // to look.
    return fail(kExitUsage, std::string(e.what()) + " (see --help)");
  }

  io::set_library_verbosity(settings.verbose);  // every command; run sets it again after the config file
  try {
    if (*run_cmd) {
      // The preset first, then the config file and the command line again:
      // an explicit value wins over the preset.
      params.apply(settings.config);
      apply_quality_preset(settings.quality, settings);
      params.apply(settings.config);
      settings.overwrite = settings.overwrite || yes;
      settings.quiet = settings.quiet || run_quiet;
      if (settings.print_plan) {
        for (const Param& p : params.params())
          std::printf("%s = %s\n", p.name.c_str(), ParamSet::value_text(p).c_str());
        std::printf("%s", describe_run(settings).c_str());
        return kExitOk;
      }
      const RunSummary summary = run(settings);
      if (!settings.quiet || summary.interrupted_by) std::fprintf(stderr, "%s\n", summary.one_line().c_str());
      if (summary.interrupted_by) return 128 + summary.interrupted_by;
    } else if (*bench_cmd) {
      std::vector<OutputPath> outputs;
      if (!bench.csv.empty()) require_extension(bench.csv, {".csv"}, "--csv"), outputs.push_back({bench.csv, "--csv"});
      if (!bench.png.empty()) require_extension(bench.png, {".png"}, "--png"), outputs.push_back({bench.png, "--png"});
      if (!replace_files) refuse_existing(outputs);  // before minutes of work
      cv::setNumThreads(bench_threads > 0 ? bench_threads : -1);
      bench.quiet = quiet_tool;
      const std::vector<BenchRow> rows = run_bench(bench);
      std::printf("%s", bench_table(rows).c_str());
      if (!bench.csv.empty()) write_bench_csv(rows, bench.csv);
      if (!bench.png.empty()) draw_bench_chart(rows, bench.png);
      if (bench.peers) std::printf("\n%s", peers_table(run_peers(bench)).c_str());
    } else if (*curves_cmd) {
      curve_params.apply("");
      require_extension(curves_output, {".png"}, "curves -o");
      if (!replace_files) refuse_existing({{curves_output, "-o"}});
      write_tone_curves(curve_settings.tone, curves_output);
    } else if (*psf_cmd) {
      psf_params.apply("");
      require_extension(psf.output, {".exr"}, "psf -o");
      if (!replace_files)
        refuse_existing({{psf.output, "-o"},
                         {std::filesystem::path(psf.output).replace_extension(".png").string(), "-o's picture"}});
      std::printf("%s", write_psf(psf_settings, psf).text().c_str());
    } else if (*compare_cmd) {
      if (!cmp.diff_out.empty() && !io::is_printf_pattern(cmp.diff_out))
        throw UsageError("--diff-out '" + cmp.diff_out + "': expected a printf pattern such as diff/%05d.png");
      if (!cmp.diff_out.empty()) {
        require_extension(cmp.diff_out, {".png"}, "--diff-out");
        if (!replace_files) refuse_existing({{cmp.diff_out, "--diff-out"}});
      }
      if (!cmp.json.empty() && !replace_files) refuse_existing({{cmp.json, "--json"}});
      const CompareResult r = compare(cmp);
      std::printf("%s", r.text.c_str());
      return r.exit_code;
    } else if (*chunks_cmd) {
      const std::unique_ptr<io::FrameSource> source = io::open_source(chunks.input, io::SourceOptions{});
      const std::vector<Chunk> plan = plan_chunks(chunks, source->info().frame_count);
      for (const Chunk& c : plan) std::printf("%s\n", c.command.c_str());
      if (!quiet_tool)
        std::fprintf(stderr, "eyestream: %zu chunks of up to %lld frames, %.2f s pre-roll each\n", plan.size(),
                     (long long)chunks.chunk_frames, chunks.preroll_s);
    } else if (*concat_cmd) {
      require_extension(concat_output, {".mp4", ".mkv"}, "concat -o");
      if (!replace_files) refuse_existing({{concat_output, "-o"}});
      io::concat_videos(concat_inputs, concat_output);
      if (!quiet_tool)
        std::fprintf(stderr, "eyestream: joined %zu videos into %s\n", concat_inputs.size(), concat_output.c_str());
    } else if (*report_cmd) {
      if (report_png.empty()) report_png = std::filesystem::path(report_csv).replace_extension(".png").string();
      require_extension(report_png, {".png"}, "report -o");
      if (!replace_files) refuse_existing({{report_png, "-o"}});
      draw_report_file(report_csv, report_png);
      if (!quiet_tool) std::fprintf(stderr, "eyestream: wrote %s\n", report_png.c_str());
    } else if (*reference_cmd) {
      const std::string text = reference_format == "man" ? man_page(app) : markdown_reference(app);
      if (reference_output.empty()) {
        std::fputs(text.c_str(), stdout);
      } else {
        if (!replace_files) refuse_existing({{reference_output, "-o"}});
        io::StagedFile file(reference_output);
        io::write_all(file, std::vector<unsigned char>(text.begin(), text.end()));
        file.commit();
      }
    } else if (*sample_cmd) {
      const samples::Scene& s = samples::find_scene(scene_name);
      if (!replace_scene)
        refuse_existing({{scene.out_dir + "/gaze.csv", "the scene's gaze log"},
                         {scene.out_dir + "/frames/%05d.exr", "the scene's frames"}});
      s.generate(scene);
      if (!quiet_tool) std::fprintf(stderr, "eyestream: wrote scene %s to %s\n", s.name.c_str(), scene.out_dir.c_str());
    }
    return kExitOk;
  } catch (const Interrupted& e) {
    return fail(ExitCode(128 + e.signal), e.what());
  } catch (const UsageError& e) {
    return fail(kExitUsage, e.what());
  } catch (const InputError& e) {
    return fail(kExitInput, e.what());
  } catch (const OutputError& e) {
    return fail(kExitOutput, e.what());
  } catch (const std::exception& e) {
    return fail(kExitInternal, std::string("internal error: ") + e.what());
  }
}
