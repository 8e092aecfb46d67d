#pragma once
#include <string>
#include <vector>

namespace pedtrack::cli {

// Each subcommand takes the arguments after its name and returns the process exit code.
int runCommand(const std::vector<std::string>& args);
int pluginsCommand(const std::vector<std::string>& args);
int importCommand(const std::vector<std::string>& args);
int benchCommand(const std::vector<std::string>& args);
int evalCommand(const std::vector<std::string>& args);
int simCommand(const std::vector<std::string>& args);
int renderCommand(const std::vector<std::string>& args);

/// Installs SIGINT/SIGTERM handlers that ask a running pipeline to stop after the current frame.
void installStopHandlers();

}  // namespace pedtrack::cli
