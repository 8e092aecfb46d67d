#pragma once
// The INI text of pipelines, scenarios and datasets before MRPT's CConfigFile parses it.
#include <string>

namespace pedtrack {

/// Strips comments (whole-line and inline " ;" / " #"; line numbers kept) and expands ${VAR}
/// from the environment (names @define'd in the file are left to MRPT). Throws ConfigError
/// naming file and line for an unset variable.
std::string preprocessIniText(const std::string& text, const std::string& file);

}  // namespace pedtrack
