#pragma once
// Shared by the libFuzzer targets: the readers under test take file paths, so an input is
// written to a file of this process first (in /dev/shm when there is one: no disk I/O).
#include <unistd.h>

#include <cstdint>
#include <fstream>
#include <string>

namespace pedtrack::fuzz {

inline std::string inputFile(const std::uint8_t* data, std::size_t size, const std::string& ext) {
  const std::string dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
  const std::string path = dir + "/pedtrack_fuzz_" + std::to_string(getpid()) + ext;
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

}  // namespace pedtrack::fuzz
