#pragma once
#include <stdexcept>
#include <string>

namespace pedtrack {

/// Bad input the user can fix (pipeline file, command line, missing file): exit code 2.
/// The message is one line that names the file, section, key or value at fault.
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A failure while running on valid configuration (corrupt data, device error): exit code 1.
class DataError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

namespace exit_code {
constexpr int kOk = 0;
constexpr int kFailure = 1;
constexpr int kBadInput = 2;
}  // namespace exit_code

}  // namespace pedtrack
