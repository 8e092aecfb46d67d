#pragma once
// Command-line parsing shared by the subcommands (Boost.Program_options).
#include <boost/program_options.hpp>
#include <string>
#include <vector>

namespace pedtrack::cli {

namespace po = boost::program_options;

/// Parses `args`; prints usage and returns false on --help. Throws ConfigError (exit 2) on a bad
/// option, naming it.
bool parseOptions(const std::string& command, const std::string& synopsis,
                  const po::options_description& options,
                  const po::positional_options_description& positional,
                  const std::vector<std::string>& args, po::variables_map& vm);

}  // namespace pedtrack::cli
