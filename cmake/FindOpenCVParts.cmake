# Finds the OpenCV component libraries eyestream uses (core, imgproc,
# imgcodecs) from Debian's per-module -dev packages, which ship no CMake
# package config. Defines the imported target OpenCVParts::OpenCVParts.
find_path(OpenCVParts_INCLUDE_DIR opencv2/core.hpp PATH_SUFFIXES opencv4)
set(_parts core imgproc imgcodecs)
set(OpenCVParts_LIBRARIES)
foreach(part IN LISTS _parts)
  find_library(OpenCVParts_${part}_LIBRARY NAMES opencv_${part})
  list(APPEND OpenCVParts_LIBRARIES ${OpenCVParts_${part}_LIBRARY})
endforeach()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(OpenCVParts REQUIRED_VARS
  OpenCVParts_INCLUDE_DIR OpenCVParts_core_LIBRARY
  OpenCVParts_imgproc_LIBRARY OpenCVParts_imgcodecs_LIBRARY)
if(OpenCVParts_FOUND AND NOT TARGET OpenCVParts::OpenCVParts)
  add_library(OpenCVParts::OpenCVParts INTERFACE IMPORTED)
  set_target_properties(OpenCVParts::OpenCVParts PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${OpenCVParts_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${OpenCVParts_LIBRARIES}")
endif()
