// KITTI's text formats: tracking label / results files and their evaluation (each file scored
// against itself), calibration files, and the `detections` source reading a detector's KITTI
// lines or a detections.csv. Any file must end in results, frames or a DataError, never a crash.
#include <cstdint>
#include <fstream>
#include <string>

#include "fuzz_support.h"
#include "pedtrack/eval/kitti_mot.h"
#include "pedtrack/kitti_calib.h"
#include "pedtrack/pipeline.h"
#include "pedtrack/pipeline_config.h"
#include "pedtrack/plugin_registry.h"

namespace {

// A valid calibration for the source (the fuzzed file is the detections).
std::string calibFile() {
  const std::string path = pedtrack::fuzz::inputFile(nullptr, 0, ".calib");
  std::ofstream(path) << "P2: 700 0 600 45 0 700 180 0 0 0 1 0\nR0_rect: 1 0 0 0 1 0 0 0 1\n"
                         "Tr_velo_to_cam: 0 -1 0 0 0 0 -1 0 1 0 0 0\n";
  return path;
}

void replay(const pedtrack::PluginRegistry& registry, const std::string& file,
            const std::string& extra) {
  try {
    const auto cfg = pedtrack::PipelineConfig::fromText(
        "[pipeline]\nstages = source\n[source]\nplugin = detections\nfile = " + file + "\n" + extra,
        "fuzz.ini", {}, registry);
    pedtrack::Pipeline pipeline(cfg);
    pedtrack::Frame frame;
    for (int i = 0; i < 200 && pipeline.source().next(frame); ++i) frame = pedtrack::Frame();
  } catch (const std::exception&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const pedtrack::PluginRegistry registry({PEDTRACK_FUZZ_PLUGIN_DIR});
  static const std::string calib = calibFile();
  const std::string path = pedtrack::fuzz::inputFile(data, size, ".txt");
  try {
    pedtrack::eval::KittiSequence s;
    s.name = path;
    s.truth = pedtrack::eval::readKittiTrackFile(path);
    s.tracks = s.truth;
    long last = 0;
    for (const auto& r : s.truth) last = std::max(last, r.frame);
    // Scoring is linear in the frames: a label 10 million frames on is slow, not wrong.
    if (s.truth.size() <= 400 && last < 20000) pedtrack::eval::evaluateKittiMot({s}, {});
  } catch (const std::exception&) {
  }
  try {
    pedtrack::readKittiCalib(path);
  } catch (const std::exception&) {
  }
  replay(registry, path, "format = kitti\ncalib = " + calib + "\n");
  replay(registry, path, "format = csv\n");
  return 0;
}
