// Linear Rec.709 RGB <-> LMS cone space, and the afterimage colour matrix H
// (Jacobs et al. 2015 App. A).
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace eyestream::retina {

// RGB -> LMS: Rec.709 RGB to CIE XYZ (D65), then the Hunt-Pointer-Estevez
// cone matrix normalised to D65. Normalisation: RGB white (1,1,1) of
// luminance Y maps to L = M = S = Y, so a neutral stimulus excites the three
// cone types equally, as Jacobs et al. 2015 fig. 4 assumes ("white (stimulating all
// cone types equally) flash"); cone stimuli are in cd/m^2-equivalents.
const Eigen::Matrix3d& rgb_to_lms();
const Eigen::Matrix3d& lms_to_rgb();

// Bleaching (LMS) -> RGB afterimage colour (Jacobs et al. 2015 App. A matrix H).
const Eigen::Matrix3d& afterimage_matrix();

// The same matrices as OpenCV types, for cv::transform.
cv::Matx33f rgb_to_lms_f();
cv::Matx33f lms_to_rgb_f();
cv::Matx33f afterimage_matrix_f();

}  // namespace eyestream::retina
