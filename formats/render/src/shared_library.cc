#include "shared_library.h"

#include <dlfcn.h>

namespace cablefit::render {

void* OpenSharedLibrary(std::initializer_list<const char*> names, std::string* why) {
  for (const char* name : names)
    if (void* handle = dlopen(name, RTLD_NOW | RTLD_LOCAL)) return handle;
  const char* error = dlerror();
  *why = error ? error : "not found";
  return nullptr;
}

}  // namespace cablefit::render
