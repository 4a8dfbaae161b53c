#include "base/render_lock.h"

namespace cablefit::addin {

// Its own unit so that taking the lock does not link the relax report (and with it the CAD
// writer) into the executable that only diagnoses.
std::mutex& RenderMutex() {
  static std::mutex mutex;
  return mutex;
}

}  // namespace cablefit::addin
