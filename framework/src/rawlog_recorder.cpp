#include "pedtrack/rawlog_recorder.h"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/serialization/CArchive.h>

#include "pedtrack/errors.h"

namespace pedtrack {

struct RawlogRecorder::Impl {
  mrpt::io::CFileGZOutputStream out;
};

RawlogRecorder::RawlogRecorder(const std::string& path)
    : impl_(std::make_unique<Impl>()), path_(path) {
  if (!impl_->out.open(path)) throw DataError(path + ": cannot open for writing (--record)");
}

RawlogRecorder::~RawlogRecorder() {
  try {
    close();
  } catch (...) {
  }
}

void RawlogRecorder::write(const Frame& frame) {
  if (!impl_->out.is_open()) return;
  auto ar = mrpt::serialization::archiveFrom(impl_->out);
  try {
    // One sensory frame per frame, so the scanners merged into one frame replay as one. The
    // odometry first: the rawlog source applies it to the observations beside it.
    mrpt::obs::CSensoryFrame sf;
    if (frame.has_odometry) {
      auto odo = mrpt::obs::CObservationOdometry::Create();
      odo->odometry = mrpt::poses::CPose2D(frame.robot_pose);
      odo->timestamp = frame.observations.empty() ? mrpt::Clock::fromDouble(frame.t)
                                                  : frame.observations.front()->timestamp;
      odo->sensorLabel = "ODOMETRY";
      sf.insert(odo);
    }
    for (const auto& o : frame.observations)
      if (o) sf.insert(o);
    ar << sf;
  } catch (const std::exception& e) {
    throw DataError(path_ + ": cannot write frame " + std::to_string(frame.index) +
                    " (--record): " + e.what());
  }
  ++written_;
}

void RawlogRecorder::close() {
  if (impl_ && impl_->out.is_open()) impl_->out.close();
}

}  // namespace pedtrack
