// cablefit-mesh-child: the helper process of cablefit/formats/helper_process.h for meshes.
//   cablefit-mesh-child PARENT_PID skeleton MESH_FD SKELETON_FD
//       the curve skeleton of one mesh component (internal::SkeletonInHelper)
#include <cstdlib>
#include <string>

#include "cablefit/formats/helper_process.h"
#include "cablefit/formats/internal/skeleton_helper.h"

namespace {

int Skeleton(int argc, char** argv) {
  if (argc != 5 || std::string(argv[2]) != "skeleton") return cablefit::kHelperUsage;
  return cablefit::internal::SkeletonInHelper(std::atoi(argv[3]), std::atoi(argv[4]));
}

}  // namespace

// The allocator is left at glibc's defaults, as it always was here: the skeleton's routes follow
// heap addresses (see helper_process.h), and they are tested with this heap.
int main(int argc, char** argv) { cablefit::RunAsHelper(argc, argv, Skeleton, /*tune_allocator=*/false); }
