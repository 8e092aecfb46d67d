#pragma once
// A classifier model file's text, read and checked before OpenCV parses it.
//
// OpenCV 4.6's YAML parser loops for good on some malformed files (found by fuzz_model): after
// a document's root it skips three characters, assuming a '---' or '...' marker, and a '-' it
// then meets that is not '---' is never consumed. pedtrack writes one layout only (a '%YAML'
// line, a '---' line, then one map whose keys start at column 0), so a model file must have it:
// a single document whose root map ends only at the end of the file. Control bytes (other than
// tab, CR, LF), which YAML forbids, are refused too: another such loop met them.
#include <cstddef>
#include <string>

namespace pedtrack::classify {

/// The largest model text read (after decompression): a gzip bomb is refused, not unpacked.
constexpr std::size_t kMaxModelTextBytes = std::size_t(256) << 20;

/// The first reason `text` is not in pedtrack's model layout, as one phrase ("line 3: ..."), or
/// "" when it is. Only the layout is checked here; the keys are ModelReader's business.
std::string modelTextProblem(const std::string& text);

/// The whole text of the model file at `path` (a gzip-compressed one decompressed), checked by
/// modelTextProblem. Throws ConfigError "PATH: ..." naming the problem.
std::string readModelText(const std::string& path);

}  // namespace pedtrack::classify
