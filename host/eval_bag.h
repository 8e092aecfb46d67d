#pragma once
// Truth from a labelled ROS1 bag (leg_tracker's training bags): the leg positions of
// `labels_topic` (geometry_msgs/PoseArray, laser frame) for every scan of the scan topic.
#include <string>
#include <vector>

#include "pedtrack/eval/frames.h"

namespace pedtrack::cli {

struct BagLabels {
  std::string scan_topic;                 ///< the topic the scans came from
  std::vector<eval::TimedObjects> scans;  ///< one per scan, t = its header stamp, by t
};

/// A label array belongs to the scan with the same header stamp; an array with a zero stamp (as
/// in leg_tracker's *_extracted.bags, whose arrays are unstamped) belongs to the next scan in bag
/// order, as leg_tracker's train_leg_detector reads them. A scan without labels has no truth
/// points (every detection there is a false positive); `labels_topic` "none" reads the bag as
/// having no people at all (leg_tracker's negative_2.bag). `scan_topic` empty: the bag's only
/// sensor_msgs/LaserScan topic. Throws ConfigError (bad bag, missing or ambiguous topic).
BagLabels readBagLabels(const std::string& path, const std::string& scan_topic,
                        const std::string& labels_topic);

/// The people of a leg_tracker benchmark bag (ICRA 2015): each message of `people_topic`
/// (leg_tracker/Person: pose, id; decoded from the bag's own message definition) is written
/// right after the scan it annotates, so it belongs to the last scan before it in bag order, as
/// the benchmark's clear_mot.py reads them. One entry per scan of `scan_topic` (empty: the only
/// LaserScan topic), t = its header stamp, the people at their pose's x, y (laser frame), id =
/// the person's id. `people_topic` empty: the bag's only leg_tracker/Person topic.
struct BagPeople {
  std::string scan_topic, people_topic;
  std::vector<eval::TimedObjects> scans;
};
BagPeople readBagPeople(const std::string& path, const std::string& scan_topic,
                        const std::string& people_topic);

/// The bag's topic of leg_tracker/Person messages, or "" when it has none.
std::string bagPeopleTopic(const std::string& path);

/// The truth bags read so far that were cut short (or unindexed) and re-indexed: each was warned
/// about once; the command exits 1 after scoring what they hold.
std::vector<std::string> truthBagsCutShort();

}  // namespace pedtrack::cli
