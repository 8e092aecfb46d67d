#include "ros_message_decode.h"

#include <cstdlib>
#include <cstring>
#include <sstream>

#include "pedtrack/errors.h"
#include "pedtrack/text.h"

namespace pedtrack::cli {
namespace {

// Bytes of each fixed-size primitive (time and duration: two 32-bit words).
const std::map<std::string, int>& primitiveSizes() {
  static const std::map<std::string, int> sizes = {
      {"bool", 1},  {"byte", 1},   {"char", 1},    {"int8", 1},   {"uint8", 1},
      {"int16", 2}, {"uint16", 2}, {"int32", 4},   {"uint32", 4}, {"float32", 4},
      {"int64", 8}, {"uint64", 8}, {"float64", 8}, {"time", 8},   {"duration", 8}};
  return sizes;
}

template <class T>
double read(const std::uint8_t* p) {
  T v;
  std::memcpy(&v, p, sizeof v);  // ROS1 is little-endian, as every machine pedtrack runs on
  return double(v);
}

double primitive(const std::string& type, const std::uint8_t* p) {
  if (type == "bool" || type == "byte" || type == "uint8" || type == "char")
    return read<std::uint8_t>(p);
  if (type == "int8") return read<std::int8_t>(p);
  if (type == "int16") return read<std::int16_t>(p);
  if (type == "uint16") return read<std::uint16_t>(p);
  if (type == "int32") return read<std::int32_t>(p);
  if (type == "uint32") return read<std::uint32_t>(p);
  if (type == "float32") return read<float>(p);
  if (type == "int64") return read<std::int64_t>(p);
  if (type == "uint64") return read<std::uint64_t>(p);
  if (type == "float64") return read<double>(p);
  if (type == "time") return read<std::uint32_t>(p) + 1e-9 * read<std::uint32_t>(p + 4);
  return read<std::int32_t>(p) + 1e-9 * read<std::int32_t>(p + 4);  // duration
}

std::string packageOf(const std::string& type) {
  const auto slash = type.find('/');
  return slash == std::string::npos ? std::string() : type.substr(0, slash);
}

constexpr int kMaxDepth = 16;  // nested types; a definition deeper than this is refused

}  // namespace

RosMessageSchema::RosMessageSchema(const std::string& datatype, const std::string& definition)
    : root_(datatype) {
  std::string current = datatype;
  std::istringstream in(definition);
  std::string line;
  int lineno = 0;
  types_[current];
  while (std::getline(in, line)) {
    ++lineno;
    const std::string t = trim(line.substr(0, line.find('#')));
    if (t.empty() || t.rfind("====", 0) == 0) continue;
    if (t.rfind("MSG:", 0) == 0) {
      current = trim(t.substr(4));
      types_[current];
      continue;
    }
    std::istringstream f(t);
    Field field;
    std::string type;
    f >> type >> field.name;
    if (field.name.empty() || t.find('=') != std::string::npos) continue;  // a constant
    const auto bracket = type.find('[');
    if (bracket != std::string::npos) {
      const std::string n = type.substr(bracket + 1, type.find(']') - bracket - 1);
      char* stop = nullptr;
      field.array = n.empty() ? 0 : std::strtol(n.c_str(), &stop, 10);
      if (!n.empty() && (*stop || field.array <= 0 || field.array > (1L << 20)))
        throw DataError(datatype + ": message definition line " + std::to_string(lineno) +
                        ": array size '" + n + "'");
      type = type.substr(0, bracket);
    }
    // A type without a package is its message's package's ("Point" in geometry_msgs/Pose);
    // Header is std_msgs/Header.
    if (type == "Header")
      type = "std_msgs/Header";
    else if (!primitiveSizes().count(type) && type != "string" &&
             type.find('/') == std::string::npos)
      type = packageOf(current) + "/" + type;
    field.type = type;
    types_[current].push_back(field);
  }
  for (const auto& [name, fields] : types_)
    for (const Field& f : fields)
      if (!primitiveSizes().count(f.type) && f.type != "string" && !types_.count(f.type))
        throw DataError(datatype + ": message definition: type " + f.type + " of field " + name +
                        "." + f.name + " is not defined");
}

std::map<std::string, double> RosMessageSchema::numbers(const std::uint8_t* data,
                                                        std::size_t size) const {
  std::map<std::string, double> out;
  const std::uint8_t* p = data;
  decode(root_, "", p, data + size, out, 0);
  return out;
}

void RosMessageSchema::decode(const std::string& type, const std::string& prefix,
                              const std::uint8_t*& p, const std::uint8_t* end,
                              std::map<std::string, double>& out, int depth) const {
  if (depth > kMaxDepth) throw DataError(root_ + ": message types nested too deep");
  auto need = [&](std::size_t n, const std::string& what) {
    if (std::size_t(end - p) < n)
      throw DataError(root_ + ": the message ends inside " + what + " (" + std::to_string(end - p) +
                      " bytes left, " + std::to_string(n) + " needed)");
  };
  for (const Field& f : types_.at(type)) {
    const std::string name = prefix + f.name;
    std::size_t count = 1;
    if (f.array == 0) {
      need(4, name + "'s count");
      count = std::size_t(read<std::uint32_t>(p));
      p += 4;
      if (count > std::size_t(end - p))  // every element takes a byte at least
        throw DataError(root_ + ": " + name + "'s count " + std::to_string(count) +
                        " does not fit in the " + std::to_string(end - p) + " bytes left");
    } else if (f.array > 0) {
      count = std::size_t(f.array);
    }
    for (std::size_t i = 0; i < count; ++i) {
      const std::string element = f.array >= 0 ? name + "[" + std::to_string(i) + "]" : name;
      if (f.type == "string") {
        need(4, element + "'s length");
        const std::size_t n = read<std::uint32_t>(p);
        p += 4;
        need(n, element);
        p += n;
      } else if (const auto it = primitiveSizes().find(f.type); it != primitiveSizes().end()) {
        need(std::size_t(it->second), element);
        out[element] = primitive(f.type, p);
        p += it->second;
      } else {
        decode(f.type, element + ".", p, end, out, depth + 1);
      }
    }
  }
}

}  // namespace pedtrack::cli
