// SPDX-License-Identifier: BSD-3-Clause
#include "HeadlessContext.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdlib>
#include <string>
#include <vector>

namespace bp
{
namespace
{
struct Device
{
  EGLDeviceEXT handle;
  bool software;
  std::string name;
};

std::vector<Device> eglDevices()
{
  std::vector<Device> devices;
  auto queryDevices =
    reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  auto queryString =
    reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
  EGLDeviceEXT handles[16];
  EGLint count = 0;
  if (!queryDevices || !queryDevices(16, handles, &count))
  {
    return devices;
  }
  for (EGLint i = 0; i < count; ++i)
  {
    const char* extensions = queryString ? queryString(handles[i], EGL_EXTENSIONS) : nullptr;
    const std::string ext = extensions ? extensions : "";
    Device d{ handles[i], ext.find("EGL_MESA_device_software") != std::string::npos, "" };
    const char* file = ext.find("EGL_EXT_device_drm") != std::string::npos && queryString
      ? queryString(handles[i], EGL_DRM_DEVICE_FILE_EXT)
      : nullptr;
    d.name = d.software ? "software (EGL_MESA_device_software)"
                        : std::string("hardware") + (file ? std::string(", ") + file : "") +
        (ext.find("EGL_NV_device_cuda") != std::string::npos ? ", NVIDIA CUDA device" : "");
    devices.push_back(d);
  }
  return devices;
}

EGLDisplay initialize(EGLDisplay display)
{
  EGLint major = 0, minor = 0;
  return display != EGL_NO_DISPLAY && eglInitialize(display, &major, &minor) ? display
                                                                             : EGL_NO_DISPLAY;
}

std::string glInteger(const char* name, GLenum which)
{
  GLint value = -1;
  glGetIntegerv(which, &value);
  return std::string(name) + " " + std::to_string(value) + "\n";
}
} // namespace

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
  const std::vector<Device> devices = getDisplay ? eglDevices() : std::vector<Device>();
  for (size_t i = 0; i < devices.size(); ++i)
  {
    this->Devices += "EGL device " + std::to_string(i) + ": " + devices[i].name + "\n";
  }
  auto onDevice = [&](size_t i)
  {
    this->Taken = "EGL device " + std::to_string(i) + " (" + devices[i].name + ")";
    return initialize(getDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i].handle, nullptr));
  };
  EGLDisplay display = EGL_NO_DISPLAY;
  const char* wanted = std::getenv("BOUNDPARTICLES_EGL_DEVICE");
  if (wanted && *wanted)
  {
    char* end = nullptr;
    const long index = std::strtol(wanted, &end, 10);
    if (*end || index < 0 || size_t(index) >= devices.size())
    {
      this->Taken = "none";
      return "BOUNDPARTICLES_EGL_DEVICE=" + std::string(wanted) + " names no EGL device (" +
        std::to_string(devices.size()) + " found)";
    }
    display = onDevice(size_t(index));
  }
  else if (getDisplay)
  {
    // A hardware device first (NVIDIA's driver offers no surfaceless platform,
    // and its first device need not be the GPU), then Mesa's surfaceless
    // platform (hardware where Mesa drives one), then a software device.
    for (size_t i = 0; i < devices.size() && display == EGL_NO_DISPLAY; ++i)
      if (!devices[i].software)
        display = onDevice(i);
    if (display == EGL_NO_DISPLAY)
    {
      this->Taken = "Mesa's surfaceless platform";
      display = initialize(getDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr));
    }
    for (size_t i = 0; i < devices.size() && display == EGL_NO_DISPLAY; ++i)
      display = onDevice(i);
  }
  if (display == EGL_NO_DISPLAY)
  {
    this->Taken = "none";
    return "no headless EGL display (needs an EGL device or Mesa's surfaceless platform; " +
      std::to_string(devices.size()) + " EGL devices found)";
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

std::string HeadlessContext::report() const
{
  std::string text = this->Devices.empty() ? "EGL devices: none enumerated\n" : this->Devices;
  text += "display: " + (this->Taken.empty() ? std::string("none") : this->Taken) + "\n";
  if (!this->Display || !this->Context)
  {
    return text;
  }
  const char* eglVendor = eglQueryString(this->Display, EGL_VENDOR);
  text += std::string("EGL vendor: ") + (eglVendor ? eglVendor : "?") + "\n";
  const char* strings[3][2] = { { "GL vendor: ", nullptr }, { "GL renderer: ", nullptr },
    { "GL version: ", nullptr } };
  const GLenum names[3] = { GL_VENDOR, GL_RENDERER, GL_VERSION };
  for (int i = 0; i < 3; ++i)
  {
    const char* value = reinterpret_cast<const char*>(glGetString(names[i]));
    text += std::string(strings[i][0]) + (value ? value : "?") + "\n";
  }
  text += glInteger("GL_MAX_TEXTURE_SIZE", GL_MAX_TEXTURE_SIZE);
  text += glInteger("GL_MAX_TEXTURE_IMAGE_UNITS", GL_MAX_TEXTURE_IMAGE_UNITS);
  text += glInteger("GL_MAX_DRAW_BUFFERS", GL_MAX_DRAW_BUFFERS);
  if (epoxy_gl_version() < 43)
  {
    return text + "compute: none (OpenGL below 4.3)\n";
  }
  GLint size[3] = { -1, -1, -1 };
  for (GLuint axis = 0; axis < 3; ++axis)
    glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_SIZE, axis, &size[axis]);
  text += "GL_MAX_COMPUTE_WORK_GROUP_SIZE " + std::to_string(size[0]) + " " +
    std::to_string(size[1]) + " " + std::to_string(size[2]) + "\n";
  text += glInteger("GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS", GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS);
  text += glInteger("GL_MAX_COMPUTE_SHARED_MEMORY_SIZE", GL_MAX_COMPUTE_SHARED_MEMORY_SIZE);
  text += glInteger("GL_MAX_COMPUTE_IMAGE_UNIFORMS", GL_MAX_COMPUTE_IMAGE_UNIFORMS);
  text += glInteger("GL_MAX_FRAGMENT_IMAGE_UNIFORMS", GL_MAX_FRAGMENT_IMAGE_UNIFORMS);
  text += glInteger("GL_MAX_IMAGE_UNITS", GL_MAX_IMAGE_UNITS);
  text += glInteger("GL_MAX_COMPUTE_TEXTURE_IMAGE_UNITS", GL_MAX_COMPUTE_TEXTURE_IMAGE_UNITS);
  return text;
}

} // namespace bp
