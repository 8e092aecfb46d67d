#pragma once
// Messages off the wire whatever their type (their conversion to MRPT observations is the
// rosbag source's: plugins/sensors/rosbag/ros_frames.h).
#include <ros/message_traits.h>
#include <ros/serialization.h>

#include <boost/make_shared.hpp>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "pedtrack/ros_checked_message.h"

namespace pedtrack::ros_plugins {

/// A message of any type. Subscribed with md5sum "*", one subscription takes whichever of
/// LaserScan or PointCloud2 the publisher sends (the type is not known before a publisher
/// exists); the connection header names the real type. topic_tools::ShapeShifter does the same,
/// but Debian does not package topic_tools.
struct AnyMessage {
  std::string datatype, md5sum;
  std::vector<std::uint8_t> data;

  /// The message as M, or null when it is of another type.
  template <class M>
  boost::shared_ptr<M> instantiate() const {
    if (datatype != ros::message_traits::datatype<M>() ||
        (md5sum != "*" && md5sum != ros::message_traits::md5sum<M>()))
      return nullptr;
    return checkedDeserialize<M>(data.data(), data.size());  // counts checked first
  }
};

}  // namespace pedtrack::ros_plugins

namespace ros {
namespace message_traits {
template <>
struct IsMessage<pedtrack::ros_plugins::AnyMessage> : TrueType {};
template <>
struct IsMessage<const pedtrack::ros_plugins::AnyMessage> : TrueType {};
// Asked without an instance (when subscribing) an AnyMessage is of any type, "*".
template <>
struct MD5Sum<pedtrack::ros_plugins::AnyMessage> {
  static const char* value() { return "*"; }
  static const char* value(const pedtrack::ros_plugins::AnyMessage& m) { return m.md5sum.c_str(); }
};
template <>
struct DataType<pedtrack::ros_plugins::AnyMessage> {
  static const char* value() { return "*"; }
  static const char* value(const pedtrack::ros_plugins::AnyMessage& m) {
    return m.datatype.c_str();
  }
};
template <>
struct Definition<pedtrack::ros_plugins::AnyMessage> {
  static const char* value() { return ""; }
  static const char* value(const pedtrack::ros_plugins::AnyMessage&) { return ""; }
};
}  // namespace message_traits

namespace serialization {
template <>
struct Serializer<pedtrack::ros_plugins::AnyMessage> {
  template <typename Stream>
  static void write(Stream& stream, const pedtrack::ros_plugins::AnyMessage& m) {
    std::memcpy(stream.advance(static_cast<std::uint32_t>(m.data.size())), m.data.data(),
                m.data.size());
  }
  template <typename Stream>
  static void read(Stream& stream, pedtrack::ros_plugins::AnyMessage& m) {
    m.data.assign(stream.getData(), stream.getData() + stream.getLength());
  }
  static std::uint32_t serializedLength(const pedtrack::ros_plugins::AnyMessage& m) {
    return static_cast<std::uint32_t>(m.data.size());
  }
};
// The publisher's connection header says what the bytes are.
template <>
struct PreDeserialize<pedtrack::ros_plugins::AnyMessage> {
  static void notify(const PreDeserializeParams<pedtrack::ros_plugins::AnyMessage>& p) {
    p.message->datatype = (*p.connection_header)["type"];
    p.message->md5sum = (*p.connection_header)["md5sum"];
  }
};
}  // namespace serialization
}  // namespace ros
