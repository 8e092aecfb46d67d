// Classifier model files (OpenCV FileStorage YAML with pedtrack's header): whatever the file
// holds, loading gives a scorer or an exception.
#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "pedtrack/classify/model_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = pedtrack::fuzz::inputFile(data, size, ".yml");
  try {
    pedtrack::classify::loadScorer(path);
  } catch (const std::exception&) {
  }
  return 0;
}
