// The only place that owns an OSMesa context: creation, making it current, pixel read-back.
// Everything else issues plain GL calls against whatever context is current.
#pragma once

#include <cstdint>
#include <memory>

#include "cablefit/formats/image.h"

namespace cablefit::render {

/// An off-screen GL 2.1+ compatibility context rendering into a CPU buffer (llvmpipe).
/// Made current on construction, for the calling thread. Non-copyable.
class OffscreenContext {
 public:
  /// Throws InvalidInput when OSMesa cannot create a context of that size.
  OffscreenContext(int width, int height);
  ~OffscreenContext();
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  /// Makes the context current again for the calling thread (after another one was).
  void MakeCurrent();
  /// Leaves the calling thread with no current context. A context kept current between
  /// pictures breaks a host's own GL (FreeCAD's Qt crashed in its next GLX buffer swap).
  static void Release();

  int width() const { return width_; }
  int height() const { return height_; }
  /// Finishes rendering and returns the buffer as an image with row 0 at the top.
  Image ReadPixels() const { return ReadPixels(width_, height_); }
  /// The same for the top-left `width` x `height` pixels of the buffer, each `factor` x
  /// `factor` block averaged into one pixel (Downsample(ReadPixels(width, height), factor),
  /// without the full-size image in between: a supersampled panel is ~10 MB).
  Image ReadPixels(int width, int height, int factor = 1) const;

 private:
  int width_;
  int height_;
  void* context_ = nullptr;  // OSMesaContext
  std::unique_ptr<std::uint8_t[]> buffer_;  // RGBA, bottom row first (GL convention)
};

}  // namespace cablefit::render
