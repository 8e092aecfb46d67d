#pragma once
// Command-line parsing shared by the subcommands (Boost.Program_options).
#include <boost/program_options.hpp>
#include <string>
#include <vector>

#include "pedtrack/pipeline.h"

namespace pedtrack::cli {

namespace po = boost::program_options;

/// Parses `args`; prints usage and returns false on --help. Throws ConfigError (exit 2) on a bad
/// option, naming it.
/// --help prints the usage line, the command's description (commandAbout(about_key), `command`
/// when empty) and the options.
bool parseOptions(const std::string& command, const std::string& synopsis,
                  const po::options_description& options,
                  const po::positional_options_description& positional,
                  const std::vector<std::string>& args, po::variables_map& vm,
                  const std::string& about_key = std::string());

/// What a command's --help says besides its options ("eval --model" for eval's model mode).
const char* commandAbout(const std::string& key);

/// The options `pedtrack run` and `pedtrack ros` share: --out, --no-point-labels, --plugin-path,
/// --max-frames, --record, --live-queue, --quiet. Read them back with readRunOptions().
void addRunOptions(po::options_description& options, RunOptions& run,
                   std::vector<std::string>& plugin_path);
/// The flags of addRunOptions() into `run`; ConfigError for a --live-queue below 1 or a --record
/// file that cannot be written (checked before anything is written).
void readRunOptions(const po::variables_map& vm, RunOptions& run);

/// ConfigError naming `option` unless `path` is a file that can be created or overwritten (its
/// directory exists and is writable, or is `created_dir`, which the run creates, under a
/// writable one; the path is no directory).
void checkWritableFile(const std::string& path, const std::string& option,
                       const std::string& created_dir = std::string());

}  // namespace pedtrack::cli
