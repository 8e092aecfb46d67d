#pragma once
// The ROS1 node the ros_* plugins share: one per process (roscpp's own rule), started by
// whichever ROS plugin is created first.
#include <ros/node_handle.h>

#include <string>

#include "pedtrack/param_table.h"

namespace pedtrack::ros_plugins {

/// The node keys every ROS plugin declares.
struct NodeParams {
  std::string node = "pedtrack";  ///< ROS node name (the first ROS plugin created names it)
  double master_timeout = 10.0;   ///< s to wait for the master at $ROS_MASTER_URI
};
const ParamTable<NodeParams>& nodeTable();

/// Initialises roscpp once per process as node `node_name` (the first ROS plugin created names
/// the node; later names are ignored) and waits up to `master_timeout` s for the master at
/// $ROS_MASTER_URI. ConfigError naming the URI when no master answers: advertise() and subscribe()
/// would otherwise block forever retrying.
void ensureNode(const std::string& node_name, double master_timeout);

/// A node handle and the name to give it for a topic name from the INI: "~x" is private to the
/// node (roscpp refuses '~' names on a plain NodeHandle), anything else resolves as usual.
struct ResolvedTopic {
  ros::NodeHandle nh;
  std::string name;
};
ResolvedTopic resolveTopic(const std::string& topic);

}  // namespace pedtrack::ros_plugins
