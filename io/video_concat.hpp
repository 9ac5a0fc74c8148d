// Joins chunk videos made with the same settings into one file without
// re-encoding (packets copied), for `eyestream concat`.
#pragma once

#include <string>
#include <vector>

namespace eyestream::io {

// The inputs' first video streams, in order, into `output` (its container
// from the extension, staged then renamed). Timestamps are kept: chunks
// carry their frames' times from the input, so they follow on. InputError
// for an unreadable input, one whose codec or size differs from the first,
// or whose timestamps overlap the previous one's; OutputError for the output.
void concat_videos(const std::vector<std::string>& inputs, const std::string& output);

}  // namespace eyestream::io
