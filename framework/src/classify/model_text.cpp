#include "pedtrack/classify/model_text.h"

#include <zlib.h>

#include <cctype>
#include <memory>

#include "pedtrack/errors.h"

namespace pedtrack::classify {
namespace {

bool startsWith(const std::string& s, std::size_t at, const char* prefix) {
  return s.compare(at, std::char_traits<char>::length(prefix), prefix) == 0;
}

// Nothing but spaces, or a comment, from `from` to `to`.
bool blankOrComment(const std::string& s, std::size_t from, std::size_t to) {
  while (from < to && s[from] == ' ') ++from;
  return from == to || s[from] == '#';
}

}  // namespace

std::string modelTextProblem(const std::string& text) {
  // OpenCV picks its parser by the first bytes; pedtrack writes YAML only, and only the YAML
  // parser's pitfalls are checked here, so XML or JSON is not read at all.
  if (!startsWith(text, 0, "%YAML"))
    return "not a pedtrack model file (it does not start with '%YAML')";
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 && c != '\t' && c != '\n' && c != '\r')
      return "control byte at offset " + std::to_string(i);
  }
  // Lines split at CR as well as LF: OpenCV starts a line after LF only, so every line start it
  // sees is checked (and a CR amid a line, which it drops the rest of, is only refused sooner).
  bool in_header = true, seen_document_start = false;
  std::size_t line_no = 0;
  for (std::size_t begin = 0; begin < text.size();) {
    std::size_t end = text.find_first_of("\r\n", begin);
    if (end == std::string::npos) end = text.size();
    ++line_no;
    const std::string at = "line " + std::to_string(line_no) + ": ";
    if (!blankOrComment(text, begin, end)) {
      const bool marker = startsWith(text, begin, "---") || startsWith(text, begin, "...");
      if (in_header) {
        if (text[begin] == '%') {
          // a directive
        } else if (startsWith(text, begin, "---")) {
          if (seen_document_start) return at + "a second '---' (a model file is one document)";
          if (!blankOrComment(text, begin + 3, end))
            return at + "content after '---' (a model file's root is a map on the lines below)";
          seen_document_start = true;
        } else if (text[begin] == ' ') {
          return at + "the root is indented (a model file's root is a map at column 0)";
        } else if (!std::isalnum(static_cast<unsigned char>(text[begin])) && text[begin] != '_') {
          return at + "the root is not a map of keys";
        } else {
          in_header = false;
        }
      } else if (marker) {
        // The root map would end here and the parser go on to a next document.
        return at +
               "a document marker ('---' or '...') after the root (a model file is one "
               "document)";
      }
    }
    begin = end + 1;
  }
  return "";
}

std::string readModelText(const std::string& path) {
  // gzread passes an uncompressed file through as it is, so one reader serves both.
  const std::unique_ptr<gzFile_s, int (*)(gzFile)> in(gzopen(path.c_str(), "rb"), gzclose);
  if (!in) throw ConfigError(path + ": cannot open the model file");
  std::string text;
  char buf[65536];
  for (;;) {
    const int got = gzread(in.get(), buf, sizeof buf);
    if (got < 0) throw ConfigError(path + ": not a readable model file (corrupt compressed data)");
    if (got == 0) break;
    if (text.size() + std::size_t(got) > kMaxModelTextBytes)
      throw ConfigError(path + ": not a readable model file (more than " +
                        std::to_string(kMaxModelTextBytes >> 20) + " MiB of text)");
    text.append(buf, std::size_t(got));
  }
  if (const std::string problem = modelTextProblem(text); !problem.empty())
    throw ConfigError(path + ": not a readable model file (" + problem + ")");
  return text;
}

}  // namespace pedtrack::classify
