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
# The bag structure check run before rosbag_storage reads a bag (pedtrack/bag_check.h), the
# re-indexing of a bag cut short (pedtrack/bag_recover.h) and the
# message count check run before roscpp deserializes a message (pedtrack/ros_wire_check.h): used by
# the rosbag source plugin and by `pedtrack eval --truth BAG`, so a static library of its own.
find_library(PEDTRACK_BZ2 NAMES bz2 REQUIRED)
find_library(PEDTRACK_ROSLZ4 NAMES roslz4 REQUIRED)
add_library(pedtrack_bag_check STATIC ${PROJECT_SOURCE_DIR}/framework/src/bag_check.cpp
  ${PROJECT_SOURCE_DIR}/framework/src/bag_recover.cpp
  ${PROJECT_SOURCE_DIR}/framework/src/ros_wire_check.cpp)
set_target_properties(pedtrack_bag_check PROPERTIES POSITION_INDEPENDENT_CODE ON)
target_link_libraries(pedtrack_bag_check PUBLIC pedtrack_core PRIVATE ${PEDTRACK_BZ2}
  ${PEDTRACK_ROSLZ4})
target_compile_options(pedtrack_bag_check PRIVATE -Wall -Wextra)
add_library(pedtrack_ros1 INTERFACE)
target_link_libraries(pedtrack_ros1 INTERFACE mrpt::ros1bridge ${_ros_libs} pedtrack_bag_check)
target_include_directories(pedtrack_ros1 SYSTEM INTERFACE ${_ros_includes})
