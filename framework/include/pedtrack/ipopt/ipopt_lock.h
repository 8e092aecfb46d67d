#pragma once
// One process-wide lock around every Ipopt call. Debian's MUMPS is the sequential build, whose
// Fortran modules keep global state (dmumps_load): two Ipopt solves at once in one process
// (montecarlo -j, two pipelines, the MHE and the gait fit) corrupt each other and crash.
#include <mutex>

namespace pedtrack::track {

std::mutex& ipoptLock();

}  // namespace pedtrack::track
