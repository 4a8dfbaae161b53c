// The lines a relax run says about its cables and inputs while it works (RunMessage::kDetail).
// Internal to the relax pipeline.
#pragma once

#include <string>

#include "cablefit/app/output/relax_file.h"

namespace cablefit::addin {

/// "<stem>: <cable>: L=..., max deviation ... at s=..., min bend radius ..., max tension ...,
/// N supports, stable, 12.3 ms".
std::string CableLine(const RelaxedFile& f, const CableRelaxation& r);

/// "<stem>: N cables, M solids; seconds: read ..., relax ..., STEP ..., JSON ..., picture ...".
std::string InputLine(const RelaxedFile& f);

}  // namespace cablefit::addin
