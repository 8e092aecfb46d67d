// The counts inside a serialized ROS1 message checked against its bytes before roscpp
// deserializes it.
//
// roscpp's deserializer sizes every array by the 32-bit count in front of it (std::vector
// resize, elements default-constructed) before it reads a byte of it, so a damaged or hostile
// message asks for up to 4 G elements: fuzz_rosbag found a /tf message whose transforms count
// made it allocate 223 GB. Strings are safe (bounds checked before the copy). This walks the
// message types pedtrack reads, field by field, and refuses one whose any count or field does
// not fit in the bytes left. ROS-free: the template that uses it is pedtrack/ros_checked_message.h.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace pedtrack {

/// "" when the serialized message of ROS type `datatype` ("sensor_msgs/LaserScan",
/// "sensor_msgs/PointCloud2", "tf2_msgs/TFMessage", "nav_msgs/Odometry",
/// "geometry_msgs/PoseArray") holds exactly its fields, else the first fault ("the ranges
/// count 1000000000 does not fit in the 3,964 bytes left"). A type not listed is not checked:
/// "".
std::string rosWireProblem(const std::string& datatype, const std::uint8_t* data, std::size_t size);

}  // namespace pedtrack
