#include "freetype_api.h"

#include <dlfcn.h>

#include <string>

#include "cablefit/core/base/errors.h"
#include "shared_library.h"

#ifndef CABLEFIT_FREETYPE_SONAME
#define CABLEFIT_FREETYPE_SONAME "libfreetype.so.6"
#endif

namespace cablefit::render {
namespace {

struct Loaded {
  FreeTypeApi api;
  std::string error;  // empty when every entry point was found
};

Loaded Load() {
  Loaded out;
  std::string why;
  void* handle =
      OpenSharedLibrary({CABLEFIT_FREETYPE_SONAME, "libfreetype.so.6", "libfreetype.so"}, &why);
  if (!handle) {
    out.error = std::string("text in pictures is not available: ") + CABLEFIT_FREETYPE_SONAME +
                " could not be loaded (" + why + "; install the libfreetype6 package)";
    return out;
  }
  auto find = [&](const char* symbol) -> void* {
    if (void* p = dlsym(handle, symbol)) return p;
    if (out.error.empty())
      out.error = std::string("text in pictures is not available: ") + CABLEFIT_FREETYPE_SONAME +
                  " has no " + symbol;
    return nullptr;
  };
  FreeTypeApi& a = out.api;
#define CABLEFIT_FT_LOAD(name) a.name = reinterpret_cast<decltype(a.name)>(find("FT_" #name));
  CABLEFIT_FT_LOAD(Init_FreeType)
  CABLEFIT_FT_LOAD(Done_FreeType)
  CABLEFIT_FT_LOAD(New_Face)
  CABLEFIT_FT_LOAD(Done_Face)
  CABLEFIT_FT_LOAD(Set_Pixel_Sizes)
  CABLEFIT_FT_LOAD(Load_Char)
#undef CABLEFIT_FT_LOAD
  return out;
}

}  // namespace

const FreeTypeApi& FreeType() {
  static const Loaded loaded = Load();
  if (!loaded.error.empty()) throw InvalidInput(loaded.error);
  return loaded.api;
}

}  // namespace cablefit::render
