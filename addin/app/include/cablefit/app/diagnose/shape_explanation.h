// The shape diagnosis worded for a person: what the chosen effect means on this cable, how much
// fitting it helps, a close runner-up, or, when nothing explains the recording, what to check.
// Built from the diagnosis's data (parameters, clamp, interval, adequacy, candidates, notes) only.
#pragma once

#include <string>

#include "cablefit/core/diagnosis/shape_diagnosis.h"
#include "cablefit/core/rod/rod_spec.h"

namespace cablefit::addin {

/// `nominal` is the set-up the diagnosis was made for (where its clamps sit).
std::string ExplainShapeDiagnosis(const ShapeDiagnosis& d, const RodSpec& nominal);

/// One note of the diagnosis as a sentence (diagnosis.json's `notes`, the report).
std::string DescribeNote(const DiagnosisNote& note);

}  // namespace cablefit::addin
