#include "pedtrack/ipopt/ipopt_lock.h"

namespace pedtrack::track {

std::mutex& ipoptLock() {
  static std::mutex m;
  return m;
}

}  // namespace pedtrack::track
