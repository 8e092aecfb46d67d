#include "ros_node.h"

#include <ros/init.h>
#include <ros/master.h>
#include <ros/names.h>

#include <chrono>
#include <thread>

#include "pedtrack/errors.h"
#include "pedtrack/text.h"

namespace pedtrack::ros_plugins {

void ensureNode(const std::string& node_name, double master_timeout) {
  if (!ros::isInitialized()) {
    try {
      // pedtrack's own SIGINT/SIGTERM handlers stop the pipeline, which then shuts ROS down
      // with the last node handle; roscpp's handler would shut down under the running stages.
      ros::init(ros::M_string(), node_name, ros::init_options::NoSigintHandler);
    } catch (const std::exception& e) {
      throw ConfigError("node: '" + node_name + "': " + oneLine(e.what()));
    }
  }
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(master_timeout);
  while (!ros::master::check()) {
    if (std::chrono::steady_clock::now() >= deadline)
      throw ConfigError("no ROS master answers at " + ros::master::getURI() + " (waited " +
                        std::to_string(master_timeout) +
                        " s; start `roscore` or set ROS_MASTER_URI)");
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
}

ResolvedTopic resolveTopic(const std::string& topic) {
  const std::string t = trim(topic);
  if (t.empty()) throw ConfigError("empty topic name");
  std::string err;
  if (t[0] == '~') {
    std::string rest = t.substr(1);
    if (!rest.empty() && rest[0] == '/') rest.erase(0, 1);
    if (!ros::names::validate(rest, err)) throw ConfigError("topic '" + t + "': " + err);
    return {ros::NodeHandle("~"), rest};
  }
  if (!ros::names::validate(t, err)) throw ConfigError("topic '" + t + "': " + err);
  return {ros::NodeHandle(), t};
}

const ParamTable<NodeParams>& nodeTable() {
  static const auto t =
      ParamTable<NodeParams>()
          .text(&NodeParams::node, "node",
                "ROS node name (the first ROS plugin created names the node)")
          .real(&NodeParams::master_timeout, "master_timeout", "s", 0, 3600,
                "how long to wait for the ROS master at $ROS_MASTER_URI before giving up");
  return t;
}

}  // namespace pedtrack::ros_plugins
