#include "pipeline/preview/preview.hpp"

#include <algorithm>
#include <cstdio>
#include <opencv2/imgproc.hpp>

namespace eyestream::pipeline {

namespace {

const cv::Scalar kWhite(1, 1, 1), kBlack(0, 0, 0), kMarker(1.0, 0.8, 0.0);  // R, G, B

// White text with a dark outline, readable on any background.
void burn_text(cv::Mat& img, const std::string& text, cv::Point at, double scale) {
  const int thick = std::max(1, int(scale * 2));
  cv::putText(img, text, at, cv::FONT_HERSHEY_SIMPLEX, scale, kBlack, thick + 2, cv::LINE_8);
  cv::putText(img, text, at, cv::FONT_HERSHEY_SIMPLEX, scale, kWhite, thick, cv::LINE_8);
}

void burn_marker(cv::Mat& panel, double x, double y, double radius) {
  const cv::Point c{int(x), int(y)};
  const int r = std::max(3, int(radius + 0.5));
  cv::circle(panel, c, r, kBlack, 3, cv::LINE_8);
  cv::circle(panel, c, r, kMarker, 1, cv::LINE_8);
}

}  // namespace

cv::Mat compose_preview(const std::vector<PanelView>& panels, const PreviewOptions& o, double time_s,
                        std::int64_t frame_index) {
  const bool labels = o.labels || panels.size() > 1;
  if (panels.size() == 1 && !labels && !o.gaze && !o.timecode) return panels[0].linear;
  const cv::Size size = panels[0].linear.size();
  cv::Mat out(size.height, size.width * int(panels.size()), CV_32FC3);
  const double scale = std::max(0.35, size.height / 720.0);
  for (size_t i = 0; i < panels.size(); ++i) {
    cv::Mat panel = out(cv::Rect(int(i) * size.width, 0, size.width, size.height));
    panels[i].linear.copyTo(panel);
    if (o.gaze && !panels[i].eye_closed) burn_marker(panel, panels[i].gaze_x, panels[i].gaze_y, o.marker_radius_px);
    if (labels) burn_text(panel, panels[i].label, {int(10 * scale), int(40 * scale)}, scale);
  }
  if (o.timecode) {
    char text[64];
    std::snprintf(text, sizeof(text), "frame %lld  %.3f s", (long long)frame_index, time_s);
    burn_text(out, text, {int(10 * scale), size.height - int(14 * scale)}, scale);
  }
  return out;
}

}  // namespace eyestream::pipeline
