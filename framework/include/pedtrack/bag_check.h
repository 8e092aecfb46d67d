// The structure of a ROS1 bag (format 2.0) checked before rosbag_storage reads it.
//
// rosbag_storage trusts the lengths inside a bag: ros::Header::parse reads a record header's
// fields by their own length prefixes without checking them against the header's length, and a
// message is read from a chunk at whatever offset the index names. A damaged or hostile bag then
// makes it read past its buffers (fuzz_rosbag found both). This walk checks, before any message
// is read, everything rosbag_storage parses from memory:
//  - every record (top level and inside each chunk, decompressed: none, bz2 or lz4) fits where it
//    lies, and its header's fields, like a connection record's data, tile it exactly;
//  - a chunk decompresses to exactly its stated size;
//  - every index entry names a message record of the chunk it follows;
//  - the bag header's index position and every chunk info's chunk position are record starts.
// Reading a bag costs one more pass over it (each chunk read and decompressed once more).
// Built with the ROS1 parts (cmake/PedtrackRos1.cmake): it needs libbz2 and roslz4.
#pragma once

#include <string>

namespace pedtrack {

/// Throws DataError at the first fault, one line without the path ("not a readable ROS bag: a
/// header field longer than its header at byte 11553"), for the caller to prefix.
void checkBagStructure(const std::string& path);

}  // namespace pedtrack
