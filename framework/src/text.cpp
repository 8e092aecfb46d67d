#include "pedtrack/text.h"

#include <algorithm>
#include <iostream>
#include <sstream>

namespace pedtrack {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> splitList(const std::string& s) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : s + ",") {
    if (c == ',' || c == ' ' || c == '\t' || c == '\n' || c == '\r') {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  return out;
}

std::string shortNumber(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

std::string oneLine(const std::string& what) {
  // MRPT: "==== MRPT exception ====\nMessage:  <text>\nLocation: ...\nCall stack backtrace:..."
  const auto m = what.find("Message:");
  if (m != std::string::npos) {
    const auto end = what.find('\n', m);
    return trim(what.substr(m + 8, end == std::string::npos ? std::string::npos : end - m - 8));
  }
  std::string last;
  std::string cur;
  for (char c : what + "\n") {
    if (c == '\n') {
      const std::string t = trim(cur);
      if (!t.empty()) last = t;
      cur.clear();
    } else {
      cur += c;
    }
  }
  return last.empty() ? trim(what) : last;
}

void WarnOnce::operator()(const std::string& message) {
  if (std::find(seen_.begin(), seen_.end(), message) != seen_.end()) return;
  seen_.push_back(message);
  std::cerr << "warning: " << prefix_ << message << "\n";
}

std::vector<std::string> splitFields(const std::string& line, char sep) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : line) {
    if (c == sep) {
      out.push_back(trim(cur));
      cur.clear();
    } else if (c != '\r') {
      cur += c;
    }
  }
  out.push_back(trim(cur));
  return out;
}

}  // namespace pedtrack
