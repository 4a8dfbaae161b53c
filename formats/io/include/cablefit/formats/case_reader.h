// Reader for recording cases (case.json, the cable-recording/1 format described in the README).
#pragma once

#include <string>
#include <vector>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/rod/recording_case.h"
#include "cablefit/formats/json_util.h"

namespace cablefit {

/// The `format` value this reader understands.
inline constexpr const char* kRecordingFormat = "cable-recording/1";

/// Reads and validates a case.json (or a folder holding one). Clamps become `nominal.supports`
/// (kind clamp/clip/pin; a pin without tangent/normal keeps the SupportSpec defaults), recording
/// paths are resolved relative to the case file and must exist. Every problem throws
/// FileError(case file, one-line problem), e.g. "clamps[1].s must be positive, got -0.1".
RecordingCase ReadRecordingCase(const std::string& path);

/// The case file a path names: the path itself, or the case.json in that folder (FileError when
/// the folder holds none).
std::string CaseFilePath(const std::string& path);

/// The `format` of a case file (or of the case.json in a folder), "" when it has none. Reading
/// problems throw FileError.
std::string CaseFormatOf(const std::string& path);

/// The file named by field `key` of `field`, resolved in `case_dir`: relative, inside the case
/// folder and existing, or FileError naming the field.
std::string CaseRelativeFile(const json::FieldReader& field, const std::string& key,
                             const std::string& case_dir);

/// Case files found under some command-line paths.
struct CaseFileList {
  std::vector<std::string> files;  ///< sorted, each a case.json path, one per case name
  std::vector<std::string> names;  ///< per file: its case `name`, "" when it cannot be read
  std::vector<FileError> errors;   ///< one per case whose name repeats an earlier one (skipped)
};

/// Expands each path — a case file, a folder holding case.json, or a folder of such folders —
/// into case.json paths, sorted by path. The same file reached twice counts once; a second case
/// with an already-seen `name` is left out and reported in `errors`. Throws FileError for a path
/// that does not exist or holds no case at all. A case whose name cannot be read is still listed
/// (ReadRecordingCase will report what is wrong with it).
CaseFileList FindCaseFiles(const std::vector<std::string>& paths);

}  // namespace cablefit
