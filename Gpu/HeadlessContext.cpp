// SPDX-License-Identifier: BSD-3-Clause
#include "HeadlessContext.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <string>

namespace bp
{

HeadlessContext::~HeadlessContext()
{
  if (this->Display)
  {
    eglMakeCurrent(this->Display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (this->Context)
    {
      eglDestroyContext(this->Display, this->Context);
    }
    eglTerminate(this->Display);
  }
}

std::string HeadlessContext::create()
{
  auto getDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
    eglGetProcAddress("eglGetPlatformDisplayEXT"));
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLint major = 0, minor = 0;
  if (getDisplay)
  {
    // Mesa's software (or hardware) surfaceless platform first ...
    display = getDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display != EGL_NO_DISPLAY && !eglInitialize(display, &major, &minor))
    {
      display = EGL_NO_DISPLAY;
    }
    // ... then the first EGL device (NVIDIA's driver offers no surfaceless platform).
    auto queryDevices =
      reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    if (display == EGL_NO_DISPLAY && queryDevices)
    {
      EGLDeviceEXT devices[8];
      EGLint count = 0;
      if (queryDevices(8, devices, &count) && count > 0)
      {
        display = getDisplay(EGL_PLATFORM_DEVICE_EXT, devices[0], nullptr);
        if (display != EGL_NO_DISPLAY && !eglInitialize(display, &major, &minor))
        {
          display = EGL_NO_DISPLAY;
        }
      }
    }
  }
  if (display == EGL_NO_DISPLAY)
  {
    return "no headless EGL display (needs Mesa's surfaceless platform or an EGL device)";
  }
  this->Display = display;
  if (!eglBindAPI(EGL_OPENGL_API))
  {
    return "EGL cannot bind the desktop OpenGL API";
  }
  const EGLint configAttributes[] = { EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
    EGL_OPENGL_BIT, EGL_NONE };
  EGLConfig config = nullptr;
  EGLint configs = 0;
  eglChooseConfig(display, configAttributes, &config, 1, &configs);
  // 4.3 core (the GPU engine's compute path) where the driver has it, else
  // 3.3 core (its fragment path); a driver may give a later version of either.
  const EGLint versions[2][2] = { { 4, 3 }, { 3, 3 } };
  for (const EGLint* version : versions)
  {
    const EGLint contextAttributes[] = { EGL_CONTEXT_MAJOR_VERSION, version[0],
      EGL_CONTEXT_MINOR_VERSION, version[1], EGL_CONTEXT_OPENGL_PROFILE_MASK,
      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE };
    this->Context = eglCreateContext(
      display, configs > 0 ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, contextAttributes);
    if (this->Context)
    {
      break;
    }
  }
  if (!this->Context)
  {
    return "EGL cannot create an OpenGL 3.3 core context";
  }
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, this->Context))
  {
    return "EGL cannot make the context current without a surface";
  }
  return std::string();
}

std::string HeadlessContext::description() const
{
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return std::string(renderer ? renderer : "?") + ", OpenGL " + (version ? version : "?");
}

} // namespace bp
