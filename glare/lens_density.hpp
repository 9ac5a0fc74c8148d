// The crystalline lens's optical density and how it grows with age
// (Pokorny, Smith and Lutze 1987, "Aging of the human lens", Applied
// Optics 26(8), 1437-1440, Table I and eq. 1): the lens absorbs short
// wavelengths, more with every decade, so an older eye receives less blue.
#pragma once

#include <opencv2/core.hpp>

namespace eyestream::glare {

// The lens's optical density (log10 of 1 / transmittance) at lambda nm for
// a viewer `age_years` old: TL1 (1 + 0.02 (A - 32)) + TL2 up to 60 years,
// TL1 (1.56 + 0.0667 (A - 60)) + TL2 beyond, with Table I's TL1 and TL2
// (400 to 650 nm every 10 nm, linear between; 400 nm's below it, nothing
// above 650). The model starts at 20 years: younger ages take 20's.
double lens_density(double lambda_nm, double age_years);

// The change a viewer's lens makes to linear Rec.709 RGB against the
// observer of 32 years that Pokorny et al.'s formula is referred to, T =
// 10^-(D(age) - D(32)) (younger viewers get T above 1 in the blue): each display
// channel's spectrum taken as its colour-matching function s_c
// (non-negative Rec.709 CMFs), the filtered spectrum's least-squares
// coordinates in the s_k, M = G^-1 F with G[k][c] = integral of s_k s_c and
// F[k][c] = integral of s_k s_c T over 380-780 nm. The identity at 32;
// older, the blue channel loses most.
cv::Matx33f lens_filter_rgb(double age_years);

}  // namespace eyestream::glare
