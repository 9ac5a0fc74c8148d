// The Python module `eyestream` (pybind11): the library's Eye
// (eyestream/eye.hpp) for numpy arrays, with keyword settings named as
// the command line's options ("viewer_age" for --viewer-age). Frames that
// are float32 with their pixels packed are read in place; the GIL is
// released while a frame is processed.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <eyestream/eye.hpp>
#include <eyestream/readers.hpp>
#include <mutex>
#include <sstream>

#include "pipeline/settings/parameter.hpp"
#include "pipeline/settings/quality_presets.hpp"
#include "pipeline/settings/settings.hpp"

namespace py = pybind11;

namespace {

using eyestream::Eye;

std::string setting_text(const py::handle& v) {
  if (py::isinstance<py::bool_>(v)) return v.cast<bool>() ? "true" : "false";
  return py::str(v).cast<std::string>();
}

// Samples as (t, x, y[, closed[, lost[, pupil_mm]]]) rows: a sequence of
// tuples or an N x 3..6 array.
std::vector<eyestream::Gaze> gaze_samples(const py::object& gaze) {
  std::vector<eyestream::Gaze> out;
  if (gaze.is_none()) return out;
  for (const py::handle row : gaze) {
    const py::sequence s = py::reinterpret_borrow<py::sequence>(row);
    const size_t n = py::len(s);
    if (n < 3 || n > 6)
      throw py::value_error("a gaze sample is (t, x, y[, closed[, lost[, pupil_mm]]]), not " + std::to_string(n) +
                            " values");
    eyestream::Gaze g;
    g.t_s = s[0].cast<double>();
    g.x = s[1].cast<double>();
    g.y = s[2].cast<double>();
    g.closed = n > 3 && s[3].cast<double>() != 0.0;
    g.lost = n > 4 && s[4].cast<double>() != 0.0;
    if (n > 5 && !s[5].is_none()) g.pupil_mm = s[5].cast<double>();
    out.push_back(g);
  }
  return out;
}

// A numpy view of a cv::Mat that keeps the Mat (and its buffer) alive.
py::array to_numpy(const cv::Mat& m) {
  auto* owner = new cv::Mat(m);
  const py::capsule keep(owner, [](void* p) { delete static_cast<cv::Mat*>(p); });
  const std::vector<py::ssize_t> shape{m.rows, m.cols, m.channels()};
  const std::vector<py::ssize_t> strides{py::ssize_t(m.step[0]), py::ssize_t(m.elemSize()), py::ssize_t(m.elemSize1())};
  switch (m.depth()) {
    case CV_8U: return py::array(py::dtype::of<std::uint8_t>(), shape, strides, m.data, keep);
    case CV_16U: return py::array(py::dtype::of<std::uint16_t>(), shape, strides, m.data, keep);
    case CV_32F: return py::array(py::dtype::of<float>(), shape, strides, m.data, keep);
    case CV_64F: return py::array(py::dtype::of<double>(), shape, strides, m.data, keep);
    default: throw py::type_error("an image of an unexpected depth");
  }
}

bool is_float32(const py::array& a) { return a.dtype().kind() == 'f' && a.dtype().itemsize() == 4; }
bool is_float64(const py::array& a) { return a.dtype().kind() == 'f' && a.dtype().itemsize() == 8; }

cv::Mat from_numpy(const py::handle& object) {
  const py::array a = py::array::ensure(object);
  if (!a) throw py::type_error("a state matrix is a numpy array");
  if (a.ndim() != 3) throw py::value_error("a state matrix is rows x cols x channels");
  const auto rows = int(a.shape(0)), cols = int(a.shape(1)), channels = int(a.shape(2));
  int depth = -1;
  if (is_float32(a)) depth = CV_32F;
  if (is_float64(a)) depth = CV_64F;
  if (depth < 0 || channels < 1 || channels > 4) throw py::value_error("a state matrix is float32 or float64 with 1-4 channels");
  if (rows == 0 || cols == 0) return cv::Mat();
  const py::array packed = py::array::ensure(a, py::array::c_style);
  return cv::Mat(rows, cols, CV_MAKETYPE(depth, channels), const_cast<void*>(packed.data())).clone();
}

// The eye and what its last frame gave. One frame at a time: the GIL is
// released while a frame is processed, so another thread may call in; the
// lock keeps each eye's calls one after another.
struct PyEye {
  explicit PyEye(Eye e) : eye(std::move(e)) {}
  Eye eye;
  eyestream::Frame last;
  mutable std::mutex busy;

  py::array process(const py::array& frame, const py::object& gaze) {
    const int w = eye.width(), h = eye.height();
    if (frame.ndim() != 3 || frame.shape(0) != h || frame.shape(1) != w || frame.shape(2) != 3) {
      std::ostringstream shape;
      for (py::ssize_t i = 0; i < frame.ndim(); ++i) shape << (i ? "x" : "") << frame.shape(i);
      throw eyestream::Error("frame: a " + shape.str() + " array, not " + std::to_string(h) + "x" + std::to_string(w) + "x3", 2);
    }
    const std::vector<eyestream::Gaze> samples = gaze_samples(gaze);
    // float32 with each row's pixels packed is read where it lies; anything
    // else is converted first.
    const bool packed = is_float32(frame) && frame.strides(2) == 4 && frame.strides(1) == 12 &&
                        frame.strides(0) >= 12 * w;
    const py::array held =
        packed ? frame : py::array(py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(frame));
    if (!held) throw py::type_error("frame: not convertible to float32");
    const auto* pixels = static_cast<const float*>(held.data());
    const size_t stride = size_t(held.strides(0));
    eyestream::Frame out;
    {
      py::gil_scoped_release unlocked;
      const std::lock_guard<std::mutex> one_at_a_time(busy);
      last = eye.process(pixels, stride, samples);
      out = last;
    }
    return to_numpy(out.linear);
  }

  py::dict report() const {
    const std::lock_guard<std::mutex> one_at_a_time(busy);
    const eyestream::FrameReport r = last.report;
    py::dict d;
    d["adaptation_cd_m2"] = r.adaptation_cd_m2;
    d["pupil_mm"] = r.pupil_mm;
    d["pupil_model_mm"] = r.pupil_model_mm;
    d["gaze_x"] = r.gaze_x;
    d["gaze_y"] = r.gaze_y;
    d["eye_closed"] = r.eye_closed;
    d["glare"] = r.glare;
    d["retina"] = r.retina;
    d["mesopic"] = r.mesopic;
    d["afterimages"] = r.afterimages;
    d["peak_cd_m2"] = r.peak_cd_m2;
    d["veil_cd_m2"] = r.veil_cd_m2;
    d["ti_percent"] = r.ti_percent;
    d["target_cd_m2"] = r.target_cd_m2;
    d["background_cd_m2"] = r.background_cd_m2;
    d["target_veil_cd_m2"] = r.target_veil_cd_m2;
    d["nonfinite_pixels"] = r.nonfinite_pixels;
    d["glare_ms"] = r.glare_ms;
    d["adaptation_ms"] = r.adaptation_ms;
    d["retina_ms"] = r.retina_ms;
    d["mesopic_ms"] = r.mesopic_ms;
    d["afterimage_ms"] = r.afterimage_ms;
    return d;
  }

  void set_gaze(const py::object& recording) {
    const std::vector<eyestream::Gaze> samples = gaze_samples(recording);
    const std::lock_guard<std::mutex> one_at_a_time(busy);
    eye.set_gaze(samples);
  }

  py::array code() const {
    const std::lock_guard<std::mutex> one_at_a_time(busy);
    return to_numpy(last.code);
  }

  py::tuple state() const {
    const std::lock_guard<std::mutex> one_at_a_time(busy);
    const Eye::State s = eye.state();
    py::list mats;
    for (const cv::Mat& m : s.mats) mats.append(m.empty() ? py::array(py::dtype::of<float>(), std::vector<py::ssize_t>{0, 0, 3}) : to_numpy(m));
    return py::make_tuple(mats, s.numbers);
  }

  void restore(const py::tuple& t) {
    if (py::len(t) != 2) throw eyestream::Error("the eye's state is malformed", 2);
    Eye::State s;
    for (const py::handle m : t[0].cast<py::list>()) s.mats.push_back(from_numpy(m));
    s.numbers = t[1].cast<std::vector<double>>();
    const std::lock_guard<std::mutex> one_at_a_time(busy);
    eye.restore(s);
  }
};

// The run command's parameters as the keywords take them, from the table
// that makes the command line (pipeline/settings/settings.hpp), at their defaults
// under `quality`.
std::vector<eyestream::pipeline::Param> parameters_of(eyestream::pipeline::Settings& s, const std::string& quality) {
  eyestream::pipeline::apply_quality_preset(quality, s);
  return eyestream::pipeline::run_parameters(s).params();
}

std::string keyword(std::string name) {
  for (char& c : name)
    if (c == '-') c = '_';
  return name;
}

std::string eye_doc() {
  eyestream::pipeline::Settings s;
  std::ostringstream doc;
  doc << "Eye(width, height, fps, **settings)\n\n"
         "One viewer's eye for a width x height stream at fps frames/s. The settings are the options of\n"
         "`eyestream run`, '-' written '_' (viewer_age=70, quality=\"fast\"); \"quality\" picks the preset the\n"
         "others override. Defaults below are those of quality=\"balanced\".\n\n";
  for (const auto& p : parameters_of(s, "balanced")) {
    doc << "  " << keyword(p.name);
    if (!p.unit.empty()) doc << " [" << p.unit << "]";
    doc << ": " << p.help << " (default " << eyestream::pipeline::ParamSet::value_text(p) << ")\n";
  }
  return doc.str();
}

std::map<std::string, std::string> named_settings(const py::kwargs& settings) {
  std::map<std::string, std::string> named;
  for (const auto& [k, v] : settings) named[k.cast<std::string>()] = setting_text(v);
  return named;
}

// The frames of an input, one (frame, t, index) at a time; the GIL is
// released while a frame is read.
struct PyFrames {
  explicit PyFrames(eyestream::FrameReader r) : reader(std::move(r)) {}
  eyestream::FrameReader reader;
  mutable std::mutex busy;

  // A property of the input, read under the lock next() holds.
  template <typename F>
  auto read(F f) const {
    const std::lock_guard<std::mutex> one_at_a_time(busy);
    return f(reader);
  }

  py::tuple next() {
    eyestream::InputFrame f;
    bool got = false;
    {
      py::gil_scoped_release unlocked;
      const std::lock_guard<std::mutex> one_at_a_time(busy);
      got = reader.next(f);
    }
    if (!got) throw py::stop_iteration();
    return py::make_tuple(to_numpy(f.rgb_cd_m2), f.time_s, f.index);
  }
};

}  // namespace

PYBIND11_MODULE(eyestream, m) {
  m.doc() = "eyestream: HDR frames through a model of one viewer's eye (adaptation, glare, mesopic vision, "
            "afterimages), frame by frame from numpy.";
  static py::exception<eyestream::Error> error(m, "Error");
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const eyestream::Error& e) {
      PyErr_SetObject(error.ptr(), py::make_tuple(e.what(), e.exit_code()).ptr());
    }
  });
  m.attr("__version__") = EYESTREAM_VERSION;

  py::class_<PyEye>(m, "Eye", eye_doc().c_str())
      .def(py::init([](int width, int height, double fps, const py::kwargs& settings) {
             return new PyEye(Eye(width, height, fps, named_settings(settings)));
           }),
           py::arg("width"), py::arg("height"), py::arg("fps"))
      .def("process", &PyEye::process, py::arg("frame"), py::arg("gaze") = py::none(),
           "process(frame, gaze=None) -> the display-linear image (float32 HxWx3, 1 = the display's peak).\n\n"
           "frame: HxWx3 linear Rec.709 RGB in cd/m^2 (float32 with packed pixels is read in place, anything\n"
           "else converted). gaze: the samples (t, x, y[, closed[, lost[, pupil_mm]]]) inside the frame's interval\n"
           "[n / fps, (n + 1) / fps), in seconds and frame pixels; without samples the last gaze holds.")
      .def("set_gaze", &PyEye::set_gaze, py::arg("recording"),
           "set_gaze(recording): the whole gaze recording, samples (t, x, y[, closed[, lost[, pupil_mm]]]), read\n"
           "as the command line reads a log (the first sample held back to frame 0, recorded pupils bridged\n"
           "across blinks); process() then takes no gaze. An empty recording goes back to gaze per frame.")
      .def_property_readonly("code", &PyEye::code,
                             "the last frame encoded for the display and dithered (uint8 HxWx3; uint16 with png_bits=16)")
      .def_property_readonly("report", &PyEye::report, "what happened to the last frame (a dict)")
      .def("state", &PyEye::state, "the eye's state between frames (a copy), for restore()")
      .def("restore", &PyEye::restore, py::arg("state"), "resume from a state() of an eye with the same settings")
      .def("describe", [](const PyEye& e) { return e.eye.describe(); }, "the resolved settings, one per line")
      .def_property_readonly("width", [](const PyEye& e) { return e.eye.width(); })
      .def_property_readonly("height", [](const PyEye& e) { return e.eye.height(); })
      .def_property_readonly("fps", [](const PyEye& e) { return e.eye.fps(); });

  m.def(
      "psf",
      [](int width, int height, double adaptation, const py::kwargs& settings) {
        const std::map<std::string, std::string> named = named_settings(settings);
        eyestream::Psf p;
        {
          py::gil_scoped_release unlocked;
          p = eyestream::psf(width, height, adaptation, named);
        }
        py::dict out;
        out["kernel"] = to_numpy(p.kernel);
        out["pixels_per_degree"] = p.pixels_per_degree;
        out["pupil_mm"] = p.pupil_mm;
        return out;
      },
      py::arg("width"), py::arg("height"), py::arg("adaptation") = 10.0,
      "psf(width, height, adaptation=10.0, **settings) -> {'kernel', 'pixels_per_degree', 'pupil_mm'}\n\n"
      "The viewer's point-spread function as the glare stage uses it for a width x height frame, the eye\n"
      "adapted to `adaptation` cd/m^2; settings as for Eye (viewer_age=70, psf_model=\"cie\", ...). kernel:\n"
      "float32 (2 height - 1) x (2 width - 1) x 3 (R, G, B), centred on (height - 1, width - 1); each\n"
      "channel sums to the share of a pixel's light spread within the frame's reach.");

  py::class_<PyFrames>(m, "Frames",
                       "Frames(path, **settings): the frames of an input as `eyestream run -i` reads it (EXR\n"
                       "sequence, HDR video, .hdr/.pfm/.tif stills), iterated as (frame, t, index): frame float32\n"
                       "HxWx3 linear Rec.709 in cd/m^2, t seconds from the first frame. Settings are the input\n"
                       "options (fps, scale, layer, video_transfer, video_peak, skip_missing, ...).")
      .def(py::init([](const std::string& path, const py::kwargs& settings) {
             return new PyFrames(eyestream::FrameReader(path, named_settings(settings)));
           }),
           py::arg("path"))
      .def("__iter__", [](PyFrames& f) -> PyFrames& { return f; })
      .def("__next__", &PyFrames::next)
      .def_property_readonly("width", [](const PyFrames& f) { return f.read([](const auto& r) { return r.width(); }); })
      .def_property_readonly("height", [](const PyFrames& f) { return f.read([](const auto& r) { return r.height(); }); })
      .def_property_readonly("fps", [](const PyFrames& f) { return f.read([](const auto& r) { return r.fps(); }); })
      .def_property_readonly("frame_count", [](const PyFrames& f) { return f.read([](const auto& r) { return r.frame_count(); }); })
      .def_property_readonly("description", [](const PyFrames& f) { return f.read([](const auto& r) { return r.description(); }); });

  m.def(
      "read_gaze",
      [](const std::string& path, int width, int height, double fps, const py::kwargs& settings) {
        const std::vector<eyestream::Gaze> gaze = eyestream::read_gaze(path, width, height, fps, named_settings(settings));
        py::array_t<double> out(std::vector<py::ssize_t>{py::ssize_t(gaze.size()), 6});
        auto a = out.mutable_unchecked<2>();
        for (size_t i = 0; i < gaze.size(); ++i) {
          const eyestream::Gaze& g = gaze[i];
          const double row[6] = {g.t_s, g.x, g.y, g.closed ? 1.0 : 0.0, g.lost ? 1.0 : 0.0, g.pupil_mm};
          for (int c = 0; c < 6; ++c) a(py::ssize_t(i), c) = row[c];
        }
        return out;
      },
      py::arg("path"), py::arg("width"), py::arg("height"), py::arg("fps"),
      "read_gaze(path, width, height, fps, **settings) -> float64 N x 6 (t, x, y, closed, lost, pupil_mm)\n\n"
      "A gaze log or eye-tracker export as `eyestream run -g` reads it for a width x height stream at fps\n"
      "frames/s: seconds from the first frame, frame pixels, pupil_mm NaN when not recorded. Settings are the\n"
      "gaze options (gaze_format, gaze_units, gaze_sync, gaze_recording, gaze_pupil_scale, ...). Rows of a\n"
      "frame's interval are what Eye.process takes as its gaze.");

  m.def(
      "parameters",
      [](const std::string& quality) {
        eyestream::pipeline::Settings s;
        py::list out;
        for (const auto& p : parameters_of(s, quality)) {
          py::dict d;
          d["name"] = keyword(p.name);
          d["option"] = "--" + p.name;
          d["unit"] = p.unit;
          d["help"] = p.help;
          d["default"] = eyestream::pipeline::ParamSet::value_text(p);
          d["choices"] = p.choices;
          out.append(d);
        }
        return out;
      },
      py::arg("quality") = "balanced", "the settings Eye takes, with their units, defaults under `quality` and help");
}
