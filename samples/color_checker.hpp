// The 24 patches of the X-Rite ColorChecker Classic as linear Rec.709
// reflectances (D65).
#pragma once

#include <array>
#include <opencv2/core.hpp>

namespace eyestream::samples {

// Row-major, 4 rows of 6: dark skin ... black. From the chart's published
// sRGB values (X-Rite, 2009 formulation), decoded with the sRGB transfer
// function. Patch 19 (white) reflects about 90 %.
const std::array<cv::Vec3f, 24>& color_checker_linear();

}  // namespace eyestream::samples
