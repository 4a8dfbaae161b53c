// SECTION.json (cablefit-section/1) and the material library (cablefit-materials/1): reading
// into a core SectionSpec, and the result JSON of `cablefit section`. Formats are described in
// the section command's README text; errors are one-line FileErrors naming the file and field.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cablefit/core/section/section.h"

namespace cablefit::addin {

struct SectionInput {
  SectionSpec spec;
  TorsionOptions torsion;
  std::string library;              // resolved library path, empty when none
  std::vector<std::string> notes;   // assumptions taken while expanding library entries
};

/// Reads SECTION.json: components (explicit discs/annuli or library wires), layers (explicit or
/// library tapes/conduits, wrapping what is inside them by default) and torsion options.
/// Materials are looked up in the file's "materials", then in the library. Throws FileError.
SectionInput ReadSectionFile(const std::string& path);

/// The result object written by `cablefit section`.
nlohmann::json SectionResultToJson(const SectionResult& result, const SectionInput& input,
                                   const std::string& input_path);

}  // namespace cablefit::addin
