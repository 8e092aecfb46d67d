#include "pedtrack/classify/model_text.h"

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <memory>
#include <vector>

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
constexpr std::size_t kMaxFlowDepth = 16;

// The lines of the root map, in the forms OpenCV's YAML writer gives a pedtrack model:
//   key:            key: VALUE         - VALUE         -          (and flow continuation lines)
// with VALUE a number, a word, a double-quoted string, a `!!type` tag, or a [ ] / { } flow
// collection (of numbers, words and key:value pairs, over as many lines as it needs). A block
// collection then nests only by indentation, one level per line at most.
class LineForms {
 public:
  // "" or the problem with the line [b, e).
  std::string check(const std::string& t, std::size_t b, std::size_t e) {
    std::size_t p = b;
    while (p < e && t[p] == ' ') ++p;
    if (p < e && p - b > kMaxIndent)
      return "indented more than " + std::to_string(kMaxIndent) + " columns";
    if (inFlow()) return flow(t, b, e);
    if (blankOrComment(t, b, e)) return "";
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
  bool inFlow() const { return !open_.empty(); }

 private:
  std::string value(const std::string& t, std::size_t p, std::size_t e) {
    const char c = t[p], d = p + 1 < e ? t[p + 1] : '\0';
    if (c == '[' || c == '{') {
      open(c);
      return flow(t, p + 1, e);
    }
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
  // A [ ] / { } collection read as OpenCV reads it: in a sequence each element is a value, in
  // a map "key: value"; a value is a nested collection or a word, which ends at ',', ']', '}'
  // or the line's end. Brackets are counted exactly where OpenCV opens and closes one; where it
  // would read a bracket as text (in a word or key), or a quote or '#' could hide one, the line
  // is refused: pedtrack writes numbers and plain keys there.
  enum class Flow { Value, Key, InKey, InWord, After };
  void open(char c) {
    open_.push_back(c);
    at_ = c == '[' ? Flow::Value : Flow::Key;
  }
  std::string flow(const std::string& t, std::size_t p, std::size_t e) {
    const std::string bad_key = "a key inside { } that is not a word followed by ':'";
    for (; p < e; ++p) {
      const char c = t[p];
      if (c == '"' || c == '\'' || c == '#') return "a quote or '#' inside [ ] or { }";
      if (c == ' ' && at_ != Flow::InWord && at_ != Flow::InKey) continue;
      if (c == ']' || c == '}' || c == ',') {
        if (at_ == Flow::InKey) return bad_key;
        if (c == ',') {
          at_ = open_.back() == '[' ? Flow::Value : Flow::Key;
          continue;
        }
        if ((c == ']') != (open_.back() == '[')) return "a ']' or '}' that does not match";
        open_.pop_back();
        if (open_.empty()) return rest(t, p + 1, e);
        at_ = Flow::After;
        continue;
      }
      switch (at_) {
        case Flow::Value:
          if (c == '[' || c == '{') {
            open(c);
            if (open_.size() > kMaxFlowDepth)
              return "[ ] or { } nested more than " + std::to_string(kMaxFlowDepth) + " deep";
          } else {
            at_ = Flow::InWord;
          }
          break;
        case Flow::Key:
        case Flow::InKey:
          if (c == ':' && at_ == Flow::InKey)
            at_ = Flow::Value;
          else if (!(at_ == Flow::Key ? isKeyStart(c) : isKeyChar(c)))
            return bad_key;
          else
            at_ = Flow::InKey;
          break;
        case Flow::InWord:
          if (c == '[' || c == '{') return "a '[' or '{' inside a word in [ ] or { }";
          break;
        case Flow::After:
          return "more after a [ ] or { } inside [ ] or { }";
      }
    }
    // A word ends with its line (OpenCV reads printable characters only); a key may not.
    if (at_ == Flow::InWord) at_ = Flow::After;
    return at_ == Flow::InKey ? bad_key : "";
  }
  static std::string rest(const std::string& t, std::size_t p, std::size_t e) {
    return blankOrComment(t, p, e) ? "" : "more after the value";
  }

  std::vector<char> open_;  // the open collections' brackets, outermost first
  Flow at_ = Flow::Value;
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
    // OpenCV drops the rest of a line after a CR: text this check would see and it would not.
    if (c == '\r' && (i + 1 == text.size() || text[i + 1] != '\n'))
      return "a CR without LF at offset " + std::to_string(i);
  }
  // Lines end at LF (a CR before it dropped), as OpenCV reads them.
  bool in_header = true, seen_document_start = false;
  LineForms forms;
  std::size_t line_no = 0;
  for (std::size_t begin = 0; begin < text.size();) {
    const std::size_t lf = std::min(text.find('\n', begin), text.size());
    const std::size_t end = lf > begin && text[lf - 1] == '\r' ? lf - 1 : lf;
    ++line_no;
    const auto at = [&] { return "line " + std::to_string(line_no) + ": "; };  // on error only
    if (!blankOrComment(text, begin, end)) {
      const bool marker = startsWith(text, begin, "---") || startsWith(text, begin, "...");
      if (in_header) {
        if (text[begin] == '%') {
          begin = lf + 1;  // a directive
          continue;
        }
        if (startsWith(text, begin, "---")) {
          if (seen_document_start) return at() + "a second '---' (a model file is one document)";
          if (!blankOrComment(text, begin + 3, end))
            return at() + "content after '---' (a model file's root is a map on the lines below)";
          seen_document_start = true;
          begin = lf + 1;
          continue;
        }
        if (text[begin] == ' ')
          return at() + "the root is indented (a model file's root is a map at column 0)";
        if (!isKeyStart(text[begin])) return at() + "the root is not a map of keys";
        in_header = false;
      } else if (marker) {
        // The root map would end here and the parser go on to a next document.
        return at() +
               "a document marker ('---' or '...') after the root (a model file is one "
               "document)";
      }
    }
    if (!in_header)
      if (const std::string bad = forms.check(text, begin, end); !bad.empty()) return at() + bad;
    begin = lf + 1;
  }
  if (forms.inFlow()) return "the file ends inside [ ] or { }";
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
