// What a file is by its first bytes, not by its name: so that a file given to the wrong command
// (a STEP file to diagnose, a scan to relax, a case.json as --config) gets an error that says
// what it is and where it belongs, instead of a parser's complaint about its first character.
#pragma once

#include <string>

namespace cablefit {

enum class FileKind {
  kUnknown,
  kStep,       // ISO-10303-21 exchange file
  kIges,       // 80-column records with a section letter in column 73
  kJson,       // starts with { or [
  kPlyMesh,    // PLY with faces
  kPlyPoints,  // PLY without faces: a point cloud (a scan)
  kStl,        // ASCII "solid ..." or binary with the size its triangle count gives
  kObj,        // Wavefront OBJ vertex lines
  kKbl,        // XML whose root element is a KBL_container (VDA 4964 harness description)
};

/// Reads at most the first few kilobytes of `path`; kUnknown when it cannot be read or matches
/// none of the above.
FileKind SniffFileKind(const std::string& path);

/// "a STEP file", "a PLY point cloud (no faces)", ...; "" for kUnknown.
std::string DescribeFileKind(FileKind kind);

}  // namespace cablefit
