// The time a relax run spent per stage: in its summary, on its last lines and in --summary-json.
#pragma once

#include <string>

#include "cablefit/formats/json_util.h"

namespace cablefit::addin {

/// Wall time per stage [s]. Stages that run per input in parallel (read, relax, measure, JSON,
/// STEP, pictures) are summed over inputs and groups, so with several workers they can add up to
/// more than `total`.
struct RelaxStageSeconds {
  double read = 0, relax = 0, measure = 0;  ///< measure: deviations and the springback/sag split
  double clearance = 0, motion = 0, tolerance = 0;
  double json = 0, step = 0, pictures = 0, report = 0;
  double total = 0;
};

/// "seconds per stage: read 0.12, relax 1.31, ..., report 0.04; total 2.10".
std::string StageSecondsLine(const RelaxStageSeconds& s);
json::Json StageSecondsJson(const RelaxStageSeconds& s);

}  // namespace cablefit::addin
