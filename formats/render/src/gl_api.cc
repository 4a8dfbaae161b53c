#include "gl_api.h"

#include <dlfcn.h>

#include <mutex>
#include <string>

#include "cablefit/core/base/errors.h"
#include "shared_library.h"

#ifndef CABLEFIT_OSMESA_SONAME
#define CABLEFIT_OSMESA_SONAME "libOSMesa.so.8"
#endif

namespace cablefit::render {
namespace {

struct Loaded {
  GlApi api;
  std::string error;  // empty when every entry point was found
};

Loaded Load() {
  Loaded out;
  std::string why;
  // The library the build found first; its usual names after it (a rebuilt Mesa).
  void* handle =
      OpenSharedLibrary({CABLEFIT_OSMESA_SONAME, "libOSMesa.so.8", "libOSMesa.so"}, &why);
  if (!handle) {
    out.error = std::string("off-screen rendering is not available: ") + CABLEFIT_OSMESA_SONAME +
                " could not be loaded (" + why + "; install the libosmesa6 package)";
    return out;
  }
  // Never closed: GL state and the driver's threads live as long as the process.
  auto find = [&](const char* symbol) -> void* {
    if (void* p = dlsym(handle, symbol)) return p;
    if (out.error.empty())
      out.error = std::string("off-screen rendering is not available: ") +
                  CABLEFIT_OSMESA_SONAME + " has no " + symbol;
    return nullptr;
  };
  GlApi& a = out.api;
  a.CreateContextAttribs =
      reinterpret_cast<decltype(a.CreateContextAttribs)>(find("OSMesaCreateContextAttribs"));
  a.MakeCurrent = reinterpret_cast<decltype(a.MakeCurrent)>(find("OSMesaMakeCurrent"));
  a.DestroyContext = reinterpret_cast<decltype(a.DestroyContext)>(find("OSMesaDestroyContext"));
  auto get_proc = reinterpret_cast<decltype(&::OSMesaGetProcAddress)>(find("OSMesaGetProcAddress"));
  // GL functions through OSMesa's own lookup (the core 1.x ones are exported too, the 2.0
  // shader functions only through it).
  auto gl = [&](const char* symbol) -> void* {
    if (get_proc)
      if (void* p = reinterpret_cast<void*>(get_proc(symbol))) return p;
    return find(symbol);
  };
#define CABLEFIT_GL_LOAD(name) a.name = reinterpret_cast<decltype(a.name)>(gl("gl" #name));
  CABLEFIT_GL_FUNCTIONS(CABLEFIT_GL_LOAD)
#undef CABLEFIT_GL_LOAD
  return out;
}

}  // namespace

const GlApi& Gl() {
  static const Loaded loaded = Load();
  if (!loaded.error.empty()) throw InvalidInput(loaded.error);
  return loaded.api;
}

}  // namespace cablefit::render
