#include "io/ycbcr.hpp"

extern "C" {
#include <libavutil/pixdesc.h>
}

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace eyestream::io {

namespace {

struct Coefficients {
  double kr, kb;
};

Coefficients coefficients(AVColorSpace m) {
  switch (m) {
    case AVCOL_SPC_BT2020_NCL:
    case AVCOL_SPC_BT2020_CL: return {0.2627, 0.0593};
    case AVCOL_SPC_BT470BG:
    case AVCOL_SPC_SMPTE170M: return {0.299, 0.114};
    default: return {0.2126, 0.0722};  // BT.709, and unspecified
  }
}

// A plane's sample at (x, y), 8 or 16 bits a sample.
double sample(const AVFrame& f, int plane, int x, int y, bool wide) {
  const uint8_t* row = f.data[plane] + std::ptrdiff_t(y) * f.linesize[plane];
  return wide ? double(reinterpret_cast<const std::uint16_t*>(row)[x]) : double(row[x]);
}

}  // namespace

bool is_planar_ycbcr(AVPixelFormat format) {
  const AVPixFmtDescriptor* d = av_pix_fmt_desc_get(format);
  if (!d || d->nb_components != 3) return false;
  if (!(d->flags & AV_PIX_FMT_FLAG_PLANAR) || (d->flags & (AV_PIX_FMT_FLAG_RGB | AV_PIX_FMT_FLAG_BE |
                                                            AV_PIX_FMT_FLAG_PAL | AV_PIX_FMT_FLAG_FLOAT |
                                                            AV_PIX_FMT_FLAG_BITSTREAM | AV_PIX_FMT_FLAG_HWACCEL)))
    return false;
  for (int c = 0; c < 3; ++c)
    if (d->comp[c].plane != c || d->comp[c].shift != 0 || d->comp[c].depth < 8 || d->comp[c].depth > 16 ||
        d->comp[c].step != (d->comp[c].depth > 8 ? 2 : 1))
      return false;
  return d->log2_chroma_w <= 1 && d->log2_chroma_h <= 1;
}

cv::Mat ycbcr_to_rgb(const AVFrame& f, AVColorSpace matrix, bool full_range) {
  const AVPixFmtDescriptor* d = av_pix_fmt_desc_get(AVPixelFormat(f.format));
  const int depth = d->comp[0].depth;
  const bool wide = depth > 8;
  const double scale = std::ldexp(1.0, depth - 8);
  // Code to normalised Y' in [0, 1] and C' in [-0.5, 0.5] (BT.2100 table 9).
  const double y_off = full_range ? 0.0 : 16 * scale, y_gain = full_range ? std::ldexp(1.0, depth) - 1 : 219 * scale;
  const double c_off = std::ldexp(1.0, depth - 1), c_gain = full_range ? std::ldexp(1.0, depth) - 1 : 224 * scale;
  const Coefficients k = coefficients(matrix);
  const double kg = 1.0 - k.kr - k.kb;
  const int sx = 1 << d->log2_chroma_w, sy = 1 << d->log2_chroma_h;
  const int cw = (f.width + sx - 1) / sx, ch = (f.height + sy - 1) / sy;
  // Where chroma sample (i, j) sits, in luma pixels: i sx + ox, j sy + oy.
  const AVChromaLocation loc = f.chroma_location == AVCHROMA_LOC_UNSPECIFIED ? AVCHROMA_LOC_LEFT : f.chroma_location;
  const bool left = loc == AVCHROMA_LOC_LEFT || loc == AVCHROMA_LOC_TOPLEFT || loc == AVCHROMA_LOC_BOTTOMLEFT;
  const bool top = loc == AVCHROMA_LOC_TOPLEFT || loc == AVCHROMA_LOC_TOP;
  const bool bottom = loc == AVCHROMA_LOC_BOTTOMLEFT || loc == AVCHROMA_LOC_BOTTOM;
  const double ox = sx == 1 || left ? 0.0 : (sx - 1) / 2.0;
  const double oy = sy == 1 || top ? 0.0 : bottom ? sy - 1.0 : (sy - 1) / 2.0;
  cv::Mat out(f.height, f.width, CV_32FC3);
  cv::parallel_for_(cv::Range(0, f.height), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      const double cy = std::clamp((y - oy) / sy, 0.0, double(ch - 1));
      const int j0 = int(cy), j1 = std::min(j0 + 1, ch - 1);
      const double fy = cy - j0;
      cv::Vec3f* o = out.ptr<cv::Vec3f>(y);
      for (int x = 0; x < f.width; ++x) {
        const double cx = std::clamp((x - ox) / sx, 0.0, double(cw - 1));
        const int i0 = int(cx), i1 = std::min(i0 + 1, cw - 1);
        const double fx = cx - i0;
        double c[2];
        for (int p = 1; p <= 2; ++p)
          c[p - 1] = ((sample(f, p, i0, j0, wide) * (1 - fx) + sample(f, p, i1, j0, wide) * fx) * (1 - fy) +
                      (sample(f, p, i0, j1, wide) * (1 - fx) + sample(f, p, i1, j1, wide) * fx) * fy -
                      c_off) /
                     c_gain;
        const double yp = (sample(f, 0, x, y, wide) - y_off) / y_gain;
        const double r = yp + 2 * (1 - k.kr) * c[1], b = yp + 2 * (1 - k.kb) * c[0];
        o[x] = cv::Vec3f(float(r), float((yp - k.kr * r - k.kb * b) / kg), float(b));
      }
    }
  });
  return out;
}

void rgb_to_ycbcr420_10(const cv::Mat& code, AVColorSpace matrix, AVFrame& f) {
  CV_Assert(code.type() == CV_16UC3 && f.format == AV_PIX_FMT_YUV420P10LE && code.cols <= f.width &&
            code.rows <= f.height);
  const Coefficients k = coefficients(matrix);
  const int w = f.width, h = f.height;
  // Y', Cb', Cr' of every pixel (the frame's padding replicates the edge).
  std::vector<double> cb(size_t(w) * h), cr(size_t(w) * h);
  const auto limited = [](double v, double offset, double gain) {
    return std::uint16_t(std::clamp(std::lround((gain * v + offset) * 4), 0L, 1023L));
  };
  cv::parallel_for_(cv::Range(0, h), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      const cv::Vec3w* in = code.ptr<cv::Vec3w>(std::min(y, code.rows - 1));
      std::uint16_t* luma = reinterpret_cast<std::uint16_t*>(f.data[0] + std::ptrdiff_t(y) * f.linesize[0]);
      for (int x = 0; x < w; ++x) {
        const cv::Vec3w p = in[std::min(x, code.cols - 1)];
        const double r = p[0] / 65535.0, g = p[1] / 65535.0, b = p[2] / 65535.0;
        const double yp = k.kr * r + (1 - k.kr - k.kb) * g + k.kb * b;
        luma[x] = limited(yp, 16, 219);
        cb[size_t(y) * w + x] = (b - yp) / (2 * (1 - k.kb));
        cr[size_t(y) * w + x] = (r - yp) / (2 * (1 - k.kr));
      }
    }
  });
  const int cw = (w + 1) / 2, ch = (h + 1) / 2;
  cv::parallel_for_(cv::Range(0, ch), [&](const cv::Range& rows) {
    for (int j = rows.start; j < rows.end; ++j) {
      const int y0 = 2 * j, y1 = std::min(2 * j + 1, h - 1);
      std::uint16_t* u = reinterpret_cast<std::uint16_t*>(f.data[1] + std::ptrdiff_t(j) * f.linesize[1]);
      std::uint16_t* v = reinterpret_cast<std::uint16_t*>(f.data[2] + std::ptrdiff_t(j) * f.linesize[2]);
      for (int i = 0; i < cw; ++i) {
        const int xl = std::max(2 * i - 1, 0), xc = 2 * i, xr = std::min(2 * i + 1, w - 1);
        const auto at = [&](const std::vector<double>& m) {
          const auto row = [&](int y) {
            return 0.25 * m[size_t(y) * w + xl] + 0.5 * m[size_t(y) * w + xc] + 0.25 * m[size_t(y) * w + xr];
          };
          return 0.5 * (row(y0) + row(y1));
        };
        u[i] = limited(at(cb), 128, 224);
        v[i] = limited(at(cr), 128, 224);
      }
    }
  });
}

}  // namespace eyestream::io
