// A video's frames as FFmpeg's own decoder gives them: the tests' oracle
// for what the program's writer put in a file.
#pragma once

#include <functional>
#include <string>

extern "C" {
#include <libavutil/frame.h>
}

namespace eyestream::test {

// Calls `take` with each decoded frame of the file's best video stream, in
// presentation order, until it returns false or the frames end. Returns
// how many frames it was given, or -1 if the file cannot be opened.
int for_each_decoded_frame(const std::string& path, const std::function<bool(const AVFrame&)>& take);

}  // namespace eyestream::test
