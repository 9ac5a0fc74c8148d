// Y'CbCr <-> R'G'B' by the standard's own arithmetic (BT.709, BT.2020 and
// BT.601 coefficients; BT.2100 limited and full range), in double, for
// planar video frames of 8 to 16 bits. It replaces swscale's 16-bit packed
// RGB path, which scales to 0xFF00 instead of 0xFFFF and read PQ video
// 1.5-3 % too dark (tests/hdr_video_oracle_test.cpp).
#pragma once

extern "C" {
#include <libavutil/frame.h>
#include <libavutil/pixfmt.h>
}

#include <opencv2/core.hpp>

namespace eyestream::io {

// Whether a decoded frame's format is planar Y'CbCr of 8 to 16 bits,
// native byte order, no alpha: the formats ycbcr_to_rgb() reads.
bool is_planar_ycbcr(AVPixelFormat format);

// R'G'B' (CV_32FC3, 1 = the format's white, not clamped) of a decoded
// planar Y'CbCr frame with the given matrix and range. Subsampled chroma
// is interpolated bilinearly from its sited positions (the frame's
// chroma_location; unspecified is left, as H.264 and HEVC assume).
cv::Mat ycbcr_to_rgb(const AVFrame& frame, AVColorSpace matrix, bool full_range);

// Fills a YUV420P10LE frame, limited range, from 16-bit R'G'B' codes
// (CV_16UC3, 65535 = white) with the given matrix; chroma left-sited
// (horizontal taps 1/4, 1/2, 1/4 at even columns, the two rows averaged).
void rgb_to_ycbcr420_10(const cv::Mat& code, AVColorSpace matrix, AVFrame& frame);

}  // namespace eyestream::io
