#pragma once
// Labelled samples as CSV (`label,<feature>,...`, label 1 = person, 0 = non-person), so that a
// collected training or test set can be reused (`--save-samples`, `--samples`) without running
// the segmentation again.
#include <string>

#include "pedtrack/classify/samples.h"

namespace pedtrack::cli {

void writeSamplesCsv(const std::string& path, const classify::SampleSet& s);
/// Throws ConfigError naming the file and line of anything malformed.
classify::SampleSet readSamplesCsv(const std::string& path);

}  // namespace pedtrack::cli
