// The spectra of the eye's centred glare kernels on an FFT torus, for the
// FFT engines (fft_convolver.hpp, tiled_convolver.hpp).
#pragma once

#include <functional>
#include <opencv2/core.hpp>
#include <vector>

namespace eyestream::glare {

// The spectra of centred kernels (CV_64F, odd sizes) on an nx x ny torus
// (r2c layout: ny rows of nx / 2 + 1 complex values, as FFTW's
// fftw_complex), each handed to `keep(k, spectrum)` on the thread that
// made it, before its array is reused (an engine stores them in its own
// layout: no copy of all of them is made first). The eye's PSF is
// point-symmetric (radial, its flare lines drawn in pairs 180 degrees
// apart), so its spectrum is real: the engines keep only the real parts,
// half the memory and a third of the reads of complex ones. A kernel whose
// imaginary parts exceed 1e-9 of its largest value is refused (cv::Exception).
// One plan serves every kernel; the kernels are transformed in parallel,
// each through its own arrays (the values do not depend on the thread).
void kernel_spectra(const std::vector<const cv::Mat*>& kernels, int nx, int ny,
                    const std::function<void(int, const double (*)[2])>& keep);

}  // namespace eyestream::glare
