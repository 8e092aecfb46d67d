// Scenario files: every section and key of the simulator's scenario reader.
#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "pedtrack/sim/scenario.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = pedtrack::fuzz::inputFile(data, size, ".ini");
  try {
    pedtrack::sim::loadScenario(path);
  } catch (const std::exception&) {
  }
  return 0;
}
