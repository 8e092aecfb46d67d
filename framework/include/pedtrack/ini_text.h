#pragma once
// The INI text of pipelines, scenarios and datasets before MRPT's CConfigFile parses it.
#include <string>

namespace pedtrack {

/// Strips comments (whole-line and inline " ;" / " #"; line numbers kept) and expands ${VAR}
/// from the environment (names @define'd in the file are left to MRPT). Throws ConfigError
/// naming file and line for an unset variable, except in section `replaced` (the source a
/// command line's --input replaces), where such a line is dropped.
std::string preprocessIniText(const std::string& text, const std::string& file,
                              const std::string& replaced = std::string());

/// The first name of [pipeline] `stages` (the source's section), empty when there is none.
std::string firstStageName(const std::string& text);

}  // namespace pedtrack
