// `pedtrack render`: top-view pictures (PNG) and videos (MP4) of a rawlog with the tracks, truth
// and detections of a run drawn over it. The drawing lives in render/.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>

#include "commands.h"
#include "options.h"
#include "pedtrack/errors.h"
#include "pedtrack/eval/kitti_labels.h"
#include "pedtrack/pipeline.h"
#include "pedtrack/progress.h"
#include "render/frame_source.h"
#include "render/image_output.h"
#include "render/object_index.h"
#include "render/renderer.h"

namespace pedtrack::cli {
namespace {

namespace fs = std::filesystem;
using render::FrameSource;
using render::ObjectIndex;
using render::StreamSummary;

struct RenderArgs {
  std::string rawlog, tracks, truth, detections, out, center, labels, run, kitti, kitti_labels,
      calib;
  std::vector<std::string> plugin_path;
  long frame = -1, max_frames = -1;
  double trail = 2, range = 0, fps = 0, ground_z = 0.15, person_score = 0.5;
  int size = 900;
  bool quiet = false, video = false, scores = false;
};

[[noreturn]] void bad(const std::string& what) {
  throw ConfigError("pedtrack render: " + what);
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

void requireFile(const char* option, const std::string& path) {
  if (!path.empty() && !fs::is_regular_file(path))
    bad(std::string("--") + option + " '" + path + "': no such file");
}

std::optional<cv::Point2d> parseCenter(const std::string& text) {
  if (text.empty()) return std::nullopt;
  double x, y;
  char extra;
  if (std::sscanf(text.c_str(), " %lf , %lf %c", &x, &y, &extra) != 2 || !std::isfinite(x) ||
      !std::isfinite(y))
    bad("--center '" + text + "': expected x,y in metres (fixed frame), e.g. --center 2.5,-1");
  return cv::Point2d(x, y);
}

/// Every check that needs no data, so bad input stops before anything is read or written.
void validate(RenderArgs& a) {
  const std::string ext = lower(fs::path(a.out).extension().string());
  if (ext != ".png" && ext != ".mp4")
    bad("--out '" + a.out + "': unknown extension '" + ext + "' (expected .png or .mp4)");
  a.video = ext == ".mp4";
  if (a.video && a.frame >= 0)
    bad("--frame: applies to .png output only (an .mp4 has every frame)");
  if (a.frame < -1) bad("--frame " + std::to_string(a.frame) + ": must be >= 0");
  if (a.size < 100 || a.size > 8000)
    bad("--size " + std::to_string(a.size) + ": expected 100..8000 px");
  if (a.range < 0 || !std::isfinite(a.range)) bad("--range: must be > 0 m (0: fit the data)");
  if (a.fps != 0 && (a.fps < 1 || a.fps > 240)) bad("--fps: expected 1..240 (0: the data rate)");
  if (a.trail < 0) bad("--trail: must be >= 0 s");
  if (a.max_frames == 0) bad("--max-frames 0: nothing to render");
  if (!a.run.empty()) {
    if (!fs::is_directory(a.run)) bad("--run '" + a.run + "': no such directory");
    // A run's outputs, unless given one by one.
    auto take = [&](std::string& slot, const char* name) {
      if (slot.empty() && fs::is_regular_file(fs::path(a.run) / name))
        slot = (fs::path(a.run) / name).string();
    };
    take(a.tracks, "tracks.csv");
    take(a.detections, "detections.csv");
    take(a.labels, "point_labels.bin");
    take(a.truth, "truth.csv");
  }
  // A folder is a sequence of KITTI scans (the kitti source).
  if (!fs::is_directory(a.rawlog)) requireFile("rawlog", a.rawlog);
  requireFile("labels", a.labels);
  requireFile("tracks", a.tracks);
  requireFile("truth", a.truth);
  requireFile("detections", a.detections);
  if (!a.kitti.empty() && !fs::is_directory(fs::path(a.kitti) / "label_2"))
    bad("--kitti '" + a.kitti + "': no label_2/ folder (a KITTI object benchmark folder)");
  if (!a.calib.empty() && a.kitti_labels.empty()) bad("--calib goes with --kitti-labels");
  if (!a.kitti_labels.empty()) {
    requireFile("kitti-labels", a.kitti_labels);
    if (a.calib.empty()) a.calib = kittiCalibBeside(a.kitti_labels);  // label_02/ beside calib/
    if (!fs::is_regular_file(a.calib))
      bad("--kitti-labels: no calibration " +
          (a.calib.empty()
               ? "calib/" + fs::path(a.kitti_labels).filename().string() + " beside its folder"
               : "'" + a.calib + "'") +
          " (give --calib CALIB/SSSS.txt)");
  }
  if (!std::isfinite(a.person_score)) bad("--person-score: must be a number");
}

/// Positions the default view must hold: every track and true position, and the sensor's path
/// with 4 m around it, so the points near the sensor show even where it reaches the edge.
std::vector<cv::Point2d> mustSee(const render::Scene& s) {
  std::vector<cv::Point2d> pts;
  for (const auto& p : s.sensor_path) {
    pts.emplace_back(p.x - 4, p.y - 4);
    pts.emplace_back(p.x + 4, p.y + 4);
  }
  for (const ObjectIndex* idx : {s.tracks, s.truth})
    if (idx)
      for (const auto& r : idx->rows()) pts.emplace_back(r.x, r.y);
  return pts;
}

}  // namespace

int renderCommand(const std::vector<std::string>& args) {
  RenderArgs a;
  po::options_description opts("options");
  opts.add_options()("rawlog", po::value(&a.rawlog)->required(), "the rawlog the run replayed")(
      "tracks", po::value(&a.tracks), "tracks.csv of the run (optional: e.g. truth only)")(
      "truth", po::value(&a.truth), "truth.csv (simulated ground truth), drawn as outlines")(
      "detections", po::value(&a.detections), "detections.csv, drawn as crosses")(
      "labels", po::value(&a.labels),
      "point_labels.bin of the run (colours ground, clusters and removed points) or "
      "truth_points.bin of a simulation (colours each true person)")(
      "run", po::value(&a.run),
      "a run's --out directory: its tracks.csv, detections.csv, point_labels.bin and truth.csv "
      "(those present and not given on their own)")(
      "out", po::value(&a.out)->required(), "output: FILE.png (one frame / overlay) or FILE.mp4")(
      "frame", po::value(&a.frame)->default_value(-1),
      "PNG of this frame index (default: overlay of the whole run)")(
      "trail", po::value(&a.trail)->default_value(2.0), "seconds of track history behind a frame")(
      "size", po::value(&a.size)->default_value(900), "image side in pixels (square)")(
      "range", po::value(&a.range)->default_value(0.0),
      "half-width of the view in metres (0: fit tracks, truth and sensor path, at least 8)")(
      "center", po::value(&a.center), "view centre x,y in metres (default: first sensor position)")(
      "fps", po::value(&a.fps)->default_value(0.0),
      "video frame rate (0: the data rate, clamped to 1..60)")(
      "ground-z", po::value(&a.ground_z)->default_value(0.15, "0.15"),
      "points lower than this (m, robot frame) are drawn as ground")(
      "max-frames", po::value(&a.max_frames)->default_value(-1),
      "use only the first N frames (-1: all)")(
      "scores", po::bool_switch(&a.scores),
      "write each detection's score beside it (bright from --person-score on)")(
      "person-score", po::value(&a.person_score)->default_value(0.5),
      "a detection scoring at least this is called a person")(
      "kitti", po::value(&a.kitti),
      "a KITTI object benchmark folder (label_2/, calib/): its labelled boxes over the scan "
      "of the same number (the kitti source's times: scan t x 10)")(
      "kitti-labels", po::value(&a.kitti_labels),
      "KITTI tracking labels (label_02/SSSS.txt) of a run on that sequence's detections or "
      "scans: the labelled pedestrians drawn as the truth, every labelled box in a frame")(
      "calib", po::value(&a.calib),
      "the calibration of --kitti-labels (default: calib/SSSS.txt beside label_02/)")(
      "plugin-path", po::value(&a.plugin_path)->composing(), "extra plugin directory (repeatable)")(
      "quiet,q", "no progress output");
  po::positional_options_description pos;
  po::variables_map vm;
  if (!parseOptions("render",
                    "--rawlog R [--run DIR] [--tracks T] [--truth G] [--labels L] --out "
                    "FILE.png|FILE.mp4 [options]",
                    opts, pos, args, vm))
    return 0;
  a.quiet = vm.count("quiet") > 0;
  validate(a);
  const std::optional<cv::Point2d> center = parseCenter(a.center);

  // Inputs, then one cheap pass over the frames (no clouds) for the sensor path and data rate.
  const ObjectIndex tracks(a.tracks.empty() ? std::vector<ObjectRow>{}
                                            : readObjectTable(a.tracks).rows);
  std::unique_ptr<ObjectIndex> truth, detections;
  if (!a.truth.empty()) truth = std::make_unique<ObjectIndex>(readObjectTable(a.truth).rows);
  // A KITTI tracking sequence's labels, in the Velodyne's frame: frame n at n / 10 s (the
  // `kitti` and `detections` sources' times without OXTS motion: the scanner is the fixed frame).
  std::map<long, std::vector<eval::KittiObject>> labelled;
  if (!a.kitti_labels.empty()) {
    std::vector<ObjectRow> people;
    for (const auto& o :
         eval::readKittiTrackingLabels(a.kitti_labels, eval::readKittiCalib(a.calib))) {
      if (o.dontCare()) continue;
      labelled[o.frame].push_back(o);
      if (!o.person()) continue;
      ObjectRow r;
      r.t = double(o.frame) / 10, r.frame = o.frame, r.id = o.track, r.x = o.x, r.y = o.y;
      people.push_back(r);
    }
    if (!truth) truth = std::make_unique<ObjectIndex>(people);
  }
  if (!a.detections.empty())
    detections = std::make_unique<ObjectIndex>(readDetectionTable(a.detections).rows);
  std::unique_ptr<render::LabelSource> labels;
  if (!a.labels.empty()) labels = std::make_unique<render::LabelSource>(a.labels);

  const long limit = a.frame >= 0 ? a.frame + 1 : a.max_frames;
  if (a.max_frames >= 0 && a.frame >= a.max_frames)
    bad("--frame " + std::to_string(a.frame) + ": beyond --max-frames " +
        std::to_string(a.max_frames));
  StreamSummary summary;
  // The source outlives `kept`: a plugin may create the observations (rosbag's point clouds),
  // and their code goes away with it.
  FrameSource source(a.rawlog, a.plugin_path);
  Frame frame, kept;  // kept: the frame a PNG shows (--frame N, or the last one)
  {
    Progress progress("render: reading", !a.quiet);
    while ((limit < 0 || static_cast<long>(summary.frames) < limit) && source.next(frame)) {
      if (summary.frames == 0) summary.t_first = frame.t;
      summary.t_last = frame.t;
      summary.sensor_path.emplace_back(frame.sensor_pose.x(), frame.sensor_pose.y());
      ++summary.frames;
      kept = frame;
      progress.update(summary.frames, source.progress());
    }
    // Before done(): bad input stays a single line.
    if (summary.frames == 0) throw DataError(a.rawlog + ": no range frames to render");
    if (a.frame >= static_cast<long>(summary.frames))
      bad("--frame " + std::to_string(a.frame) + ": '" + a.rawlog + "' has only " +
          std::to_string(summary.frames) + " frames");
    progress.done(summary.frames);
  }

  render::Scene scene;
  scene.tracks = &tracks;
  scene.truth = truth.get();
  scene.detections = detections.get();
  scene.sensor_path = summary.sensor_path;
  scene.t_first = summary.t_first;
  scene.ground_z = a.ground_z;
  scene.trail_s = a.trail;
  scene.video = a.video;
  scene.labels = labels.get();
  scene.scores = a.scores;
  scene.person_score = a.person_score;
  if (!labelled.empty())
    scene.boxes = [&labelled](const Frame& f) {
      std::vector<render::LabelBox> out;
      const auto it = labelled.find(std::lround(f.t * 10));
      if (it == labelled.end()) return out;
      for (const auto& o : it->second)
        out.push_back({o.x, o.y, o.yaw, o.l, o.w, o.type, o.person()});
      return out;
    };
  std::map<long, eval::KittiScanLabels> kitti;
  if (!a.kitti.empty()) {
    kitti = eval::readKittiObjectDir(a.kitti);
    scene.boxes = [&kitti](const Frame& f) {
      std::vector<render::LabelBox> out;
      const auto it = kitti.find(std::lround(f.t * 10));
      if (it == kitti.end()) return out;
      // Velodyne frame to fixed frame through the scanner's pose.
      const double c = std::cos(f.sensor_pose.yaw()), s = std::sin(f.sensor_pose.yaw());
      for (const auto& o : it->second.objects) {
        if (o.dontCare()) continue;
        out.push_back({f.sensor_pose.x() + c * o.x - s * o.y, f.sensor_pose.y() + s * o.x + c * o.y,
                       o.yaw + f.sensor_pose.yaw(), o.l, o.w, o.type, o.person()});
      }
      return out;
    };
  }
  scene.view = render::fitView(center.value_or(summary.sensor_path.front()), a.range, a.size,
                               mustSee(scene));

  const fs::path parent = fs::path(a.out).parent_path();
  if (!parent.empty()) fs::create_directories(parent);
  if (!a.video) {
    render::writePng(a.out, a.frame >= 0 ? render::renderFrame(scene, kept)
                                         : render::renderOverlay(scene, kept));
    if (!a.quiet) std::fprintf(stderr, "render: wrote %s\n", a.out.c_str());
    return exit_code::kOk;
  }

  const double fps = a.fps > 0 ? a.fps : summary.rate();
  render::Mp4Writer video(a.out, fps, a.size);
  installStopHandlers();  // Ctrl-C ends the video early but leaves a playable file
  FrameSource replay(a.rawlog, a.plugin_path);
  Frame shown;  // after `replay`, which must outlive its observations
  Progress progress("render", !a.quiet);
  while (video.frames() < summary.frames && !Pipeline::stopRequested() && replay.next(shown)) {
    video.write(render::renderFrame(scene, shown));
    progress.update(video.frames(), double(video.frames()) / summary.frames);
  }
  video.close();
  progress.done(video.frames());
  if (!a.quiet)
    std::fprintf(stderr, "render: wrote %s (%zu frames, %.2f fps, %dx%d)\n", a.out.c_str(),
                 video.frames(), fps, a.size, a.size);
  return exit_code::kOk;
}

}  // namespace pedtrack::cli
