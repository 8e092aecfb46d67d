# Defines the INTERFACE target pedtrack_roscpp: a live ROS1 node (roscpp, tf2_ros listener and the
# geometry/visualization message headers) on top of pedtrack_ros1 (mrpt::ros1bridge conversions).
# Debian ships pkg-config files for roscpp and tf2_ros; message packages are header-only.
if(TARGET pedtrack_roscpp)
  return()
endif()
include(${CMAKE_CURRENT_LIST_DIR}/PedtrackRos1.cmake)
find_package(PkgConfig REQUIRED)
pkg_check_modules(PEDTRACK_ROSCPP IMPORTED_TARGET roscpp tf2_ros)
if(NOT PEDTRACK_ROSCPP_FOUND)
  message(FATAL_ERROR "PEDTRACK_WITH_ROS: roscpp/tf2_ros not found (Debian: libroscpp-dev "
    "libtf2-ros-dev, see scripts/install-deps.sh); configure with -DPEDTRACK_WITH_ROS=OFF to "
    "build without `pedtrack ros`")
endif()
foreach(hdr geometry_msgs/PoseArray.h visualization_msgs/MarkerArray.h sensor_msgs/PointCloud2.h)
  string(MAKE_C_IDENTIFIER ${hdr} _id)
  find_path(PEDTRACK_HDR_${_id} ${hdr})
  if(NOT PEDTRACK_HDR_${_id})
    message(FATAL_ERROR "PEDTRACK_WITH_ROS: ${hdr} not found (Debian: libgeometry-msgs-dev "
      "libvisualization-msgs-dev libsensor-msgs-dev); or -DPEDTRACK_WITH_ROS=OFF")
  endif()
endforeach()
add_library(pedtrack_roscpp INTERFACE)
target_link_libraries(pedtrack_roscpp INTERFACE pedtrack_ros1 PkgConfig::PEDTRACK_ROSCPP)
