# Finds only OpenCV's core, imgproc and imgcodecs modules.
# Debian ships OpenCV's CMake config in libopencv-dev, which depends on every module,
# highgui among them, and highgui pulls in Qt5. Finding the three modules directly keeps
# Qt5 out of the build and out of the process. Defines OpenCV::core, OpenCV::imgproc,
# OpenCV::imgcodecs.
find_path(OpenCVMinimal_INCLUDE_DIR opencv2/core.hpp PATH_SUFFIXES opencv4)
set(_ocv_vars OpenCVMinimal_INCLUDE_DIR)
foreach(_m core imgproc imgcodecs)
  find_library(OpenCVMinimal_${_m}_LIBRARY opencv_${_m})
  list(APPEND _ocv_vars OpenCVMinimal_${_m}_LIBRARY)
endforeach()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(OpenCVMinimal REQUIRED_VARS ${_ocv_vars})
if(OpenCVMinimal_FOUND)
  foreach(_m core imgproc imgcodecs)
    if(NOT TARGET OpenCV::${_m})
      add_library(OpenCV::${_m} UNKNOWN IMPORTED)
      set_target_properties(OpenCV::${_m} PROPERTIES
        IMPORTED_LOCATION "${OpenCVMinimal_${_m}_LIBRARY}"
        INTERFACE_INCLUDE_DIRECTORIES "${OpenCVMinimal_INCLUDE_DIR}")
    endif()
  endforeach()
endif()
