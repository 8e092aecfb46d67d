#include "imm_pdaf/existence_log.h"

#include <cstdio>

#include "pedtrack/track/management.h"

namespace pedtrack::track {

const char* ExistenceLog::header() {
  return "t,frame,track,existence,llr,llr_confirm,llr_delete,status";
}

void ExistenceLog::row(double t, std::size_t frame, long track, double existence,
                       double llr_confirm, double llr_delete, const char* status) {
  char buf[256];
  const int n =
      std::snprintf(buf, sizeof buf, "%.6f,%zu,%ld,%.6g,%.4f,%.4f,%.4f,%s\n", t, frame, track,
                    existence, ExistenceLlr::llr(existence), llr_confirm, llr_delete, status);
  out_.write(buf, n);
}

}  // namespace pedtrack::track
