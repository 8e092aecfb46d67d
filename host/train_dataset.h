#pragma once
// Training and test data for the classifiers: a dataset file (configs/training/*.ini) or the
// equivalent `pedtrack train` options name a segmentation pipeline and the inputs whose clusters
// become labelled samples:
//   [sim.NAME]        a simulated scenario; each cluster is labelled from the per-point truth
//                     (person, non-person, or mixed and left out)
//   [recording.NAME]  a rawlog or bag; kind = negative: every cluster is a non-person;
//                     kind = positive: clusters matching a label of `labels_topic` (a bag's
//                     PoseArray, leg_tracker style) or lying inside `region` are persons, the
//                     others are left out
#include <string>
#include <vector>

#include "pedtrack/classify/samples.h"
#include "pedtrack/params.h"

namespace pedtrack::cli {

struct DatasetInput {
  enum class Kind { Sim, Positive, Negative } kind = Kind::Sim;
  std::string name;            ///< section name (messages)
  std::string file;            ///< scenario or recording
  long seed = -1;              ///< sim: -1 = the scenario's
  std::string topic;           ///< recording: scan topic (bags), empty = the only one
  std::string labels_topic;    ///< positive recording: PoseArray topic of person/leg positions
  std::vector<double> region;  ///< positive recording: x0 y0 x1 y1 (sensor frame, m)
  double part_from = 0, part_to = 1;  ///< the share of the input's frames used
};

struct Dataset {
  std::string file;      ///< the dataset file ("" when built from options)
  std::string pipeline;  ///< segmentation pipeline; only its segmenter stages run
  long frame_step = 1;   ///< every Nth frame (consecutive frames are nearly the same samples)
  double min_range = 0,
         max_range = 0;          ///< m from the sensor; clusters outside are left out (0: no limit)
  double match_distance = 0.15;  ///< m, label ↔ cluster centroid (positive recordings)
  /// Recordings are also learnt from with every Nth beam of each 2D scan, for each N here
  /// (1: the scans as recorded): legs seen as the full scan sees them N times farther away.
  std::string beam_steps = "1";
  std::vector<int> steps{1};  ///< beam_steps, parsed
  double purity = 0.8;  ///< share of one person's points that makes a person (and 1 − it, of all
                        ///< people's, a non-person)
  std::vector<std::string>
      features;  ///< the features a model reads (empty: all the segmenters give)
  std::vector<DatasetInput> inputs;
  /// One line per input for the model file and reports.
  std::string describe() const;
};

/// The declared keys of every dataset section (validation and README).
const std::vector<std::pair<std::string, std::vector<ParamSpec>>>& datasetKeys();
/// Reads and validates a dataset file; throws ConfigError naming file, section and key.
Dataset loadDataset(const std::string& path);

struct CollectStats {
  std::size_t mixed = 0;           ///< sim clusters left out as mixed
  std::size_t out_of_range = 0;    ///< clusters outside [min_range, max_range]
  std::size_t labels = 0;          ///< positive-recording labels seen
  std::size_t labels_matched = 0;  ///< ... that matched a cluster
  std::size_t frames = 0;
};

/// Runs every input through the dataset's segmenters and labels the clusters.
classify::SampleSet collectSamples(const Dataset& d, const std::vector<std::string>& plugin_path,
                                   bool progress, CollectStats& stats);

}  // namespace pedtrack::cli
