// Video transfer functions, for HDR video input and HDR10 output:
// SMPTE ST 2084 (PQ, absolute), ARIB STD-B67 / ITU-R BT.2100 HLG (relative,
// with its system gamma), and the BT.1886 display of SDR video.
#pragma once

namespace eyestream::io {

// PQ: non-linear signal E' in [0, 1] to display luminance in cd/m^2
// (10 000 at E' = 1), and back (ST 2084 eqs. 4.1, 5.2; BT.2100 Table 4).
double pq_to_luminance(double signal);
double luminance_to_pq(double cd_m2);

// HLG: signal E' in [0, 1] to normalised scene light E in [0, 1] (the
// inverse OETF of BT.2100 Table 5), and back.
double hlg_to_scene(double signal);
double scene_to_hlg(double scene);
// HLG system gamma for a display of nominal peak Lw cd/m^2 (BT.2100 note
// 5f): 1.2 + 0.42 log10(Lw / 1000).
double hlg_system_gamma(double peak_cd_m2);

// BT.1886 display (zero black level): L = Lw E'^2.4, relative here.
double bt1886_to_linear(double signal);

}  // namespace eyestream::io
