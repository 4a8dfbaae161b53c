// Which inputs `relax` takes, by name and content, and the length units of mesh files.
#pragma once

#include <string>

namespace cablefit::addin {

/// True for extensions read by ReadCadFile (step, stp, iges, igs; any case).
bool IsCadPath(const std::string& path);
/// True for the mesh extensions `relax` accepts (stl, obj, ply, gltf, glb, 3mf, off, dae, fbx).
bool IsMeshPath(const std::string& path);

/// Length of one unit of `name` in metres ("mm" -> 0.001, "m", "cm", "in"/"inch", "ft").
/// Throws InvalidInput for an unknown unit.
double UnitInMetres(const std::string& name);
/// True for the extension ".kbl" (any case).
bool IsKblPath(const std::string& path);
/// True for a ".kbl" path, or a file of another extension (".xml") whose content is a KBL
/// container (SniffFileKind).
bool IsKblInput(const std::string& path);

}  // namespace cablefit::addin
