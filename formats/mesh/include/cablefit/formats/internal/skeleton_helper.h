// The helper process's side of the mesh skeleton (see cablefit/formats/helper_process.h): used by
// the helper executable only.
#pragma once

namespace cablefit::internal {

/// Exit status of the helper's skeleton when the mesh is no tube surface (InvalidInput); the
/// message is then the content of the skeleton file.
inline constexpr int kSkeletonInvalidExit = 3;

/// Reads a mesh from descriptor `mesh_fd`, computes its curve skeleton and writes it to
/// descriptor `skeleton_fd`. Returns the exit status: 0, kSkeletonInvalidExit, or 4 when a file
/// cannot be read or written.
int SkeletonInHelper(int mesh_fd, int skeleton_fd);

}  // namespace cablefit::internal
