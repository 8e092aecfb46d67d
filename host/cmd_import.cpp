// `pedtrack import INPUT --out OUT.rawlog`: any source the replay plugins read (ROS1 bag,
// rawlog) to an observations-format rawlog, odometry included as CObservationOdometry.
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/serialization/CArchive.h>

#include <cstdio>
#include <filesystem>
#include <iostream>

#include "commands.h"
#include "options.h"
#include "pedtrack/errors.h"
#include "pedtrack/pipeline.h"
#include "pedtrack/progress.h"

namespace pedtrack::cli {

int importCommand(const std::vector<std::string>& args) {
  po::options_description opts("options");
  PipelineOverrides ov;
  std::string out;
  std::vector<std::string> plugin_path;
  opts.add_options()("input", po::value(&ov.input)->required(), ".bag or .rawlog to convert")(
      "out,o", po::value(&out)->required(), "rawlog to write (gz-compressed)")(
      "topic", po::value(&ov.topic),
      "bag topics to take (comma list; default: the bag's scan/cloud topic)")(
      "set", po::value(&ov.sets)->composing(),
      "source option: source.key=value (e.g. source.fixed_frame=map)")(
      "plugin-path", po::value(&plugin_path)->composing(), "extra plugin directory (repeatable)")(
      "quiet,q", "no progress output");
  po::positional_options_description pos;
  pos.add("input", 1);
  po::variables_map vm;
  if (!parseOptions("import", "INPUT --out OUT.rawlog [options]", opts, pos, args, vm)) return 0;

  PluginRegistry registry(PluginRegistry::defaultSearchPath(plugin_path));
  // The source is configured exactly as `run --input` would configure it.
  const PipelineConfig config = PipelineConfig::fromText(
      "[pipeline]\nstages = source\n[source]\nplugin = rawlog\n", "pedtrack import", ov, registry);
  Pipeline pipeline(config);
  if (const auto dir = std::filesystem::path(out).parent_path(); !dir.empty())
    std::filesystem::create_directories(dir);
  mrpt::io::CFileGZOutputStream file;
  if (!file.open(out)) throw ConfigError("--out: cannot write '" + out + "'");
  auto archive = mrpt::serialization::archiveFrom(file);

  Progress progress("import", !vm.count("quiet"));
  installStopHandlers();
  std::size_t frames = 0, observations = 0;
  bool has_odometry = false;
  Frame frame;
  std::string error;  // the input ended in bad data: what was read before it is written
  while (!Pipeline::stopRequested()) {
    frame = Frame();
    try {
      if (!pipeline.source().next(frame)) break;
    } catch (const DataError& e) {
      error = e.what();
      break;
    }
    has_odometry =
        has_odometry || frame.robot_pose.norm() > 0 ||
        frame.robot_pose.getRotationMatrix() != mrpt::poses::CPose3D().getRotationMatrix();
    if (has_odometry && !frame.observations.empty()) {
      auto odo = mrpt::obs::CObservationOdometry::Create();
      odo->timestamp = frame.observations.front()->timestamp;
      odo->sensorLabel = "odometry";
      odo->odometry = mrpt::poses::CPose2D(frame.robot_pose);
      archive << *odo;
    }
    for (const auto& obs : frame.observations) archive << *obs;
    observations += frame.observations.size();
    progress.update(++frames, pipeline.source().progress());
  }
  progress.done(frames);
  std::fprintf(stderr, "wrote %zu observations (%zu frames%s) to %s\n", observations, frames,
               has_odometry ? ", with odometry" : "", out.c_str());
  if (!error.empty()) {
    std::cerr << "error: " << error << "\n";
    return exit_code::kFailure;
  }
  return exit_code::kOk;
}

}  // namespace pedtrack::cli
