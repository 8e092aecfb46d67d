// The chunk scan that re-indexes a bag cut short (pedtrack/bag_recover.h): any file ends in a
// DataError or a copy, and every copy it writes is a whole bag: it passes the structure check and
// rosbag_storage reads every message of it.
#include <rosbag/bag.h>
#include <rosbag/view.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

#include "fuzz_support.h"
#include "pedtrack/bag_check.h"
#include "pedtrack/bag_recover.h"
#include "pedtrack/errors.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = pedtrack::fuzz::inputFile(data, size, ".bag");
  const std::string copy = path + ".reindexed.bag";
  pedtrack::BagRecovery kept;
  try {
    kept = pedtrack::reindexBag(path, copy);
  } catch (const pedtrack::DataError&) {
    return 0;
  }
  try {
    pedtrack::checkBagStructure(copy);
    rosbag::Bag bag(copy, rosbag::bagmode::Read);
    rosbag::View view(bag);
    std::size_t n = 0;
    for (const rosbag::MessageInstance& m : view) n += m.size() > 0 || true;
    if (n != kept.messages) {
      std::cerr << "the copy holds " << n << " messages, the scan kept " << kept.messages << "\n";
      std::abort();
    }
  } catch (const std::exception& e) {
    std::cerr << "a re-indexed copy that does not read back: " << e.what() << "\n";
    std::abort();
  }
  std::remove(copy.c_str());
  return 0;
}
