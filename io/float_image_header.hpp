// The size a Radiance .hdr, PFM or TIFF file declares, read from its header
// before anything is decoded, so a tiny file claiming a huge image is
// refused without allocating it.
#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace eyestream::io {

// InputError naming the file when the header is malformed or declares a
// size that is not positive.
cv::Size float_image_size(const std::string& path);

}  // namespace eyestream::io
