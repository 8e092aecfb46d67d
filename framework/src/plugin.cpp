#include "pedtrack/plugin.h"

namespace pedtrack {

// Out-of-line key functions: the vtables and type_info of the plugin base classes live in the
// framework library only, so dynamic_cast works on objects created inside any plugin.
Plugin::~Plugin() = default;
Sensor::~Sensor() = default;
Stage::~Stage() = default;
Odometry::~Odometry() = default;
Segmenter::~Segmenter() = default;
Classifier::~Classifier() = default;
Tracker::~Tracker() = default;

const char* toString(Category c) {
  switch (c) {
    case Category::Sensor:
      return "sensor";
    case Category::Odometry:
      return "odometry";
    case Category::Segmenter:
      return "segmenter";
    case Category::Classifier:
      return "classifier";
    case Category::Tracker:
      return "tracker";
  }
  return "?";
}

const char* versionString() {
  return PEDTRACK_VERSION_STRING;
}

}  // namespace pedtrack
