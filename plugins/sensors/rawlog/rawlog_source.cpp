// `rawlog` sensor: streams an MRPT rawlog (observations-only or sensory-frame+actions format,
// gz-compressed or plain) entry by entry, with odometry from the log's actions/observations.
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CActionRobotMovement3D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/datetime.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "entry_stream.h"
#include "pedtrack/errors.h"
#include "pedtrack/plugin.h"
#include "pedtrack/replay_pacer.h"
#include "pedtrack/text.h"

namespace pedtrack::rawlog {
namespace {

using namespace mrpt::obs;

struct RawlogParams {
  std::string file;
  ReplayRateParams rate;
  std::string sensor_label;  // comma list; empty: every range sensor
  bool skip_bad = false;
};

const ParamTable<RawlogParams>& table() {
  using P = RawlogParams;
  static const auto t =
      ParamTable<P>()
          .inputFile(&P::file, "file", "the rawlog to replay")
          .include(&P::rate, replayRateTable())
          .text(&P::sensor_label, "sensor_label",
                "only observations with these sensor labels (comma list; empty: all range "
                "sensors)")
          .boolean(&P::skip_bad, "skip_bad",
                   "skip unreadable entries with a warning instead of stopping with an error");
  return t;
}

class RawlogSource : public Sensor {
 public:
  explicit RawlogSource(const PluginContext& ctx) : RawlogSource(table().read(ctx.params)) {}
  explicit RawlogSource(const RawlogParams& p)
      : file_(p.file),
        stream_(file_),
        archive_(mrpt::serialization::archiveFrom(stream_)),
        realtime_(p.rate.realtime),
        skip_bad_(p.skip_bad),
        labels_(splitList(p.sensor_label)),
        file_size_(std::filesystem::file_size(file_)),
        gz_(isGz(file_)) {}

  bool next(Frame& frame) override {
    for (;;) {
      mrpt::serialization::CSerializable::Ptr obj = readEntry();
      if (!obj) return false;
      if (auto sf = std::dynamic_pointer_cast<CSensoryFrame>(obj)) {
        for (const auto& o : *sf) {
          // `pedtrack run --record` puts a frame's odometry beside its scans.
          if (auto odo = std::dynamic_pointer_cast<CObservationOdometry>(o)) {
            odometry_ = mrpt::poses::CPose3D(odo->odometry);
            has_odometry_ = true;
          } else if (o && wanted(*o)) {
            frame.observations.push_back(o);
          }
        }
      } else if (auto acts = std::dynamic_pointer_cast<CActionCollection>(obj)) {
        applyActions(*acts);
      } else if (auto odo = std::dynamic_pointer_cast<CObservationOdometry>(obj)) {
        odometry_ = mrpt::poses::CPose3D(odo->odometry);
        has_odometry_ = true;
      } else if (auto obs = std::dynamic_pointer_cast<CObservation>(obj)) {
        if (wanted(*obs)) frame.observations.push_back(obs);
      }
      if (frame.observations.empty()) continue;
      // The newest observation's time, as the bag source does: a frame of several scanners is
      // the robot when its last scan came in (and a recorded bag frame replays as it ran).
      frame.t = -INFINITY;
      for (const auto& o : frame.observations)
        frame.t = std::max(frame.t, mrpt::Clock::toDouble(o->timestamp));
      frame.robot_pose = odometry_;
      frame.has_odometry = has_odometry_;
      for (const auto& o : frame.observations) {
        mrpt::poses::CPose3D mount;
        o->getSensorPose(mount);
        frame.sensors.push_back({o->sensorLabel, odometry_ + mount});
      }
      frame.sensor_pose = frame.sensors.front().pose;
      if (realtime_) pacer_.wait(frame.t);
      return true;
    }
  }

  double progress() const override {
    // A plain file's offset is exact; a gz file's uncompressed offset has no known total.
    if (gz_ || file_size_ == 0) return -1;
    return std::min(1.0, static_cast<double>(stream_.getPosition()) / file_size_);
  }

  std::size_t entriesSkipped() const override { return skipped_; }

  void finish() override {
    if (skipped_) std::cerr << "warning: " << file_ << ": skipped " << skipped_ << " bad entries\n";
  }

 private:
  static bool isGz(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    unsigned char m[2] = {0, 0};
    f.read(reinterpret_cast<char*>(m), 2);
    return m[0] == 0x1f && m[1] == 0x8b;
  }

  bool wanted(const CObservation& o) const {
    if (!isRangeObservation(o)) return false;
    return labels_.empty() ||
           std::find(labels_.begin(), labels_.end(), o.sensorLabel) != labels_.end();
  }

  void applyActions(const CActionCollection& acts) {
    for (const auto& a : acts) {
      has_odometry_ |= std::dynamic_pointer_cast<CActionRobotMovement2D>(a.get_ptr()) ||
                       std::dynamic_pointer_cast<CActionRobotMovement3D>(a.get_ptr());
      if (auto m2 = std::dynamic_pointer_cast<CActionRobotMovement2D>(a.get_ptr())) {
        mrpt::poses::CPose2D inc;
        m2->poseChange->getMean(inc);
        odometry_ = odometry_ + mrpt::poses::CPose3D(inc);
      } else if (auto m3 = std::dynamic_pointer_cast<CActionRobotMovement3D>(a.get_ptr())) {
        odometry_ = odometry_ + m3->poseChange.mean;
      }
    }
  }

  // Reads one top-level entry; nullptr at a clean end of file. A bad entry throws DataError, or
  // with skip_bad is reported and skipped by resynchronising on the next object header.
  mrpt::serialization::CSerializable::Ptr readEntry() {
    for (;;) {
      stream_.beginEntry();
      try {
        auto obj = archive_.ReadObject();
        ++entry_;
        return obj;
      } catch (const std::exception& e) {
        // MRPT wraps the end-of-file inside an object in a generic exception: ask the stream.
        const bool eof = stream_.atEnd();
        if (eof && stream_.entryBytes() == 0) return nullptr;
        std::string what = e.what();
        if (!stream_.refusal().empty())
          what = "unreadable: " + stream_.refusal();
        else
          what = eof ? "truncated (end of file inside the entry)" : "unreadable: " + oneLine(what);
        const std::string msg = file_ + ": entry " + std::to_string(entry_) + " (byte " +
                                std::to_string(stream_.entryOffset()) + "): " + what;
        if (!skip_bad_) throw DataError(msg);
        std::cerr << "warning: " << msg << "; skipped\n";
        ++skipped_;
        ++entry_;
        // Corrupt compressed data met while searching ends the replay, named like any entry.
        bool found = false;
        try {
          found = stream_.resync();
        } catch (const std::exception& r) {
          throw DataError(file_ + ": while skipping bad entries: " + oneLine(r.what()));
        }
        if (!found) return nullptr;
      }
    }
  }

  std::string file_;
  EntryStream stream_;
  mrpt::serialization::CArchiveStreamBase<EntryStream> archive_;
  bool realtime_, skip_bad_;
  std::vector<std::string> labels_;
  std::uintmax_t file_size_;
  bool gz_;
  mrpt::poses::CPose3D odometry_;
  bool has_odometry_ = false;  // an odometry observation or robot-movement action was read
  std::size_t entry_ = 0, skipped_ = 0;
  ReplayPacer pacer_;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Sensor;
  d.doc = "Replays an MRPT rawlog (.rawlog, gz or plain; observations or sensory-frame format)";
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<RawlogSource>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::rawlog

PEDTRACK_PLUGIN("rawlog", pedtrack::rawlog::describe)
