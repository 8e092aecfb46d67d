#include "eval_bag.h"

#include <geometry_msgs/PoseArray.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/LaserScan.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <set>

#include "pedtrack/bag_open.h"
#include "pedtrack/errors.h"
#include "pedtrack/ros_checked_message.h"
#include "pedtrack/text.h"
#include "ros_message_decode.h"

namespace pedtrack::cli {
namespace {

const std::string kLaserScan = "sensor_msgs/LaserScan";
const std::string kPoseArray = "geometry_msgs/PoseArray";
const std::string kPerson = "leg_tracker/Person";

std::set<std::string>& cutShort() {
  static std::set<std::string> paths;
  return paths;
}

void openBag(rosbag::Bag& bag, const std::string& path) {
  try {
    if (const auto kept = openBagForReading(bag, path)) {
      if (cutShort().insert(path).second)  // one warning a bag, however often it is opened
        std::cerr << "warning: --truth " << recoveryWarning(path, *kept) << "\n";
    }
  } catch (const std::exception& e) {
    throw ConfigError("--truth: cannot open bag '" + path + "': " + oneLine(e.what()));
  }
}

std::set<std::string> topicsOf(const rosbag::Bag& bag, const std::string& datatype) {
  std::set<std::string> topics;
  rosbag::View all(bag);
  for (const rosbag::ConnectionInfo* c : all.getConnections())
    if (c->datatype == datatype) topics.insert(c->topic);
  return topics;
}

std::string chooseScanTopic(const rosbag::Bag& bag, const std::string& path,
                            const std::string& wanted) {
  std::set<std::string> scans;
  rosbag::View all(bag);
  for (const rosbag::ConnectionInfo* c : all.getConnections())
    if (c->datatype == kLaserScan) scans.insert(c->topic);
  if (!wanted.empty()) {
    if (!scans.count(wanted))
      throw ConfigError("--topic: " + path + " has no " + kLaserScan + " topic '" + wanted + "'");
    return wanted;
  }
  if (scans.size() == 1) return *scans.begin();
  std::string list;
  for (const auto& t : scans) list += (list.empty() ? "" : ", ") + t;
  throw ConfigError(
      path + ": " +
      (scans.empty() ? "no " + kLaserScan + " topic" : "several scan topics (" + list + ")") +
      "; name the scans with --topic");
}

std::vector<eval::Object> toObjects(const geometry_msgs::PoseArray& a) {
  std::vector<eval::Object> out;
  for (std::size_t i = 0; i < a.poses.size(); ++i) {
    eval::Object o;
    o.id = long(i);
    o.x = a.poses[i].position.x;
    o.y = a.poses[i].position.y;
    o.range = std::hypot(o.x, o.y);  // laser frame
    out.push_back(o);
  }
  return out;
}

}  // namespace

std::vector<std::string> truthBagsCutShort() {
  return std::vector<std::string>(cutShort().begin(), cutShort().end());
}

BagLabels readBagLabels(const std::string& path, const std::string& scan_topic,
                        const std::string& labels_topic) {
  rosbag::Bag bag;
  openBag(bag, path);
  BagLabels out;
  out.scan_topic = chooseScanTopic(bag, path, scan_topic);
  const bool unlabelled = labels_topic == "none";  // a bag with no people: no truth anywhere
  if (!unlabelled) {
    rosbag::View labels(bag, rosbag::TopicQuery(labels_topic));
    bool ok = labels.size() > 0;
    for (const rosbag::ConnectionInfo* c : labels.getConnections())
      ok = ok && c->datatype == kPoseArray;
    if (!ok)
      throw ConfigError(path + ": no " + kPoseArray + " topic '" + labels_topic +
                        "' (the labelled leg positions; see --labels-topic)");
  }
  // Bag order: unstamped arrays wait for the next scan; stamped ones are matched by stamp.
  std::map<double, std::vector<eval::Object>> stamped;
  std::vector<eval::Object> pending;
  std::vector<std::pair<double, std::vector<eval::Object>>> unstamped_for_scan;
  try {
    rosbag::View view(bag,
                      rosbag::TopicQuery(std::vector<std::string>{out.scan_topic, labels_topic}));
    for (const rosbag::MessageInstance& m : view) {
      if (m.getTopic() == labels_topic) {
        auto a = checkedInstantiate<geometry_msgs::PoseArray>(m);
        if (!a) continue;
        if (a->header.stamp.isZero())
          pending = toObjects(*a);
        else
          stamped[a->header.stamp.toSec()] = toObjects(*a);
      } else if (auto s = checkedInstantiate<sensor_msgs::LaserScan>(m)) {
        unstamped_for_scan.emplace_back(s->header.stamp.toSec(), std::move(pending));
        pending.clear();
      }
    }
  } catch (const std::exception& e) {
    throw DataError(path + ": " + oneLine(e.what()));
  }
  for (auto& [t, objects] : unstamped_for_scan) {
    eval::TimedObjects to{t, std::move(objects)};
    // A stamped array within 0.1 ms of the scan is its label, whatever the bag order.
    auto it = stamped.lower_bound(t - 1e-4);
    if (it != stamped.end() && it->first <= t + 1e-4) to.objects = it->second;
    out.scans.push_back(std::move(to));
  }
  std::stable_sort(
      out.scans.begin(), out.scans.end(),
      [](const eval::TimedObjects& a, const eval::TimedObjects& b) { return a.t < b.t; });
  return out;
}

std::string bagPeopleTopic(const std::string& path) {
  rosbag::Bag bag;
  openBag(bag, path);
  const std::set<std::string> topics = topicsOf(bag, kPerson);
  return topics.size() == 1 ? *topics.begin() : std::string();
}

BagPeople readBagPeople(const std::string& path, const std::string& scan_topic,
                        const std::string& people_topic) {
  rosbag::Bag bag;
  openBag(bag, path);
  BagPeople out;
  out.scan_topic = chooseScanTopic(bag, path, scan_topic);
  const std::set<std::string> people = topicsOf(bag, kPerson);
  out.people_topic = people_topic;
  if (out.people_topic.empty() && people.size() == 1) out.people_topic = *people.begin();
  if (!people.count(out.people_topic))
    throw ConfigError(path + ": no " + kPerson + " topic" +
                      (out.people_topic.empty() ? "" : " '" + out.people_topic + "'") +
                      " (the annotated people; see --labels-topic)");
  std::unique_ptr<RosMessageSchema> schema;
  try {
    rosbag::View view(
        bag, rosbag::TopicQuery(std::vector<std::string>{out.scan_topic, out.people_topic}));
    for (const rosbag::MessageInstance& m : view) {
      if (m.getTopic() == out.people_topic) {
        if (!schema) schema = std::make_unique<RosMessageSchema>(kPerson, m.getMessageDefinition());
        if (out.scans.empty()) continue;  // before the first scan: annotates nothing
        std::vector<std::uint8_t> bytes(m.size());
        ros::serialization::OStream os(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
        m.write(os);
        const auto f = schema->numbers(bytes.data(), bytes.size());
        const auto x = f.find("pose.position.x"), y = f.find("pose.position.y"), id = f.find("id");
        if (x == f.end() || y == f.end() || id == f.end())
          throw DataError(out.people_topic + ": a " + kPerson + " without pose.position or id");
        eval::Object o;
        o.id = long(id->second);
        o.x = x->second;
        o.y = y->second;
        o.range = std::hypot(o.x, o.y);  // laser frame
        out.scans.back().objects.push_back(o);
      } else if (auto scan = checkedInstantiate<sensor_msgs::LaserScan>(m)) {
        out.scans.push_back({scan->header.stamp.toSec(), {}});
      }
    }
  } catch (const ConfigError&) {
    throw;
  } catch (const std::exception& e) {
    throw DataError(path + ": " + oneLine(e.what()));
  }
  std::stable_sort(
      out.scans.begin(), out.scans.end(),
      [](const eval::TimedObjects& a, const eval::TimedObjects& b) { return a.t < b.t; });
  return out;
}

}  // namespace pedtrack::cli
