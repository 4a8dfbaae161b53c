// cablefit-mesh-child: the helper process of cablefit/formats/helper_process.h for meshes.
//   cablefit-mesh-child PARENT_PID skeleton MESH_FD SKELETON_FD
//       the curve skeleton of one mesh component (internal::SkeletonInHelper)
#include <sys/prctl.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <string>

#include "cablefit/formats/internal/skeleton_helper.h"

namespace {

constexpr int kUsage = 64;

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return kUsage;
  // Killed with cablefit (kill -9 included) instead of computing on as an orphan.
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (std::to_string(::getppid()) != argv[1]) return kUsage;  // the parent is already gone
  const std::string mode = argv[2];
  int code = kUsage;
  if (mode == "skeleton" && argc == 5) {
    code = cablefit::internal::SkeletonInHelper(std::atoi(argv[3]), std::atoi(argv[4]));
  }
  std::_Exit(code);
}
