// Libraries the renderer opens when it first needs them instead of linking them (gl_api.h,
// freetype_api.h say why).
#pragma once

#include <initializer_list>
#include <string>

namespace cablefit::render {

/// The first of `names` that dlopen loads (now, local: its symbols do not shadow or get
/// shadowed by a library of the same API already in the process); nullptr with dlerror's text
/// in `why` when none does. Never closed: what it loads lives as long as the process.
void* OpenSharedLibrary(std::initializer_list<const char*> names, std::string* why);

}  // namespace cablefit::render
