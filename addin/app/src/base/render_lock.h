// The one lock around the OSMesa renderer for the relax pictures (it is entered one thread at a
// time; see relax_report.cc).
#pragma once

#include <mutex>

namespace cablefit::addin {

std::mutex& RenderMutex();

}  // namespace cablefit::addin
