// The one lock around the OSMesa renderer, for every picture of every command: contexts are per
// thread, but llvmpipe already uses every core and the GL state of the render library has not been
// audited for concurrent use.
#pragma once

#include <mutex>

namespace cablefit::addin {

std::mutex& RenderMutex();

}  // namespace cablefit::addin
