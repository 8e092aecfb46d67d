// Stands for a plugin compiled against an older pedtrack (plugin API version 0): it exports the
// version and name symbols every plugin has, and the loader must refuse it before touching
// anything else.
#include <boost/config.hpp>

extern "C" BOOST_SYMBOL_EXPORT int pedtrack_plugin_api_version() {
  return 0;
}
extern "C" BOOST_SYMBOL_EXPORT const char* pedtrack_plugin_name() {
  return "other_api";
}
