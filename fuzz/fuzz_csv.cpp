// The tracks / truth / detections CSV readers of `pedtrack eval`, and the grouping by time that
// every metric walks.
#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "pedtrack/eval/object_table.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = pedtrack::fuzz::inputFile(data, size, ".csv");
  try {
    const auto table = pedtrack::readObjectTable(path);
    pedtrack::sliceByTime(table);
  } catch (const std::exception&) {
  }
  try {
    const auto detections = pedtrack::readDetectionTable(path);
    pedtrack::sliceByTime(detections);
  } catch (const std::exception&) {
  }
  return 0;
}
