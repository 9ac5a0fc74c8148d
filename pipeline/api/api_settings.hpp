// What the library's entry points share (not installed): settings given by
// name compiled as the command line compiles its options, and the command
// line's exceptions turned into eyestream::Error with its exit codes.
#pragma once

#include <map>
#include <opencv2/core.hpp>
#include <string>

#include "eyestream/eye.hpp"
#include "io/error.hpp"
#include "pipeline/settings/settings.hpp"

namespace eyestream {

template <typename F>
auto translated(F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const UsageError& e) {
    throw Error(e.what(), 2);
  } catch (const InputError& e) {
    throw Error(e.what(), 3);
  } catch (const OutputError& e) {
    throw Error(e.what(), 4);
  } catch (const cv::Exception& e) {
    throw Error(e.what(), 2);
  }
}

// Names as on the command line ("viewer-age"; "_" may stand for "-"),
// "quality" choosing the preset the others override; "report" = "true"
// asks for the frame's veil and TI. UsageError naming a bad one.
pipeline::Settings compile_settings(const std::map<std::string, std::string>& given);

}  // namespace eyestream
