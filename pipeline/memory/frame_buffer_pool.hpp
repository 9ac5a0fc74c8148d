// Keeps the image buffers the frame loop frees for the next frame, which
// needs the same sizes. By default every full-frame cv::Mat is mapped from
// the system on allocation and unmapped on release, so each frame paid for
// millions of page faults and zeroed pages (about a fifth of the CPU time
// at 1080p). Output does not change, only where the memory comes from;
// small allocations, and everything not a cv::Mat, are left to malloc.
// Buffers of 2 MiB or more are mapped on huge-page boundaries and marked
// for transparent huge pages, so the set-up's first touch of them takes a
// fault per 2 MiB instead of per 4 KiB.
#pragma once

#include <cstddef>

namespace eyestream::pipeline {

// Makes the pool OpenCV's default allocator for every cv::Mat created from
// now on (call before the first frame; calling again does nothing).
void reuse_frame_buffers();

// Frees the buffers held for reuse that no frame has taken through the
// last 30 calls: the eye calls it after each frame, so the pool holds about
// the working set of the last second's frames, not every size a run has
// ever asked for (regions that follow the gaze take many sizes over a long
// run). Every eye's frame counts, so with several eyes (a preview's
// viewers) the window is shorter in frames of each.
void trim_frame_buffers();

// Frees every buffer held for reuse (the bench, before it measures a
// case's memory; `eyestream run`, after the set-up).
void release_frame_buffers();

// Bytes held for reuse now (for tests and the bench).
size_t pooled_frame_buffer_bytes();

// Blocks of 2 MiB or more the pool has mapped from the system itself so
// far (for tests: counting malloc sees every other block it takes).
unsigned long frame_buffers_mapped();

}  // namespace eyestream::pipeline
