// How many malloc arenas the program's threads share. glibc gives a
// thread that allocates while another holds an arena one of its own (up to
// eight per core), and each arena keeps memory freed into it for reuse
// by its threads: the decoder, the writer, x264's and OpenCV's threads
// each held some (docs/performance.md gives the measured difference). The
// frame loop's images come from the buffer pool (frame_buffer_pool.hpp),
// so malloc serves small blocks, which two arenas hold as well.
#pragma once

namespace eyestream::pipeline {

// At most two arenas, unless MALLOC_ARENA_MAX says otherwise. Call before
// starting threads: the command-line program calls it first; a program
// using the library decides for itself. Does nothing without glibc.
void limit_malloc_arenas();

}  // namespace eyestream::pipeline
