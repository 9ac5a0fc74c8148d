// The run's inputs as its settings name them: the frame source and the
// gaze log's import options. Shared by `eyestream run` and the library's
// readers (eyestream/readers.hpp), so both read the same way.
#pragma once

#include <memory>

#include "io/frame_source.hpp"
#include "io/gaze_import.hpp"
#include "pipeline/settings/settings.hpp"

namespace eyestream::pipeline {

// The gaze log's import options (--gaze-format, --gaze-units, ...) for a
// stream described by `info`.
io::GazeImportOptions gaze_import_options(const Settings& settings, const io::SourceInfo& info);

// The frame source of settings.input (--fps, --scale, --layer, --video-*, --size).
std::unique_ptr<io::FrameSource> open_input(const Settings& settings);

}  // namespace eyestream::pipeline
