#include "gl_scene.h"


#include <algorithm>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

#include "cablefit/core/base/errors.h"
#include "gl_api.h"
#include "osmesa_context.h"
#include "tube_mesh.h"

namespace cablefit::render {
namespace {

// Per-pixel shading for colour-coded tubes. A plain headlight would darken a tube seen at an
// angle to its axis (no normal then faces the viewer), changing the colour the eye reads. So the
// headlight term is measured against the best normal available around the axis, as in lit
// stream lines (M. Zoeckler, D. Stalling, H.-C. Hege, "Interactive visualization of 3D-vector
// fields using illuminated stream lines", IEEE Visualization 1996): the line of the tube that
// faces the viewer shows the colour-map entry exactly, whatever the tube's direction. A small
// glint from an upper-left key light adds depth without shifting hue.
constexpr const char* kVertexShader = R"(#version 120
varying vec3 normal;
varying vec3 tangent;
varying vec3 colour;
void main() {
  normal = normalize(gl_NormalMatrix * gl_Normal);
  tangent = gl_NormalMatrix * gl_MultiTexCoord0.xyz;
  colour = gl_Color.rgb;
  gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
)";

constexpr const char* kFragmentShader = R"(#version 120
varying vec3 normal;
varying vec3 tangent;
varying vec3 colour;
const vec3 key = vec3(-0.35, 0.45, 0.82);
void main() {
  vec3 n = normalize(gl_FrontFacing ? normal : -normal);
  vec3 view = vec3(0.0, 0.0, 1.0);
  float head = max(n.z, 0.0);
  if (dot(tangent, tangent) > 0.25) {
    vec3 t = normalize(tangent);
    vec3 across = view - t.z * t;
    if (dot(across, across) > 1e-4) head = max(dot(n, normalize(across)), 0.0);
  }
  float glint = pow(max(dot(n, normalize(key + view)), 0.0), 40.0);
  gl_FragColor = vec4(colour * (0.32 + 0.68 * head) + vec3(0.14 * glint), 1.0);
}
)";

GLuint Compile(GLenum kind, const char* source) {
  const GLuint shader = Gl().CreateShader(kind);
  Gl().ShaderSource(shader, 1, &source, nullptr);
  Gl().CompileShader(shader);
  GLint ok = 0;
  Gl().GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[1024] = {};
    Gl().GetShaderInfoLog(shader, sizeof log, nullptr, log);
    // The sources are fixed: a GL implementation that rejects them lacks a feature, so the
    // caller gets an error it can report (a picture fewer), not an abort of the host process.
    throw std::runtime_error(OneLine(std::string("shader compilation failed: ") + log));
  }
  return shader;
}

GLuint BuildProgram() {
  const GLuint program = Gl().CreateProgram();
  Gl().AttachShader(program, Compile(GL_VERTEX_SHADER, kVertexShader));
  Gl().AttachShader(program, Compile(GL_FRAGMENT_SHADER, kFragmentShader));
  Gl().LinkProgram(program);
  GLint ok = 0;
  Gl().GetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) throw std::runtime_error("shader program failed to link");
  return program;
}

// The off-screen context and shader program of the process, kept for its next picture: making
// them (fresh buffer pages, llvmpipe compiling the shaders) cost more than drawing a frame of a
// motion sequence. The buffer only grows; a picture uses its top-left corner. One per process,
// not per thread, so that a warm-up on another thread (WarmUpRenderer) serves the pictures.
struct GlSession {
  std::unique_ptr<OffscreenContext> context;
  GLuint program = 0;
};

// Held while a picture is drawn: the session's context is current on one thread at a time.
std::mutex& SessionMutex() {
  static std::mutex mutex;
  return mutex;
}

GlSession& SessionFor(int width, int height) {
  static GlSession session;
  if (session.context && session.context->width() >= width &&
      session.context->height() >= height) {
    session.context->MakeCurrent();  // released after the last picture
    return session;
  }
  const int w = std::max(width, session.context ? session.context->width() : 0);
  const int h = std::max(height, session.context ? session.context->height() : 0);
  session.context.reset();
  session.program = 0;
  session.context = std::make_unique<OffscreenContext>(w, h);
  session.program = BuildProgram();
  return session;
}

struct SceneMeshes {
  TubeMesh tubes;
  TubeMesh halos;
  TubeMesh solids;  // one flat-shaded triangle per face (positions only are used)
};

void AppendSolid(const TriangleMesh& mesh, TubeMesh* out) {
  for (Eigen::Index f = 0; f < mesh.faces.cols(); ++f) {
    const Eigen::Vector3d a = mesh.vertices.col(mesh.faces(0, f));
    const Eigen::Vector3d b = mesh.vertices.col(mesh.faces(1, f));
    const Eigen::Vector3d c = mesh.vertices.col(mesh.faces(2, f));
    if (!a.allFinite() || !b.allFinite() || !c.allFinite()) continue;
    const std::uint32_t base = static_cast<std::uint32_t>(out->positions.size() / 3);
    for (const Eigen::Vector3d& p : {a, b, c})
      for (int k = 0; k < 3; ++k) out->positions.push_back(static_cast<float>(p[k]));
    for (std::uint32_t k = 0; k < 3; ++k) out->indices.push_back(base + k);
  }
}

// The picture's resolution along the tubes: a panel shows the scene in at most about 2000
// supersampled pixels, so 1/8000 of its size is a quarter pixel; a chord of 1/200 of it keeps
// the colour map's gradients smooth.
constexpr double kThinTolerance = 1.0 / 8000;
constexpr double kThinMaxChord = 1.0 / 200;

SceneMeshes BuildMeshes(const Scene& scene, const ColourScale& scale, int sides) {
  SceneMeshes meshes;
  Eigen::AlignedBox3d box;
  for (const SceneTube& tube : scene.tubes)
    for (Eigen::Index i = 0; i < tube.centreline.points.cols(); ++i)
      if (tube.centreline.points.col(i).allFinite()) box.extend(Eigen::Vector3d(tube.centreline.points.col(i)));
  const double size = box.isEmpty() ? 0.0 : box.diagonal().norm();  // [m]
  for (const SceneTube& tube : scene.tubes) {
    const Eigen::Index n = tube.centreline.points.cols();
    std::vector<Eigen::Index> kept;
    if (size > 0 && tube.centreline.points.allFinite()) {
      kept = ThinnedIndices(tube.centreline.points, kThinTolerance * size, kThinMaxChord * size);
      // The largest deviation keeps its vertex: the colour bar's top shows on the tube.
      if (tube.deviation.size() == n && n > 0) {
        Eigen::Index peak = 0;
        tube.deviation.maxCoeff(&peak);
        const auto at = std::lower_bound(kept.begin(), kept.end(), peak);
        if (at == kept.end() || *at != peak) kept.insert(at, peak);
      }
    } else {  // drawn as given (BuildTubeMesh skips what it cannot draw)
      for (Eigen::Index i = 0; i < n; ++i) kept.push_back(i);
    }
    Eigen::Matrix3Xd points(3, static_cast<Eigen::Index>(kept.size()));  // 3 x k [m]
    std::vector<Rgb> colours(kept.size(), tube.flat_colour);
    for (std::size_t k = 0; k < kept.size(); ++k) {
      points.col(static_cast<Eigen::Index>(k)) = tube.centreline.points.col(kept[k]);
      if (tube.deviation.size() == n) colours[k] = scale.Map(tube.deviation[kept[k]] * 1e3);
    }
    meshes.tubes.Append(BuildTubeMesh(points, tube.radius, sides, colours));
  }
  for (const ArcHighlight& h : scene.highlights) {
    if (h.tube < 0 || h.tube >= static_cast<int>(scene.tubes.size())) continue;
    const SceneTube& tube = scene.tubes[static_cast<std::size_t>(h.tube)];
    Polyline line = tube.centreline;
    if (line.s.size() != line.points.cols()) line.ParameteriseByChords();
    const Eigen::Matrix3Xd part = SliceByArcLength(line.s, line.points, h.s_begin, h.s_end);
    const std::vector<Rgb> red(static_cast<std::size_t>(part.cols()), Rgb{214, 39, 40});
    meshes.halos.Append(BuildTubeMesh(part, tube.radius * 1.9, sides, red));
  }
  for (const SceneSolid& solid : scene.solids) AppendSolid(solid.mesh, &meshes.solids);
  return meshes;
}

void DrawMesh(const TubeMesh& mesh) {
  if (mesh.indices.empty()) return;
  Gl().EnableClientState(GL_VERTEX_ARRAY);
  Gl().EnableClientState(GL_NORMAL_ARRAY);
  Gl().EnableClientState(GL_COLOR_ARRAY);
  Gl().EnableClientState(GL_TEXTURE_COORD_ARRAY);
  Gl().TexCoordPointer(3, GL_FLOAT, 0, mesh.tangents.data());
  Gl().VertexPointer(3, GL_FLOAT, 0, mesh.positions.data());
  Gl().NormalPointer(GL_FLOAT, 0, mesh.normals.data());
  Gl().ColorPointer(3, GL_FLOAT, 0, mesh.colours.data());
  Gl().DrawElements(GL_TRIANGLES, static_cast<GLsizei>(mesh.indices.size()), GL_UNSIGNED_INT,
                 mesh.indices.data());
  Gl().DisableClientState(GL_TEXTURE_COORD_ARRAY);
  Gl().DisableClientState(GL_COLOR_ARRAY);
  Gl().DisableClientState(GL_NORMAL_ARRAY);
  Gl().DisableClientState(GL_VERTEX_ARRAY);
}

// One flat colour over a mesh's triangles (positions only), blended and without depth writes:
// what lies behind it (a cable in a clip, a tube inside its halo) stays visible.
void DrawTranslucent(const TubeMesh& mesh, float r, float g, float b, float alpha) {
  if (mesh.indices.empty()) return;
  Gl().Enable(GL_BLEND);
  Gl().DepthMask(GL_FALSE);
  Gl().DisableClientState(GL_COLOR_ARRAY);
  Gl().EnableClientState(GL_VERTEX_ARRAY);
  Gl().Color4f(r, g, b, alpha);
  Gl().VertexPointer(3, GL_FLOAT, 0, mesh.positions.data());
  Gl().DrawElements(GL_TRIANGLES, static_cast<GLsizei>(mesh.indices.size()), GL_UNSIGNED_INT,
                 mesh.indices.data());
  Gl().DisableClientState(GL_VERTEX_ARRAY);
  Gl().DepthMask(GL_TRUE);
  Gl().Disable(GL_BLEND);
}

void DrawPoints(const Eigen::Matrix3Xd& points, GLenum mode) {
  if (points.cols() == 0) return;
  const Eigen::Matrix3Xf p = points.cast<float>();
  Gl().EnableClientState(GL_VERTEX_ARRAY);
  Gl().VertexPointer(3, GL_FLOAT, 0, p.data());
  Gl().DrawArrays(mode, 0, static_cast<GLsizei>(p.cols()));
  Gl().DisableClientState(GL_VERTEX_ARRAY);
}

// Loads projection and model-view so that GL maps world points exactly where
// ViewCamera::Project puts them (relative to the panel's viewport).
void SetUpCamera(const ViewCamera& camera, const std::vector<Eigen::Vector3d>& bounds, int supersample,
                 int buffer_height) {
  const int s = supersample;
  Gl().Viewport(camera.x * s, buffer_height - (camera.y + camera.height) * s, camera.width * s,
             camera.height * s);
  Gl().Scissor(camera.x * s, buffer_height - (camera.y + camera.height) * s, camera.width * s,
            camera.height * s);
  const double ppm = camera.pixels_per_metre;
  const double left = camera.centre.x() + (camera.x - camera.origin_px.x()) / ppm;
  const double right = camera.centre.x() + (camera.x + camera.width - camera.origin_px.x()) / ppm;
  const double top = camera.centre.y() + (camera.origin_px.y() - camera.y) / ppm;
  const double bottom = camera.centre.y() - (camera.y + camera.height - camera.origin_px.y()) / ppm;
  double zmin = 0.0, zmax = 0.0;
  for (std::size_t i = 0; i < bounds.size(); ++i) {
    const double z = camera.rotation.row(2).dot(bounds[i]);
    zmin = i == 0 ? z : std::min(zmin, z);
    zmax = i == 0 ? z : std::max(zmax, z);
  }
  const double margin = 0.05 * (zmax - zmin) + 1e-3;
  Gl().MatrixMode(GL_PROJECTION);
  Gl().LoadIdentity();
  Gl().Ortho(left, right, bottom, top, 0.0, zmax - zmin + 2 * margin);
  Gl().MatrixMode(GL_MODELVIEW);
  double m[16] = {};  // column-major [R | t]: eye z = view z - (zmax + margin)
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m[c * 4 + r] = camera.rotation(r, c);
  m[14] = -(zmax + margin);
  m[15] = 1.0;
  Gl().LoadMatrixd(m);
}

std::vector<Eigen::Vector3d> DepthBounds(const Scene& scene) {
  std::vector<Eigen::Vector3d> bounds;
  auto add = [&](const Eigen::Matrix3Xd& points, double pad) {
    for (Eigen::Index i = 0; i < points.cols(); ++i) {
      if (!points.col(i).allFinite()) continue;
      for (int k = 0; k < 3; ++k) {
        bounds.push_back(points.col(i) + pad * Eigen::Vector3d::Unit(k));
        bounds.push_back(points.col(i) - pad * Eigen::Vector3d::Unit(k));
      }
    }
  };
  for (const SceneTube& tube : scene.tubes) add(tube.centreline.points, tube.radius * 2.5);
  for (const SceneGhost& ghost : scene.ghosts) add(ghost.points, 0.0);
  add(scene.scan_points, 0.0);
  // The parts' depth too (not their extent across the view, which the cameras frame without
  // them): otherwise a part's faces in front of and behind a cable fall outside the depth range.
  for (const SceneSolid& solid : scene.solids) add(solid.mesh.vertices, 0.0);
  return bounds;
}

}  // namespace

Image RenderPanels3d(int width, int height, int supersample, Rgb background,
                     const std::vector<const Scene*>& scenes, const std::vector<ColourScale>& scales,
                     const std::vector<GlPanelJob>& jobs, const RenderOptions& options) {
  const int s = supersample;
  // One buffer the size of the largest panel, reused panel by panel: a buffer of the whole
  // supersampled picture (7 Mpx for the diagnosis views) cost more in fresh pages than the
  // rendering itself, and most of it would have been background.
  int buffer_w = 1, buffer_h = 1;
  for (const GlPanelJob& job : jobs) {
    buffer_w = std::max(buffer_w, job.camera.width * s);
    buffer_h = std::max(buffer_h, job.camera.height * s);
  }
  Image picture = Image::Filled(width, height, background);
  if (jobs.empty()) return picture;
  const std::lock_guard lock(SessionMutex());
  GlSession& session = SessionFor(buffer_w, buffer_h);
  struct ReleaseOnExit {
    ~ReleaseOnExit() { OffscreenContext::Release(); }
  } release;
  const OffscreenContext& context = *session.context;
  const GLuint program = session.program;
  buffer_h = context.height();
  std::map<const Scene*, SceneMeshes> meshes;
  std::map<const Scene*, std::vector<Eigen::Vector3d>> bounds;
  for (std::size_t k = 0; k < scenes.size(); ++k) {
    meshes[scenes[k]] = BuildMeshes(*scenes[k], scales[k], options.tube_sides);
    bounds[scenes[k]] = DepthBounds(*scenes[k]);
  }
  Gl().ClearColor(background.r / 255.0f, background.g / 255.0f, background.b / 255.0f, 1.0f);
  Gl().Enable(GL_SCISSOR_TEST);
  Gl().Enable(GL_DEPTH_TEST);
  Gl().DepthFunc(GL_LEQUAL);
  Gl().BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  for (const GlPanelJob& job : jobs) {
    const Scene& scene = *job.scene;
    const SceneMeshes& m = meshes.at(job.scene);
    // The panel is drawn at the buffer's top-left corner: shifting its rectangle and its
    // origin together leaves the projection unchanged.
    ViewCamera camera = job.camera;
    camera.origin_px -= Eigen::Vector2d(camera.x, camera.y);
    camera.x = camera.y = 0;
    SetUpCamera(camera, bounds.at(job.scene), s, buffer_h);
    Gl().Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    // Halos first, without depth writes: the tube drawn next covers them, so only a red rim
    // around the highlighted stretch remains and the deviation colours stay untouched.
    if (!m.halos.indices.empty()) {
      Gl().UseProgram(0);
      DrawTranslucent(m.halos, 214 / 255.0f, 39 / 255.0f, 40 / 255.0f, 0.35f);
    }
    Gl().UseProgram(program);
    DrawMesh(m.tubes);
    Gl().UseProgram(0);
    Gl().LineWidth(static_cast<float>(1.7 * s));
    for (const SceneGhost& ghost : scene.ghosts) {
      Gl().Color3ub(ghost.colour.r, ghost.colour.g, ghost.colour.b);
      DrawPoints(ghost.points, GL_LINE_STRIP);
    }
    // Parts last, translucent and without depth writes: a cable inside a clip shows through.
    DrawTranslucent(m.solids, 0.45f, 0.47f, 0.52f, 0.22f);
    if (options.show_scan_points && scene.scan_points.cols() > 0) {
      Gl().PointSize(static_cast<float>(1.5 * s));
      Gl().Color3ub(70, 70, 70);
      DrawPoints(scene.scan_points, GL_POINTS);
    }
    picture.Paste(context.ReadPixels(job.camera.width * s, job.camera.height * s, s),
                  job.camera.x, job.camera.y);
  }
  return picture;
}

}  // namespace cablefit::render
