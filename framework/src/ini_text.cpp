#include "pedtrack/ini_text.h"

#include <cstdlib>
#include <filesystem>
#include <set>
#include <sstream>

#include "pedtrack/errors.h"
#include "pedtrack/text.h"

namespace pedtrack {

namespace fs = std::filesystem;

std::string preprocessIniText(const std::string& text, const std::string& file,
                              const std::string& replaced) {
  // Names @define'd in the file are MRPT's to expand; any other ${NAME} comes from the environment.
  std::set<std::string> defined;
  {
    std::istringstream is(text);
    std::string line;
    while (std::getline(is, line)) {
      std::istringstream ls(trim(line));
      std::string kw, name;
      if (ls >> kw >> name && kw == "@define") defined.insert(name);
    }
  }
  std::ostringstream out;
  std::istringstream is(text);
  std::string line;
  int lineno = 0;
  std::string section;
  while (std::getline(is, line)) {
    ++lineno;
    const std::string t = trim(line);
    if (!t.empty() && (t[0] == ';' || t[0] == '#')) {
      out << "\n";  // keep line numbers of MRPT's own messages right
      continue;
    }
    if (!t.empty() && t[0] == '[' && t.find(']') != std::string::npos)
      section = trim(t.substr(1, t.find(']') - 1));
    // Inline comments: ';' or '#' after white space.
    for (std::size_t i = 1; i < line.size(); ++i) {
      if ((line[i] == ';' || line[i] == '#') && (line[i - 1] == ' ' || line[i - 1] == '\t')) {
        line.resize(i);
        break;
      }
    }
    std::string expanded;
    bool unset_in_replaced = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
      if (line[i] == '$' && i + 1 < line.size() && line[i + 1] == '{') {
        const auto close = line.find('}', i);
        if (close == std::string::npos)
          throw ConfigError(file + ":" + std::to_string(lineno) + ": unterminated '${'");
        const std::string name = line.substr(i + 2, close - i - 2);
        if (defined.count(name)) {
          expanded += line.substr(i, close - i + 1);
        } else if (const char* v = std::getenv(name.c_str())) {
          // A relative path set in the shell means relative to the shell's directory, not to
          // the pipeline file's: make it absolute before file keys are resolved.
          std::error_code ec;
          const bool relative_dir = v[0] != '\0' && v[0] != '/' && fs::exists(v, ec);
          expanded += relative_dir ? fs::absolute(v).lexically_normal().string() : std::string(v);
        } else if (!replaced.empty() && section == replaced) {
          unset_in_replaced = true;  // the command line's input replaces this section's keys
        } else {
          throw ConfigError(file + ":" + std::to_string(lineno) + ": ${" + name +
                            "} is neither @define'd in the file nor set in the environment");
        }
        i = close;
      } else {
        expanded += line[i];
      }
    }
    out << (unset_in_replaced ? std::string() : expanded) << "\n";
  }
  return out.str();
}

std::string firstStageName(const std::string& text) {
  std::istringstream is(text);
  std::string line, section;
  while (std::getline(is, line)) {
    const std::string t = trim(line);
    if (!t.empty() && t[0] == '[' && t.find(']') != std::string::npos) {
      section = trim(t.substr(1, t.find(']') - 1));
      continue;
    }
    const auto eq = t.find('=');
    if (section != "pipeline" || eq == std::string::npos || trim(t.substr(0, eq)) != "stages")
      continue;
    std::istringstream names(t.substr(eq + 1));
    std::string first;
    names >> first;
    return first;
  }
  return "";
}

}  // namespace pedtrack
