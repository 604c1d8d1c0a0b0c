#include "app/studio/gl_texture.hpp"

#include <cstdint>

#include <GL/gl.h>

#include <opencv2/imgproc.hpp>

namespace fieldlines::app {

GlTexture::~GlTexture() {
  if (id_ != 0) glDeleteTextures(1, &id_);
}

void GlTexture::upload(const cv::Mat& bgr) {
  if (bgr.empty()) {
    width_ = height_ = 0;
    return;
  }
  cv::Mat rgba;
  cv::cvtColor(bgr, rgba, bgr.channels() == 1 ? cv::COLOR_GRAY2RGBA : cv::COLOR_BGR2RGBA);
  if (id_ == 0) glGenTextures(1, &id_);
  glBindTexture(GL_TEXTURE_2D, id_);
  // Nearest when magnified: a zoomed-in pixel must look like a pixel for pixel-exact labelling.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, static_cast<GLint>(rgba.step / rgba.elemSize()));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, rgba.cols, rgba.rows, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  width_ = rgba.cols;
  height_ = rgba.rows;
}

ImTextureID GlTexture::id() const { return reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(id_)); }

}  // namespace fieldlines::app
