// SPDX-License-Identifier: BSD-3-Clause
#include "GlObjects.h"

#include <algorithm>
#include <cstdint>

namespace bp
{
namespace
{
constexpr GLenum UnpackNames[3] = { GL_UNPACK_ALIGNMENT, GL_UNPACK_ROW_LENGTH,
  GL_UNPACK_IMAGE_HEIGHT };

/// A new 2D texture, bound, that texelFetch reads exactly.
GlTexture newTexture2D()
{
  GLuint name = 0;
  glGenTextures(1, &name);
  glBindTexture(GL_TEXTURE_2D, name);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return GlTexture(name);
}

/// `values` copied into a buffer of `count` values, the rest `fill`.
template <typename T>
std::vector<T> padded(const std::vector<T>& values, std::size_t count, T fill)
{
  std::vector<T> out(count, fill);
  std::copy(values.begin(), values.end(), out.begin());
  return out;
}
} // namespace

GlFramebuffer makeFramebuffer()
{
  GLuint name = 0;
  glGenFramebuffers(1, &name);
  return GlFramebuffer(name);
}

GlVertexArray makeVertexArray()
{
  GLuint name = 0;
  glGenVertexArrays(1, &name);
  return GlVertexArray(name);
}

TightUnpack::TightUnpack()
{
  for (int k = 0; k < 3; ++k)
  {
    glGetIntegerv(UnpackNames[k], &this->Saved[k]);
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
}

TightUnpack::~TightUnpack()
{
  for (int k = 0; k < 3; ++k)
  {
    glPixelStorei(UnpackNames[k], this->Saved[k]);
  }
}

namespace
{
/// A 3D texture sampled with texelFetch only (nearest), from texels read
/// with no row padding. Made while a pass binds its textures, so the active
/// unit's 3D texture is bound again after.
GlTexture makeTexture3D(
  int nx, int ny, int nz, GLint internalFormat, GLenum format, GLenum type, const void* texels)
{
  GLint bound = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_3D, &bound);
  GLuint name = 0;
  glGenTextures(1, &name);
  glBindTexture(GL_TEXTURE_3D, name);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  TightUnpack unpack;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1); // rows of one byte per texel are not padded to 4
  glTexImage3D(GL_TEXTURE_3D, 0, internalFormat, nx, ny, nz, 0, format, type, texels);
  glBindTexture(GL_TEXTURE_3D, GLuint(bound));
  return GlTexture(name);
}
} // namespace

GlTexture makeByteTexture3D(int nx, int ny, int nz, const std::uint8_t* bytes)
{
  return makeTexture3D(nx, ny, nz, GL_R8UI, GL_RED_INTEGER, GL_UNSIGNED_BYTE, bytes);
}

GlTexture makeFloatTexture3D(int nx, int ny, int nz, const float* rgb)
{
  return makeTexture3D(nx, ny, nz, GL_RGB32F, GL_RGB, GL_FLOAT, rgb);
}

GlTexture makeTexture2D(int width, int height, const float* data)
{
  GlTexture texture = newTexture2D();
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, data);
  return texture;
}

GlTexture makeElementTexture(int width, int height, const std::vector<float>& perElement)
{
  const std::vector<float> texels = padded(perElement, std::size_t(width) * height * 4, 0.0f);
  TightUnpack unpack;
  return makeTexture2D(width, height, texels.data());
}

GlTexture makeElementIndexTexture(
  int width, int height, const std::vector<std::int32_t>& perElement)
{
  const std::vector<std::int32_t> texels =
    padded(perElement, std::size_t(width) * height * 4, std::int32_t(-1));
  GlTexture texture = newTexture2D();
  TightUnpack unpack;
  glTexImage2D(
    GL_TEXTURE_2D, 0, GL_RGBA32I, width, height, 0, GL_RGBA_INTEGER, GL_INT, texels.data());
  return texture;
}

GlTexture makeListTexture(const std::vector<float>& rgba, int width)
{
  const int count = std::max<int>(1, int(rgba.size() / 4));
  const int height = (count + width - 1) / width;
  const std::vector<float> texels = padded(rgba, std::size_t(width) * height * 4, 0.0f);
  TightUnpack unpack;
  return makeTexture2D(width, height, texels.data());
}

} // namespace bp
