#pragma once
// Labelled samples as CSV (`label,<feature>,...`, label 1 = person, 0 = non-person), so that a
// collected training or test set can be reused (`--save-samples`, `--samples`) without running
// the segmentation again.
#include <string>
#include <vector>

#include "pedtrack/classify/samples.h"

namespace pedtrack::cli {

void writeSamplesCsv(const std::string& path, const classify::SampleSet& s);
/// `label,score_0,...`: each sample's label and each model's score (`--save-scores`), rows in
/// the samples' order, so the samples a model gets wrong can be found in the samples file.
void writeScoresCsv(const std::string& path, const std::vector<classify::Label>& y,
                    const std::vector<const std::vector<double>*>& scores);
/// Throws ConfigError naming the file and line of anything malformed.
classify::SampleSet readSamplesCsv(const std::string& path);

}  // namespace pedtrack::cli
