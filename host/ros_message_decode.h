#pragma once
// A ROS1 message read from its own definition: the message_definition text a bag stores in each
// connection header (the main type's fields, then a "MSG: pkg/Type" section per type it uses).
// For message types pedtrack has no compiled code for, such as the leg_tracker benchmark's
// leg_tracker/Person. ROS-free: definition text and serialized bytes in, numbers out.
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace pedtrack::cli {

class RosMessageSchema {
 public:
  /// Parses the definition of `datatype` ("leg_tracker/Person"). Throws DataError naming the line
  /// for a field it cannot read or a type the definition does not define.
  RosMessageSchema(const std::string& datatype, const std::string& definition);

  /// Every numeric field of one serialized message by its dotted name ("pose.position.x", "id";
  /// array elements "ranges[3]"; time and duration in seconds). Strings are skipped. Throws
  /// DataError when the bytes end before the fields do, or a count does not fit what is left.
  std::map<std::string, double> numbers(const std::uint8_t* data, std::size_t size) const;

 private:
  struct Field {
    std::string type, name;
    long array = -1;  // -1: not an array; 0: variable length; n: fixed n
  };
  using Type = std::vector<Field>;
  void decode(const std::string& type, const std::string& prefix, const std::uint8_t*& p,
              const std::uint8_t* end, std::map<std::string, double>& out, int depth) const;

  std::string root_;
  std::map<std::string, Type> types_;
};

}  // namespace pedtrack::cli
