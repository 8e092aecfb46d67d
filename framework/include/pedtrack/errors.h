#pragma once
// The two exceptions every part of pedtrack throws. Their vtables and type information live in
// the framework library only (out-of-line destructors, default visibility), so an exception a
// plugin throws stays valid after the plugin's library is unloaded, and is caught by type in
// the host.
#include <boost/config.hpp>
#include <stdexcept>
#include <string>

namespace pedtrack {

/// Bad input the user can fix (pipeline file, command line, missing file): exit code 2.
/// The message is one line that names the file, section, key or value at fault.
class BOOST_SYMBOL_VISIBLE ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  ~ConfigError() override;
};

/// A failure while running on valid configuration (corrupt data, device error): exit code 1.
class BOOST_SYMBOL_VISIBLE DataError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  ~DataError() override;
};

namespace exit_code {
constexpr int kOk = 0;
constexpr int kFailure = 1;
constexpr int kBadInput = 2;
}  // namespace exit_code

}  // namespace pedtrack
