#pragma once
// The plugin contract. A plugin is a shared library exporting three C symbols (made by
// PEDTRACK_PLUGIN below): its API version and name as plain C values the loader can read from a
// library built against any framework version, and a PluginDescriptor that only a library of
// this API version may be asked for.
#include <boost/config.hpp>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "pedtrack/frame.h"
#include "pedtrack/params.h"
#include "pedtrack/version.h"

namespace mrpt::config {
class CConfigFileBase;
}

namespace pedtrack {

/// Run order in a pipeline: the sensor first, odometry before any classifier or tracker (they
/// place what they find in the fixed frame the odometry sets); otherwise as the file lists them.
enum class Category { Sensor, Odometry, Segmenter, Classifier, Tracker };
const char* toString(Category c);

class Plugin {
 public:
  virtual ~Plugin();
  /// Called once before the first frame with the run's output directory (empty when the run
  /// writes no files). A plugin may put side outputs there (the sim source writes truth.csv).
  virtual void start(const std::string& out_dir) { (void)out_dir; }
  /// Called once after the last frame, before outputs are closed.
  virtual void finish() {}
  /// Named counts of what the plugin did or survived (solver failures and fallbacks, …), written
  /// under the stage in run.json after the run.
  virtual std::vector<std::pair<std::string, long>> counters() const { return {}; }
};

/// A source of frames: a device, a log replay, a simulator.
class Sensor : public Plugin {
 public:
  ~Sensor() override;
  /// Fills `frame` (observations, t, poses) and returns true, or returns false at the end of the
  /// stream. Throws DataError for unreadable data, naming the entry at fault.
  virtual bool next(Frame& frame) = 0;
  /// Fraction of the input consumed in [0, 1], or a negative value when unknown (live devices).
  virtual double progress() const { return -1; }
  /// Bad input entries skipped so far (sources with a skip option), reported in run.json.
  virtual std::size_t entriesSkipped() const { return 0; }
  /// A live device: data arrives whether or not the pipeline is ready. The pipeline then reads
  /// the source on its own thread into a bounded queue and drops the oldest frames rather than
  /// fall behind (next() is only ever called from that thread).
  virtual bool live() const { return false; }
  /// Called with every processed frame after the stages ran and tracks.csv has its rows: a source
  /// whose dataset has a results format of its own writes it here (the `detections` source's
  /// kitti_tracks.txt, in the frame its labels use). Throwing fails the run after its outputs
  /// are closed.
  virtual void results(const Frame& frame) { (void)frame; }
  /// The source hands over a detector's output (Frame::detections), no range data: a frame
  /// without observations is then no fault.
  virtual bool detectionsOnly() const { return false; }
};

/// A processing stage: odometry sets the robot's pose, segmenters add clusters, classifiers
/// detections, trackers tracks.
class Stage : public Plugin {
 public:
  ~Stage() override;
  virtual void process(Frame& frame) = 0;
};
/// Estimates the robot's motion (e.g. by scan matching) and sets the frame's robot and sensor
/// poses. Runs before every stage that uses them, so no stage ever sees a pose change after it.
class Odometry : public Stage {
 public:
  ~Odometry() override;
};
class Segmenter : public Stage {
 public:
  ~Segmenter() override;
};
class Classifier : public Stage {
 public:
  ~Classifier() override;
};
class Tracker : public Stage {
 public:
  ~Tracker() override;
};

/// What a plugin receives when it is created.
struct PluginContext {
  ParamSet params;  ///< validated values of its declared parameters
  /// The whole pipeline configuration and the plugin's section, for plugins that hand their
  /// section to MRPT (mrpt_sensor passes MRPT driver keys through).
  const mrpt::config::CConfigFileBase* config = nullptr;
  std::string section;
};

struct PluginDescriptor {
  std::string name;
  Category category = Category::Segmenter;
  std::string doc;  ///< one line
  std::vector<ParamSpec> params;
  /// When true, keys that are not declared are accepted and left to the plugin (MRPT drivers).
  bool accepts_other_keys = false;
  /// Keys the plugin had once and where they went: a pipeline still giving one is told so.
  std::vector<std::pair<std::string, std::string>> moved_keys;
  std::function<std::unique_ptr<Plugin>(const PluginContext&)> create;
};

}  // namespace pedtrack

/// Exports a plugin. DESCRIBE is a function returning its PluginDescriptor; NAME a string literal.
#define PEDTRACK_PLUGIN(NAME, DESCRIBE)                               \
  extern "C" BOOST_SYMBOL_EXPORT int pedtrack_plugin_api_version() {  \
    return PEDTRACK_API_VERSION;                                      \
  }                                                                   \
  extern "C" BOOST_SYMBOL_EXPORT const char* pedtrack_plugin_name() { \
    return NAME;                                                      \
  }                                                                   \
  extern "C" BOOST_SYMBOL_EXPORT const ::pedtrack::PluginDescriptor*  \
  pedtrack_plugin_descriptor() {                                      \
    static const ::pedtrack::PluginDescriptor d = [] {                \
      auto x = DESCRIBE();                                            \
      x.name = NAME;                                                  \
      return x;                                                       \
    }();                                                              \
    return &d;                                                        \
  }
