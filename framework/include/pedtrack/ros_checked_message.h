// Deserializing a ROS1 message only after its counts are checked (pedtrack/ros_wire_check.h).
// Header-only, for code built with the ROS1 parts.
#pragma once

#include <ros/message_traits.h>
#include <ros/serialization.h>

#include <boost/make_shared.hpp>
#include <boost/shared_ptr.hpp>
#include <cstdint>
#include <vector>

#include "pedtrack/errors.h"
#include "pedtrack/ros_wire_check.h"

namespace pedtrack {

/// The serialized message `bytes` as a T. Throws DataError naming the fault when a count inside
/// it does not fit its bytes, instead of letting roscpp allocate by it; roscpp's own exceptions
/// (a message cut short) pass through.
template <class T>
boost::shared_ptr<T> checkedDeserialize(const std::uint8_t* bytes, std::size_t size) {
  const char* type = ros::message_traits::DataType<T>::value();
  if (const std::string bad = rosWireProblem(type, bytes, size); !bad.empty())
    throw DataError("a " + std::string(type) + " message that does not fit its " +
                    std::to_string(size) + " bytes: " + bad);
  auto msg = boost::make_shared<T>();
  ros::serialization::IStream in(const_cast<std::uint8_t*>(bytes),
                                 static_cast<std::uint32_t>(size));
  ros::serialization::deserialize(in, *msg);
  return msg;
}

/// A bag's message as a T, or null when it is another type (as `m.instantiate<T>()`, whose
/// checks it adds). `m` is a rosbag::MessageInstance (getMD5Sum, size, write).
template <class T, class Message>
boost::shared_ptr<T> checkedInstantiate(const Message& m) {
  const std::string want = ros::message_traits::MD5Sum<T>::value();  // as MessageInstance::isType
  if (want != "*" && want != m.getMD5Sum()) return nullptr;
  std::vector<std::uint8_t> bytes(m.size());
  ros::serialization::OStream out(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
  m.write(out);
  return checkedDeserialize<T>(bytes.data(), bytes.size());
}

}  // namespace pedtrack
