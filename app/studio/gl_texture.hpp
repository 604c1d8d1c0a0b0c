#pragma once
// An OpenGL texture holding one 8-bit BGR image (RAII: deleted with the object). Needs a current
// GL context for construction, upload and destruction.
#include <opencv2/core/mat.hpp>

#include <imgui.h>

namespace fieldlines::app {

class GlTexture {
 public:
  GlTexture() = default;
  ~GlTexture();
  GlTexture(const GlTexture&) = delete;
  GlTexture& operator=(const GlTexture&) = delete;

  // Replaces the contents; an empty image leaves an empty texture.
  void upload(const cv::Mat& bgr);
  bool empty() const { return width_ == 0; }
  int width() const { return width_; }
  int height() const { return height_; }
  ImTextureID id() const;

 private:
  unsigned id_ = 0;
  int width_ = 0, height_ = 0;
};

}  // namespace fieldlines::app
