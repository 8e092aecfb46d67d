#pragma once
// The plugin ABI version. Bump it whenever a class or struct that crosses the host/plugin
// boundary (Frame, Plugin and its subclasses, PluginDescriptor, ParamSpec, ParamSet) changes
// layout or meaning; the loader refuses plugins built against another value.
#define PEDTRACK_API_VERSION 9

namespace pedtrack {
constexpr int kApiVersion = PEDTRACK_API_VERSION;
/// "MAJOR.MINOR.PATCH" of the framework library the host runs on.
const char* versionString();
}  // namespace pedtrack
