// `cablefit bench --diagnose DIR`: the time of every recording case's diagnosis.
#pragma once

#include <string>

namespace cablefit::addin {

/// Diagnoses every case under `dir` on one thread (as `diagnose --jobs 1` on a one-core share)
/// and prints per case its seconds, effect and kind, then the median and the worst shape and
/// force case. Returns the exit status (2 when no case could be read).
int BenchDiagnose(const std::string& dir);

}  // namespace cablefit::addin
