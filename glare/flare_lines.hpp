// Flare lines: the fine radial streaks of the ciliary corona and of the
// lenticular halo (Spencer et al. 1995 sec. 3.2). A random pattern of
// thin radial lines is multiplied into a PSF component and then scaled ring
// by ring (1 px rings about the centre) so that each ring keeps the energy
// it had: the streaks add detail without changing the PSF's radial profile
// or its total. Within 3 pixels of the centre, where every line overlaps,
// the PSF is left smooth. The corona (f1, f2) and the halo (f3) get two
// independent sets. The pattern belongs to the viewer's lens: it is a pure
// function of the viewer's seed, the same on every frame and every run.
//
// Line drawing follows the lens flare filter tutorial: angles jittered within equal sectors,
// lengths (0.2 + u) of the longest, clamped to it, intensity falling as
// 1 - (t / length)^2 along the line and as (1 - d / width)^2 across it.
// Lines come in pairs 180 deg apart, as a radial grating gives them
// (Matsuda and Ikedo). Myopic glasses raise their number and length (Matsuda and Ikedo; the
// factor 1.5 is this project's choice). A brighter source shows more and
// longer lines by itself: the pattern multiplies the PSF, so the dim ends
// and the weak lines cross the display's threshold only for bright lights.
// Haze thins them: lines weaker than the haze share go, and the rest lose
// that share of their contrast (Matsuda and Ikedo).
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "glare/viewer.hpp"

namespace eyestream::glare {

struct FlareLine {
  double angle_rad = 0;  // in [0, 2 pi)
  double length_deg = 0;
  double strength = 0;   // in [0, 1] (Spencer et al. 1995: random intensity)
};

struct FlareLineSet {
  std::vector<FlareLine> lines;  // sorted by angle
  double width_deg = 0.02;       // half width across a line (at least 1.5 frame pixels when drawn)
  // The pattern is (1 - contrast) + contrast S, S the sum of the lines
  // (each up to `strength`), before each ring is rescaled: where lines are
  // dense they carry most of the light, where they are sparse (far out) the
  // smooth floor does.
  double contrast = 0.9;
};

enum class FlareKind { corona, halo };

// The viewer's set for the corona or the halo.
FlareLineSet flare_lines(const ViewerProfile& viewer, FlareKind kind);

// The pattern's raw value (before ring normalisation) at the offset
// (dx, dy) pixels from the PSF centre, at pixels_per_degree, lines
// set.width_deg wide.
double flare_pattern(const FlareLineSet& set, double dx_px, double dy_px, double pixels_per_degree);

// Multiplies every kernel in `kernels` (CV_64F, centred, all the same size,
// at pixels_per_degree) by the set's pattern, ring-normalised for each
// kernel separately. Lines are at least 1.5 pixels of the frame (at
// frame_pixels_per_degree; 0: the kernel's own) wide; a kernel at a reduced
// resolution (the split engine's tail) takes the mean of the frame-resolution
// pattern over each of its pixels, so it matches the exact kernel's block sums.
void apply_flare_lines(const FlareLineSet& set, double pixels_per_degree, const std::vector<cv::Mat*>& kernels,
                       double frame_pixels_per_degree = 0.0);

}  // namespace eyestream::glare
