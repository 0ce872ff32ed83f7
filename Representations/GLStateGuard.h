// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file GLStateGuard.h
 * @brief Saves the GL state the GPU engine's passes change and puts it back.
 *
 * The GPU engine (Gpu/) drives OpenGL itself: it binds its own framebuffers,
 * programs, vertex arrays and textures, sets the viewport and switches
 * blending, depth test and the rest. VTK keeps a cached view of that state
 * (vtkOpenGLState, the texture units, the bound shader) and trusts it, so the
 * display's mapper runs every engine call inside a guard that puts back what
 * the engine may have changed: the cache stays true.
 */
#ifndef BoundParticles_GLStateGuard_h
#define BoundParticles_GLStateGuard_h

class vtkOpenGLState;

namespace bpvtk
{

/// Saves the state on construction, restores it on destruction; the context
/// must be current for both.
class GLStateGuard
{
public:
  GLStateGuard();
  ~GLStateGuard();
  GLStateGuard(const GLStateGuard&) = delete;
  GLStateGuard& operator=(const GLStateGuard&) = delete;

  /**
   * VTK's cache `state` learns the context's state again once the guard has
   * put GL back (vtkOpenGLState::Reset): for a run that let the GUI run
   * inside it (a progress report), which may have recorded the engine's
   * state in the cache, behind which the guard then puts GL back.
   */
  void resetCacheAfter(vtkOpenGLState* state) { this->Cache = state; }

  /// The texture units saved (the first ones, up to the context's count).
  static constexpr int Units = 16;
  /// GL_BLEND, GL_DEPTH_TEST, GL_SCISSOR_TEST, GL_CULL_FACE, GL_STENCIL_TEST.
  static constexpr int Capabilities = 5;

private:
  // GLint and GLboolean (static_asserted in the .cxx): no GL header here.
  int DrawFbo = 0, ReadFbo = 0, Viewport[4] = { 0, 0, 0, 0 }, Program = 0, ActiveTexture = 0,
      Vao = 0, UnitCount = 0;
  int Texture2D[Units] = {}, Texture3D[Units] = {};
  unsigned char Enabled[Capabilities] = {}, ColorMask[4] = {};
  vtkOpenGLState* Cache = nullptr;
};

} // namespace bpvtk

#endif
