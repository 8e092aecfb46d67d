// `detections` sensor: replays a detector's output, one frame of detections at a time, so the
// trackers run behind a detector of the user's own (a deep 3D detector, a camera): no points, no
// segmentation, no classifier. KITTI detection files (camera frame, turned into the robot frame by
// the sequence's calibration) also get their tracks written back as kitti_tracks.txt.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <optional>

#include "detection_files.h"
#include "kitti_tracks_writer.h"
#include "pedtrack/errors.h"
#include "pedtrack/kitti_oxts.h"
#include "pedtrack/param_table.h"
#include "pedtrack/plugin.h"
#include "pedtrack/replay_pacer.h"
#include "pedtrack/text.h"

namespace pedtrack::detections {
namespace {
namespace fs = std::filesystem;

struct DetectionsParams {
  std::string file;
  std::string format = "auto";
  std::string calib = "auto";
  std::vector<std::string> classes{"Pedestrian"};
  kitti::KittiRig rig;
  long frames = 0;
  std::string oxts = "none";
  ReplayRateParams replay;
};

const ParamTable<DetectionsParams>& table() {
  using P = DetectionsParams;
  static const auto t =
      ParamTable<P>()
          .inputFile(&P::file, "file",
                     "the detections: a KITTI detection file (AB3DMOT's comma-separated lines, or "
                     "KITTI tracking label / results lines), or a pedtrack detections.csv")
          .choice(&P::format, "format",
                  {{"auto", std::string("auto")},
                   {"kitti", std::string("kitti")},
                   {"csv", std::string("csv")}},
                  "auto: a .csv is pedtrack's detections.csv, anything else a KITTI file")
          .text(&P::calib, "calib",
                "KITTI: the sequence's calibration file (P2, R0_rect, Tr_velo_to_cam); auto: "
                "calib/NAME beside the detections' folder (KITTI's layout)")
          .text(&P::classes, "classes",
                "KITTI: the classes replayed (Pedestrian, Car, Cyclist, Person_sitting, ...)")
          .include(&P::rig, kitti::kittiRigTable())
          .integer(&P::frames, "frames", "", 0, 1e6,
                   "KITTI: frames in the sequence (frames after the last detection are empty); "
                   "0: up to the last frame with a detection")
          .text(&P::oxts, "oxts",
                "KITTI: the vehicle's OXTS records (tracking oxts/SSSS.txt, a line per frame) for "
                "its motion; none: the sensor is the fixed frame")
          .include(&P::replay, replayRateTable());
  return t;
}

class DetectionsSource : public Sensor {
 public:
  explicit DetectionsSource(const PluginContext& ctx) : p_(table().read(ctx.params)) {
    const ParamSet& ps = ctx.params;
    csv_ = p_.format == "csv" || (p_.format == "auto" && fs::path(p_.file).extension() == ".csv");
    if (csv_) {
      csv_frames_ = readDetectionsCsv(p_.file);
      next_csv_ = csv_frames_.begin();
      return;
    }
    const std::string calib = p_.calib == "auto" ? kittiCalibBeside(p_.file) : p_.calib;
    if (calib.empty())
      throw ConfigError(table().where(ps, &DetectionsParams::calib) + ": no calibration beside '" +
                        p_.file + "' (looked for ../calib/" +
                        fs::path(p_.file).filename().string() + "); give calib=CALIB/SSSS.txt");
    if (!fs::is_regular_file(calib))
      throw ConfigError(table().where(ps, &DetectionsParams::calib) + ": '" + calib +
                        "' is not a file");
    calib_ = readKittiCalib(calib);
    for (auto& [frame, dets] : readKittiDetections(p_.file))
      for (const KittiDetection& d : dets)
        if (wanted(d.type)) kitti_[frame].push_back(d);
    last_ = p_.frames > 0 ? p_.frames - 1 : kitti_.empty() ? -1 : kitti_.rbegin()->first;
    if (p_.oxts != "none") {
      if (!fs::exists(p_.oxts))
        throw ConfigError(table().where(ps, &DetectionsParams::oxts) + ": '" + p_.oxts +
                          "' does not exist");
      oxts_.emplace(p_.oxts, p_.rig);
    }
  }

  void start(const std::string& out_dir) override {
    // An earlier run's kitti_tracks.txt would be read as this run's.
    if (csv_ && !out_dir.empty()) fs::remove(fs::path(out_dir) / "kitti_tracks.txt");
    if (!csv_ && !out_dir.empty())
      writer_ = std::make_unique<KittiTracksWriter>(out_dir + "/kitti_tracks.txt", calib_,
                                                    p_.rig.mount_z, resultClass());
  }

  void finish() override {
    if (writer_) writer_->close();
  }

  bool next(Frame& frame) override {
    const bool more = csv_ ? nextCsv(frame) : nextKitti(frame);
    if (more && p_.replay.realtime) pacer_.wait(frame.t);
    return more;
  }

  bool detectionsOnly() const override { return true; }

  void results(const Frame& f) override {
    if (writer_) writer_->write(std::lround(f.t * p_.rig.scan_rate), f);
  }

  double progress() const override {
    if (csv_) return csv_frames_.empty() ? 1 : double(done_) / double(csv_frames_.size());
    return last_ < 0 ? 1 : double(frame_) / double(last_ + 1);
  }

  std::vector<std::pair<std::string, long>> counters() const override {
    if (!writer_) return {};
    return {{"tracks_out_of_view_camera", long(writer_->outOfView())}};
  }

 private:
  // KITTI's class names, in any case (tracking files are read in lower case).
  bool wanted(const std::string& type) const {
    const auto same = [](const std::string& a, const std::string& b) {
      return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
             });
    };
    for (const auto& c : p_.classes)
      if (same(c, type)) return true;
    return false;
  }
  std::string resultClass() const {
    return p_.classes.size() == 1 ? p_.classes.front() : "Pedestrian";
  }

  bool nextKitti(Frame& frame) {
    if (frame_ > last_) return false;
    frame.t = double(frame_) / p_.rig.scan_rate;
    if (oxts_) {
      frame.robot_pose = oxts_->robotPose(frame_);
      frame.has_odometry = true;
    }
    const mrpt::poses::CPose3D mount(0, 0, p_.rig.mount_z, 0, 0, 0);
    frame.sensor_pose = frame.robot_pose + mount;
    const auto it = kitti_.find(frame_);
    if (it != kitti_.end())
      for (const KittiDetection& k : it->second) {
        const Eigen::Vector3d velo = calib_.veloFromRect({k.box.x, k.box.y, k.box.z});
        Detection d;
        double z = 0;
        frame.robot_pose.composePoint(velo.x(), velo.y(), velo.z() + p_.rig.mount_z, d.x, d.y, z);
        d.score = k.score;
        d.yaw = std::remainder(veloYawFromRotationY(k.box.ry) + frame.robot_pose.yaw(), 2 * M_PI);
        d.box = {z, k.box.h, k.box.w, k.box.l};
        frame.detections.push_back(d);
      }
    ++frame_;
    return true;
  }

  bool nextCsv(Frame& frame) {
    if (next_csv_ == csv_frames_.end()) return false;
    frame.t = next_csv_->second.t;
    frame.detections = next_csv_->second.detections;
    ++next_csv_, ++done_;
    return true;
  }

  DetectionsParams p_;
  bool csv_ = false;
  KittiCalib calib_;
  std::map<long, std::vector<KittiDetection>> kitti_;
  long frame_ = 0, last_ = -1;
  std::optional<kitti::OxtsTrajectory> oxts_;
  std::map<long, CsvFrame> csv_frames_;
  std::map<long, CsvFrame>::const_iterator next_csv_;
  std::size_t done_ = 0;
  std::unique_ptr<KittiTracksWriter> writer_;
  ReplayPacer pacer_;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Sensor;
  d.doc = "Replays a detector's output (KITTI 3D detections, detections.csv) to the trackers";
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<DetectionsSource>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::detections

PEDTRACK_PLUGIN("detections", pedtrack::detections::describe)
