#include "pedtrack/stop_request.h"

namespace pedtrack {

std::atomic<bool>& stopRequested() {
  static std::atomic<bool> flag{false};
  return flag;
}

}  // namespace pedtrack
