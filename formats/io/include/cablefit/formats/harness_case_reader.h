// Reader for harness recordings (case.json in the harness-recording/1 format, docs/recording-format.md):
// the nominal harness as a rod network (branches with their drawn routes, materials and supports,
// junctions, solids) and what was recorded of it (one scan of the whole harness, or measured
// centrelines per branch).
#pragma once

#include <string>
#include <vector>

#include "cablefit/core/network/network_spec.h"

namespace cablefit {

/// The `format` value of a harness recording.
inline constexpr const char* kHarnessRecordingFormat = "harness-recording/1";

struct HarnessRecordingRef {
  enum class Kind { kScan, kCenterline };
  Kind kind = Kind::kScan;
  std::string file;  ///< as written in the case
  std::string path;  ///< resolved, existing
  int branch = -1;   ///< the branch a centreline belongs to (index into nominal.branches)
};

struct HarnessRecording {
  std::string case_file;
  std::string name;
  NetworkSpec nominal;  ///< routes in metres, supports and junctions attached
  std::vector<HarnessRecordingRef> recordings;
};

/// Reads and validates a harness case.json (or a folder holding one). Every problem throws
/// FileError(case file or route file, one-line problem).
HarnessRecording ReadHarnessRecording(const std::string& path);

}  // namespace cablefit
