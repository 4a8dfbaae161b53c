// The OpenGL and OSMesa entry points the renderer calls, loaded from libOSMesa on first use.
// Linking libOSMesa would load it, LLVM's JIT and a dozen more libraries into every process
// (~0.06 s and 50 MB before main), the many that never draw a picture too; and resolving the
// entry points through the library's own handle keeps a libGL loaded beside it (OpenCASCADE's,
// FreeCAD's) from shadowing them.
#pragma once

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

namespace cablefit::render {

#define CABLEFIT_GL_FUNCTIONS(X)                                                               \
  X(AttachShader) X(BlendFunc) X(Clear) X(ClearColor) X(Color3ub) X(Color4f) X(ColorPointer)   \
  X(CompileShader) X(CreateProgram) X(CreateShader) X(DepthFunc)                               \
  X(DepthMask) X(Disable) X(DisableClientState) X(DrawArrays) X(DrawElements) X(Enable)        \
  X(EnableClientState) X(Finish) X(GetProgramiv) X(GetShaderInfoLog) X(GetShaderiv)            \
  X(LineWidth) X(LinkProgram) X(LoadIdentity) X(LoadMatrixd) X(MatrixMode) X(NormalPointer)    \
  X(Ortho) X(PointSize) X(Scissor) X(ShaderSource) X(TexCoordPointer) X(UseProgram)            \
  X(VertexPointer) X(Viewport)

struct GlApi {
#define CABLEFIT_GL_POINTER(name) decltype(&::gl##name) name = nullptr;
  CABLEFIT_GL_FUNCTIONS(CABLEFIT_GL_POINTER)
#undef CABLEFIT_GL_POINTER
  decltype(&::OSMesaCreateContextAttribs) CreateContextAttribs = nullptr;
  decltype(&::OSMesaMakeCurrent) MakeCurrent = nullptr;
  decltype(&::OSMesaDestroyContext) DestroyContext = nullptr;
};

/// The entry points, loaded once per process (thread-safe). Throws InvalidInput naming the
/// library and the missing function when off-screen rendering is not available.
const GlApi& Gl();

}  // namespace cablefit::render
