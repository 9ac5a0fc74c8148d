# Finds the OpenCV component libraries eyestream uses from Debian's
# per-module -dev packages, which ship no CMake package config: core and
# imgproc for the program and library (the imported target
# OpenCVParts::OpenCVParts, required), and imgcodecs for the tests only
# (OpenCVParts::imgcodecs, defined when found), which read and write
# pictures with it as an oracle. The program does not link imgcodecs: its
# dependencies (GDAL and about 70 more libraries) were loaded at every
# start, and `eyestream --version` took 0.21 s with them and 0.10 s
# without (docs/performance.md); PNG goes through libpng (io/png_file.hpp).
find_path(OpenCVParts_INCLUDE_DIR opencv2/core.hpp PATH_SUFFIXES opencv4)
foreach(part core imgproc imgcodecs)
  find_library(OpenCVParts_${part}_LIBRARY NAMES opencv_${part})
endforeach()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(OpenCVParts REQUIRED_VARS
  OpenCVParts_INCLUDE_DIR OpenCVParts_core_LIBRARY OpenCVParts_imgproc_LIBRARY)
if(OpenCVParts_FOUND AND NOT TARGET OpenCVParts::OpenCVParts)
  add_library(OpenCVParts::OpenCVParts INTERFACE IMPORTED)
  set_target_properties(OpenCVParts::OpenCVParts PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${OpenCVParts_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${OpenCVParts_core_LIBRARY};${OpenCVParts_imgproc_LIBRARY}")
endif()
if(OpenCVParts_imgcodecs_LIBRARY AND NOT TARGET OpenCVParts::imgcodecs)
  add_library(OpenCVParts::imgcodecs INTERFACE IMPORTED)
  set_target_properties(OpenCVParts::imgcodecs PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${OpenCVParts_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${OpenCVParts_imgcodecs_LIBRARY}")
endif()
