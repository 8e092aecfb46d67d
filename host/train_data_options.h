#pragma once
// What `pedtrack train` and `pedtrack eval --model` share: turning a dataset file, a samples CSV
// or inline inputs into labelled samples.
#include <string>
#include <vector>

#include "pedtrack/classify/samples.h"
#include "train_dataset.h"

namespace pedtrack::cli {

Dataset datasetFromOptions(const std::string& dataset_file, const std::string& pipeline,
                           const std::vector<std::string>& sims,
                           const std::vector<std::string>& positives,
                           const std::vector<std::string>& negatives, const std::string& topic,
                           const std::string& labels_topic, const std::string& region,
                           long frame_step, double min_range, double max_range,
                           const std::string& features, const std::string& command);

/// Samples from `samples_csv` when given, else collected from `d`; restricted to `features`
/// when not empty. `described` receives the one-line description of where they came from.
classify::SampleSet loadSamples(const Dataset* d, const std::string& samples_csv,
                                const std::vector<std::string>& features,
                                const std::vector<std::string>& plugin_path, bool progress,
                                std::string& described);

}  // namespace pedtrack::cli
