#include "pedtrack/sim/sensor_model.h"

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationVelodyneScan.h>
#include <mrpt/obs/VelodyneCalibration.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "pedtrack/errors.h"
#include "pedtrack/sim/geometry.h"
#include "pedtrack/velodyne_decode.h"

namespace pedtrack::sim {
namespace {

constexpr double kDeg = M_PI / 180.0;
using Velo = mrpt::obs::CObservationVelodyneScan;

// The simulated VLP-16 turns at 10 Hz: 0.4° per firing block (0.2° per firing), in 0.01° units.
constexpr int kBlockUnits = 40;
constexpr int kColumns = 1800;  // 0.2° columns over 360°

const mrpt::obs::VelodyneCalibration& vlp16Calibration() {
  static const auto calib = mrpt::obs::VelodyneCalibration::LoadDefaultCalibration("VLP16");
  return calib;
}

// Velodyne azimuth (clockwise from the device's forward axis, 0.01° units) to the MRPT sensor
// frame angle (counter-clockwise from +x). Checked against MRPT's decoder by test_sim.
double velodyneToMrptAngle(int units) {
  return -units * 0.01 * kDeg;
}

}  // namespace

double sweepTime(const SensorSpec& spec, double azimuth) {
  const double period = 1.0 / spec.rate;
  if (spec.is3d) {
    const double cw = std::fmod(-azimuth + 4 * M_PI, 2 * M_PI);  // clockwise from forward
    return cw / (2 * M_PI) * period;
  }
  const double from_start = std::fmod(azimuth + 0.5 * spec.fov + 4 * M_PI, 2 * M_PI);
  return std::min(from_start, spec.fov) / (2 * M_PI) * period;
}

SensorSpec sensorDefaults(const std::string& model) {
  SensorSpec s;
  s.model = model;
  if (model == "utm30lx") {  // Hokuyo UTM-30LX: 270°, 0.25°, 0.1–30 m, 40 Hz, ±30 mm
    s.fov = 270 * kDeg;
    s.resolution = 0.25 * kDeg;
    s.min_range = 0.1;
    s.max_range = 30;
    s.rate = 40;
    s.range_noise = 0.01;
    s.label = "LASER";
  } else if (model == "urg04lx") {  // Hokuyo URG-04LX: 240°, 360/1024°, 0.02–5.6 m, 10 Hz
    s.fov = 240 * kDeg;
    s.resolution = 360.0 / 1024.0 * kDeg;
    s.min_range = 0.02;
    s.max_range = 5.6;
    s.rate = 10;
    s.range_noise = 0.01;
    s.label = "LASER";
  } else if (model == "vlp16") {  // Velodyne VLP-16: 16 rings ±15°, 0.2° at 10 Hz, 100 m, ~3 cm
    s.is3d = true;
    s.fov = 2 * M_PI;
    s.resolution = 0.2 * kDeg;
    s.min_range = 0.4;
    s.max_range = 100;
    s.rate = 10;
    s.range_noise = 0.03;
    s.label = "VELODYNE";
  } else if (model == "custom2d") {  // caller sets fov/resolution/range/rate
    s.range_noise = 0.01;
    s.min_range = 0.05;
    s.label = "LASER";
  } else {
    throw ConfigError("unknown sensor model '" + model + "' (utm30lx, urg04lx, vlp16, custom2d)");
  }
  return s;
}

void RangeImage::reset(int r, int c) {
  rings = r;
  cols = c;
  range.assign(static_cast<std::size_t>(r) * c, kNoHit);
  owner.assign(static_cast<std::size_t>(r) * c, kOwnerGround);
}

RayTable::RayTable(const SensorSpec& spec) {
  if (spec.is3d) {
    const auto& calib = vlp16Calibration();
    rings_ = static_cast<int>(calib.laser_corrections.size());
    cols_ = kColumns;
    full_circle_ = true;
    az0_ = 0;
    daz_ = -0.2 * kDeg;  // columns advance clockwise
    dir_.resize(static_cast<std::size_t>(rings_) * cols_);
    for (int l = 0; l < rings_; ++l) {
      const auto& lc = calib.laser_corrections[l];
      elev_.push_back(lc.verticalCorrection * kDeg);
      for (int c = 0; c < cols_; ++c) {
        const int units = (c / 2) * kBlockUnits + vlp16::azimuthOffset(l, c % 2, kBlockUnits);
        const double a = velodyneToMrptAngle(units);
        dir_[l * cols_ + c] = {lc.cosVertCorrection * std::cos(a),
                               lc.cosVertCorrection * std::sin(a), lc.sinVertCorrection};
      }
    }
    return;
  }
  rings_ = 1;
  cols_ = static_cast<int>(std::lround(spec.fov / spec.resolution)) + 1;
  daz_ = spec.resolution;
  az0_ = -0.5 * daz_ * (cols_ - 1);
  elev_ = {0};
  for (int c = 0; c < cols_; ++c) {
    const double a = az0_ + c * daz_;
    dir_.emplace_back(std::cos(a), std::sin(a), 0);
  }
}

int RayTable::columnRanges(double azimuth, double half_width, int out[4]) const {
  const double pad = std::abs(daz_) * (full_circle_ ? 2.5 : 1.0);  // VLP-16 per-laser offsets
  const double hw = half_width + pad;
  if (full_circle_) {
    if (hw >= M_PI) {
      out[0] = 0;
      out[1] = cols_ - 1;
      return 1;
    }
    // Column index grows with (azimuth - az0) / daz, modulo the full circle.
    const double centre = (azimuth - az0_) / daz_;
    const double span = hw / std::abs(daz_);
    const long c0 = static_cast<long>(std::floor(centre - span)),
               c1 = static_cast<long>(std::ceil(centre + span));
    const long n = cols_;
    const long a = ((c0 % n) + n) % n, len = std::min(c1 - c0, n - 1);
    if (a + len < n) {
      out[0] = int(a);
      out[1] = int(a + len);
      return 1;
    }
    out[0] = int(a);
    out[1] = int(n - 1);
    out[2] = 0;
    out[3] = int(a + len - n);
    return 2;
  }
  // 2D scanner: one range inside the aperture (wrapped azimuth).
  double lo = std::remainder(azimuth - hw, 2 * M_PI), hi = lo + 2 * hw;
  int k = 0;
  for (double shift : {0.0, 2 * M_PI, -2 * M_PI}) {
    const double l = lo + shift, h = hi + shift;
    const long c0 = std::max(0L, static_cast<long>(std::floor((l - az0_) / daz_)));
    const long c1 = std::min(long(cols_) - 1, static_cast<long>(std::ceil((h - az0_) / daz_)));
    if (c0 <= c1 && k < 2) {
      out[2 * k] = int(c0);
      out[2 * k + 1] = int(c1);
      ++k;
    }
  }
  return k;
}

ObservationMaker::ObservationMaker(const SensorSpec& spec, unsigned long seed)
    : spec_(spec), reflectivity_(seed), physics_rng_(seed ^ 0xbb67ae8584caa73bull) {}

mrpt::obs::CObservation::Ptr ObservationMaker::make(const RangeImage& img, double t,
                                                    std::mt19937_64& rng,
                                                    ReturnTruth& truth) const {
  truth.owners.clear();
  return spec_.is3d ? makeVelodyne(img, t, rng, truth) : make2D(img, t, rng, truth);
}

// One return produced on `owner`: counted for its person and listed in cloud order.
static void recordReturn(int owner, ReturnTruth& truth) {
  if (owner > 0 && owner < int(truth.per_person.size())) ++truth.per_person[owner];
  if (truth.record_owners) truth.owners.push_back(owner);
}

mrpt::obs::CObservation::Ptr ObservationMaker::make2D(const RangeImage& img, double t,
                                                      std::mt19937_64& rng,
                                                      ReturnTruth& truth) const {
  auto scan = mrpt::obs::CObservation2DRangeScan::Create();
  scan->sensorLabel = spec_.label;
  scan->timestamp = mrpt::Clock::fromDouble(t);
  scan->aperture = static_cast<float>(spec_.resolution * (img.cols - 1));
  scan->rightToLeft = true;
  scan->maxRange = static_cast<float>(spec_.max_range);
  scan->stdError = static_cast<float>(spec_.range_noise);
  scan->sensorPose = spec_.mount;
  scan->resizeScan(img.cols);
  std::normal_distribution<double> noise(0, spec_.range_noise);
  std::uniform_real_distribution<double> u01(0, 1);
  for (int c = 0; c < img.cols; ++c) {
    double r = img.range[c];
    bool ok = r <= spec_.max_range && r >= spec_.min_range;
    // Always draw both numbers so one beam's outcome never shifts another's noise.
    const double n = noise(rng), drop = u01(rng);
    if (ok && drop < spec_.dropout) ok = false;
    if (ok) {
      r = std::round((r + n) * 1000.0) / 1000.0;  // 1 mm resolution
      ok = r >= spec_.min_range && r <= spec_.max_range;
    }
    scan->setScanRange(c, ok ? static_cast<float>(r) : scan->maxRange);
    scan->setScanRangeValidity(c, ok);
    if (ok) recordReturn(img.owner[c], truth);
  }
  return scan;
}

mrpt::obs::CObservation::Ptr ObservationMaker::makeVelodyne(const RangeImage& img, double t,
                                                            std::mt19937_64& rng,
                                                            ReturnTruth& truth) const {
  auto obs = Velo::Create();
  obs->sensorLabel = spec_.label;
  obs->timestamp = mrpt::Clock::fromDouble(t);
  obs->originalReceivedTimestamp = obs->timestamp;
  obs->has_satellite_timestamp = false;
  obs->sensorPose = spec_.mount;
  obs->minRange = spec_.min_range;
  obs->maxRange = spec_.max_range;
  obs->calibration = vlp16Calibration();
  const auto& calib = obs->calibration;
  std::normal_distribution<double> noise(0, spec_.range_noise);
  std::uniform_real_distribution<double> u01(0, 1);

  const int blocks = kColumns / 2, per_packet = Velo::BLOCKS_PER_PACKET;
  const int packets = blocks / per_packet;
  obs->scan_packets.resize(packets);
  // µs since the top of the hour, as the device stamps packets.
  const double us0 = std::fmod(t, 3600.0) * 1e6;
  std::vector<unsigned char> raw(sizeof(Velo::TVelodyneRawPacket));
  for (int p = 0; p < packets; ++p) {
    unsigned char* out = raw.data();
    for (int j = 0; j < per_packet; ++j) {
      const int b = p * per_packet + j;
      const uint16_t header = Velo::UPPER_BANK, rot = uint16_t((b * kBlockUnits) % 36000);
      std::memcpy(out, &header, 2);
      std::memcpy(out + 2, &rot, 2);
      out += 4;
      for (int k = 0; k < Velo::SCANS_PER_BLOCK; ++k) {
        const int laser = k % 16, col = 2 * b + k / 16;
        const std::size_t i = static_cast<std::size_t>(laser) * img.cols + col;
        double r = img.range[i];
        const double n = noise(rng), drop = u01(rng);
        uint16_t units = 0;
        uint8_t intensity = 0;
        if (r >= spec_.min_range && r <= spec_.max_range && drop >= spec_.dropout) {
          r += n;
          const long u = std::lround(r / Velo::DISTANCE_RESOLUTION);
          // Encode only what the decoder keeps (its range check, after the calibration's
          // distance correction), so the truth lists exactly the decoded points.
          const double decoded =
              u * Velo::DISTANCE_RESOLUTION + calib.laser_corrections[laser].distanceCorrection;
          if (u > 0 && u < 65535 && decoded >= spec_.min_range && decoded <= spec_.max_range) {
            units = static_cast<uint16_t>(u);
            const int owner = img.owner[i];
            intensity = reflectivity_.of(owner);
            recordReturn(owner, truth);
          }
        }
        std::memcpy(out, &units, 2);
        out[2] = intensity;
        out += 3;
      }
    }
    const uint32_t us =
        static_cast<uint32_t>(std::fmod(us0 + p * per_packet * vlp16::kBlockUs, 3600e6));
    std::memcpy(out, &us, 4);
    out[4] = Velo::RETMODE_STRONGEST;
    out[5] = 0x22;  // VLP-16
    std::memcpy(&obs->scan_packets[p], raw.data(), raw.size());
  }
  return obs;
}

}  // namespace pedtrack::sim
