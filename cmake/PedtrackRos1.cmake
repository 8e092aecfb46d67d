# Defines the INTERFACE target pedtrack_ros1: ROS1 bag reading (rosbag_storage), tf2 and
# mrpt::ros1bridge. Debian's catkin-generated CMake configs for rosbag_storage pull in
# ament/pluginlib machinery (and a Python module) just to report paths, so libraries and headers
# are found directly.
if(TARGET pedtrack_ros1)
  return()
endif()
find_package(mrpt-ros1bridge REQUIRED)
set(_ros_libs)
foreach(lib rosbag_storage tf2 roscpp_serialization rostime cpp_common console_bridge)
  find_library(PEDTRACK_ROS_${lib} NAMES ${lib} REQUIRED)
  list(APPEND _ros_libs ${PEDTRACK_ROS_${lib}})
endforeach()
# rosbag/bag.h includes pluginlib (encryption plugins), whose ROS 2 headers live one level deeper.
set(_ros_includes)
foreach(pkg pluginlib class_loader rcpputils rcutils ament_index_cpp)
  find_path(PEDTRACK_INC_${pkg} ${pkg} PATH_SUFFIXES ${pkg} NO_DEFAULT_PATH PATHS /usr/include /usr/local/include)
  if(PEDTRACK_INC_${pkg})
    list(APPEND _ros_includes ${PEDTRACK_INC_${pkg}})
  endif()
endforeach()
add_library(pedtrack_ros1 INTERFACE)
target_link_libraries(pedtrack_ros1 INTERFACE mrpt::ros1bridge ${_ros_libs})
target_include_directories(pedtrack_ros1 SYSTEM INTERFACE ${_ros_includes})
