#include "options.h"

#include <iostream>

#include "pedtrack/errors.h"

namespace pedtrack::cli {

bool parseOptions(const std::string& command, const std::string& synopsis,
                  const po::options_description& options,
                  const po::positional_options_description& positional,
                  const std::vector<std::string>& args, po::variables_map& vm) {
  po::options_description all(options);
  all.add_options()("help,h", "show this help");
  try {
    po::store(po::command_line_parser(args).options(all).positional(positional).run(), vm);
    if (vm.count("help")) {
      std::cout << "usage: pedtrack " << command << " " << synopsis << "\n\n" << all << "\n";
      return false;
    }
    po::notify(vm);
  } catch (const po::error& e) {
    throw ConfigError("pedtrack " + command + ": " + e.what() + " (see `pedtrack " + command +
                      " --help`)");
  }
  return true;
}

}  // namespace pedtrack::cli
