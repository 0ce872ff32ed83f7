// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file GlObjects.h
 * @brief Move-only owners of the GPU engine's GL objects, and the textures it makes.
 *
 * An owner holds one GL name (texture, framebuffer, program, vertex array or query)
 * and deletes it in reset(), or when another object is assigned over it.
 * Both need the GL context current, and so does everything that makes an
 * object here.
 *
 * Why the destructor does not delete: GL objects can only be deleted with
 * their context current, and a destructor cannot know that it is. The GPU
 * engine lives in a renderer's mapper, which may be destroyed after its
 * render window (the context is gone, and its objects with it) or where
 * another context is current (a delete would free that context's objects).
 * So GpuEngine::release() (documented "the context must be current") deletes
 * every object at once by assigning an empty GpuSystem over the old one,
 * member by member, and clearing its GpuProgramCache (the programs), and
 * ~GpuEngine() calls no GL: an owner destroyed while
 * still holding a name forgets it, and the object lives on until its context
 * is destroyed. No list of objects to delete is kept anywhere.
 */
#ifndef BoundParticles_GlObjects_h
#define BoundParticles_GlObjects_h

#include <epoxy/gl.h>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace bp
{

/// One GL name and how to delete it (Traits::destroy). See the file comment.
template <typename Traits>
class GlObject
{
public:
  GlObject() = default;
  /// Takes ownership of `name` (0: none).
  explicit GlObject(GLuint name)
    : Name(name)
  {
  }
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;
  GlObject(GlObject&& other) noexcept
    : Name(other.Name)
  {
    other.Name = 0;
  }
  /// Deletes what this held (the context must be current), then takes `other`'s.
  GlObject& operator=(GlObject&& other) noexcept
  {
    if (this != &other)
    {
      this->reset();
      this->Name = other.Name;
      other.Name = 0;
    }
    return *this;
  }
  /// Calls no GL: a name still held is forgotten (see the file comment).
  ~GlObject() = default;

  GLuint get() const { return this->Name; }
  explicit operator bool() const { return this->Name != 0; }

  /// Deletes the object, if any; the context must be current.
  void reset()
  {
    if (this->Name)
    {
      Traits::destroy(this->Name);
      this->Name = 0;
    }
  }

private:
  GLuint Name = 0;
};

struct GlTextureTraits
{
  static void destroy(GLuint name) { glDeleteTextures(1, &name); }
};
struct GlFramebufferTraits
{
  static void destroy(GLuint name) { glDeleteFramebuffers(1, &name); }
};
struct GlProgramTraits
{
  static void destroy(GLuint name) { glDeleteProgram(name); }
};
struct GlVertexArrayTraits
{
  static void destroy(GLuint name) { glDeleteVertexArrays(1, &name); }
};

struct GlQueryTraits
{
  static void destroy(GLuint name) { glDeleteQueries(1, &name); }
};

using GlTexture = GlObject<GlTextureTraits>;
using GlFramebuffer = GlObject<GlFramebufferTraits>;
using GlProgram = GlObject<GlProgramTraits>;
using GlVertexArray = GlObject<GlVertexArrayTraits>;
using GlQuery = GlObject<GlQueryTraits>;

/**
 * A list of GL objects that deletes them when another list is assigned over
 * it, as GlObject does; a std::vector<GlObject> would only forget them (its
 * move assignment destroys the old elements, and ~GlObject calls no GL).
 */
template <typename Traits>
class GlObjectList
{
public:
  GlObjectList() = default;
  GlObjectList(GlObjectList&&) noexcept = default;
  GlObjectList& operator=(GlObjectList&& other) noexcept
  {
    if (this != &other)
    {
      this->clear();
      this->Objects = std::move(other.Objects);
    }
    return *this;
  }

  /// Deletes every object (the context must be current) and empties the list.
  void clear()
  {
    for (GlObject<Traits>& object : this->Objects)
    {
      object.reset();
    }
    this->Objects.clear();
  }
  void add(GlObject<Traits> object) { this->Objects.push_back(std::move(object)); }
  std::size_t size() const { return this->Objects.size(); }
  GLuint operator[](std::size_t k) const { return this->Objects[k].get(); }

private:
  std::vector<GlObject<Traits>> Objects;
};
using GlTextureList = GlObjectList<GlTextureTraits>;
using GlQueryList = GlObjectList<GlQueryTraits>;

GlFramebuffer makeFramebuffer();
GlVertexArray makeVertexArray();

/// Tightly packed uploads for the guard's lifetime, leaving the caller's
/// unpack state as it was (a render window's context has its own).
class TightUnpack
{
public:
  TightUnpack();
  ~TightUnpack();
  TightUnpack(const TightUnpack&) = delete;
  TightUnpack& operator=(const TightUnpack&) = delete;

private:
  GLint Saved[3] = { 4, 0, 0 };
};

/// An RGBA32F texture, sampled with texelFetch only (nearest, clamped);
/// `data` (null: undefined texels) is read with the current unpack state.
GlTexture makeTexture2D(int width, int height, const float* data = nullptr);

/// An R8UI 3D texture of one byte per texel (x fastest, rows not padded),
/// sampled with texelFetch only: the cell masks. The active unit's 3D texture
/// stays bound (these are made while a pass binds its textures).
GlTexture makeByteTexture3D(int nx, int ny, int nz, const std::uint8_t* bytes);

/// An RGB32F 3D texture of 3 floats per texel (x fastest), sampled with
/// texelFetch only: Release Weights (GpuFieldCache::applyReleaseWeightsTo).
/// The active unit's 3D texture stays bound.
GlTexture makeFloatTexture3D(int nx, int ny, int nz, const float* rgb);

/// A `width` x `height` texture of per-element values, 4 per element
/// (element e at (e % width, e / width), so row-major texel order is element
/// order), zero padded.
GlTexture makeElementTexture(int width, int height, const std::vector<float>& perElement);

/// The same with signed integers (RGBA32I, padded with -1), for element
/// indices beyond 2^24.
GlTexture makeElementIndexTexture(
  int width, int height, const std::vector<std::int32_t>& perElement);

/// A list of RGBA texels packed into rows `width` texels wide, zero padded.
GlTexture makeListTexture(const std::vector<float>& rgba, int width);

} // namespace bp

#endif
