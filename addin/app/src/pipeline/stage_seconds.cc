#include "cablefit/app/pipeline/stage_seconds.h"

#include <cstdio>

namespace cablefit::addin {

std::string StageSecondsLine(const RelaxStageSeconds& s) {
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "seconds per stage: read %.2f, relax %.2f, measure %.2f, clearance %.2f, motion "
                "%.2f, tolerance %.2f, JSON %.2f, STEP %.2f, pictures %.2f, report %.2f; total %.2f",
                s.read, s.relax, s.measure, s.clearance, s.motion, s.tolerance, s.json, s.step,
                s.pictures, s.report, s.total);
  return buf;
}

json::Json StageSecondsJson(const RelaxStageSeconds& s) {
  return {{"read", s.read},       {"relax", s.relax},         {"measure", s.measure},
          {"clearance", s.clearance}, {"motion", s.motion}, {"tolerance", s.tolerance},
          {"json", s.json},       {"step", s.step},           {"pictures", s.pictures},
          {"report", s.report},   {"total", s.total}};
}

}  // namespace cablefit::addin
