#include "pedtrack/classify/model_text.h"

#include <zlib.h>

#include <cctype>
#include <cstring>
#include <memory>

#include "pedtrack/errors.h"

namespace pedtrack::classify {
namespace {

bool startsWith(const std::string& s, std::size_t at, const char* prefix) {
  return s.compare(at, std::char_traits<char>::length(prefix), prefix) == 0;
}

bool isKeyStart(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool isKeyChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}
bool isDigit(char c) {
  return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

// Nothing but spaces, or a comment, from `from` to `to`.
bool blankOrComment(const std::string& s, std::size_t from, std::size_t to) {
  while (from < to && s[from] == ' ') ++from;
  return from == to || s[from] == '#';
}

// Deep nesting is the other way to break OpenCV 4.6's parser: it recurses once per level with
// no limit, and 65,000 '[' overflowed its stack (and 6,000 '-' ours, walking the tree). Under
// these bounds and the line forms below, the parser recurses at most ~100 levels.
constexpr std::size_t kMaxIndent = 64;
constexpr int kMaxFlowDepth = 16;

// The lines of the root map, in the forms OpenCV's YAML writer gives a pedtrack model:
//   key:            key: VALUE         - VALUE         -          (and flow continuation lines)
// with VALUE a number, a word, a double-quoted string, a `!!type` tag, or a [ ] / { } flow
// collection (of numbers, words and key:value pairs, over as many lines as it needs). A block
// collection then nests only by indentation, one level per line at most.
class LineForms {
 public:
  // "" or the problem with the line [b, e).
  std::string check(const std::string& t, std::size_t b, std::size_t e) {
    if (flow_depth_ > 0) return flow(t, b, e);
    if (blankOrComment(t, b, e)) return "";
    std::size_t p = b;
    while (p < e && t[p] == ' ') ++p;
    if (p - b > kMaxIndent) return "indented more than " + std::to_string(kMaxIndent) + " columns";
    if (t[p] == '-' && (p + 1 == e || t[p + 1] == ' ')) {  // a block sequence's item
      ++p;
    } else {  // key:
      if (!isKeyStart(t[p])) return "not a 'key:' or '- ' line";
      while (p < e && isKeyChar(t[p])) ++p;
      while (p < e && t[p] == ' ') ++p;
      if (p == e || t[p] != ':') return "a key without ':'";
      ++p;
    }
    while (p < e && t[p] == ' ') ++p;
    return blankOrComment(t, p, e) ? "" : value(t, p, e);
  }
  bool inFlow() const { return flow_depth_ > 0; }

 private:
  std::string value(const std::string& t, std::size_t p, std::size_t e) {
    const char c = t[p], d = p + 1 < e ? t[p + 1] : '\0';
    if (c == '[' || c == '{') return flow(t, p, e);
    if (c == '"') {  // to the closing quote; a backslash escapes the next character
      std::size_t q = p + 1;
      while (q < e && t[q] != '"') q += t[q] == '\\' ? 2 : 1;
      if (q >= e) return "a string without its closing '\"'";
      return rest(t, q + 1, e);
    }
    std::size_t q = p;
    const auto number = [](char x) { return isKeyChar(x) || x == '.' || x == '-' || x == '+'; };
    // What OpenCV's writer leaves unquoted: letters, digits and _ ( ) / + ; - . and spaces.
    const auto word = [&](char x) {
      return number(x) || (x != '\0' && std::strchr(" ()/;", x) != nullptr);
    };
    if (c == '!' && d == '!') {  // a type tag
      q += 2;
      while (q < e && number(t[q])) ++q;
    } else if (isDigit(c) || ((c == '-' || c == '+') && (isDigit(d) || d == '.')) ||
               (c == '.' && std::isalnum(static_cast<unsigned char>(d)))) {
      while (q < e && number(t[q])) ++q;
    } else if (isKeyStart(c) || std::strchr("()/;", c) != nullptr) {
      while (q < e && word(t[q])) ++q;
    } else {
      // '-' before anything but a digit or '.' would open a sequence inside this line's, and
      // a ':' in a word a map: nesting without indentation.
      return "a value that is not a number, word, string, tag or [ ] / { }";
    }
    return rest(t, q, e);
  }
  // Brackets counted, never fewer than OpenCV opens: no quote or comment can hide one (a '[' in
  // a word is text to OpenCV, but counted here; every ']' and '}' closes).
  std::string flow(const std::string& t, std::size_t p, std::size_t e) {
    for (; p < e; ++p) {
      const char c = t[p];
      if (c == '"' || c == '\'' || c == '#') return "a quote or '#' inside [ ] or { }";
      if (c == '[' || c == '{') {
        if (++flow_depth_ > kMaxFlowDepth)
          return "[ ] or { } nested more than " + std::to_string(kMaxFlowDepth) + " deep";
      } else if (c == ']' || c == '}') {
        if (--flow_depth_ == 0) return rest(t, p + 1, e);  // (flow is entered at a '[' or '{')
      }
    }
    return "";
  }
  static std::string rest(const std::string& t, std::size_t p, std::size_t e) {
    return blankOrComment(t, p, e) ? "" : "more after the value";
  }

  int flow_depth_ = 0;
};

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
  LineForms forms;
  std::size_t line_no = 0;
  for (std::size_t begin = 0; begin < text.size();) {
    std::size_t end = text.find_first_of("\r\n", begin);
    if (end == std::string::npos) end = text.size();
    ++line_no;
    const std::string at = "line " + std::to_string(line_no) + ": ";
    if (!forms.inFlow() && !blankOrComment(text, begin, end)) {
      const bool marker = startsWith(text, begin, "---") || startsWith(text, begin, "...");
      if (in_header) {
        if (text[begin] == '%') {
          begin = end + 1;  // a directive
          continue;
        }
        if (startsWith(text, begin, "---")) {
          if (seen_document_start) return at + "a second '---' (a model file is one document)";
          if (!blankOrComment(text, begin + 3, end))
            return at + "content after '---' (a model file's root is a map on the lines below)";
          seen_document_start = true;
          begin = end + 1;
          continue;
        }
        if (text[begin] == ' ')
          return at + "the root is indented (a model file's root is a map at column 0)";
        if (!isKeyStart(text[begin])) return at + "the root is not a map of keys";
        in_header = false;
      } else if (marker) {
        // The root map would end here and the parser go on to a next document.
        return at +
               "a document marker ('---' or '...') after the root (a model file is one "
               "document)";
      }
    }
    if (!in_header)
      if (const std::string bad = forms.check(text, begin, end); !bad.empty()) return at + bad;
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
