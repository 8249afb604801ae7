#include "gl/headless_context.hpp"

#include <glad/egl.h>

#include <vector>

#include "gl/gl.hpp"
#include "gl/gl_error.hpp"

namespace clothlab::vis {
namespace {

bool has_extension(const char* list, const std::string& name) {
  if (!list) return false;
  const std::string all = std::string(" ") + list + " ";
  return all.find(" " + name + " ") != std::string::npos;
}

// Tries a device display (headless GPU drivers), then Mesa's surfaceless platform, then the
// default display.
EGLDisplay open_display() {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (has_extension(client, "EGL_EXT_platform_device") && eglQueryDevicesEXT) {
    EGLDeviceEXT devices[8];
    EGLint count = 0;
    if (eglQueryDevicesEXT(8, devices, &count) && count > 0) {
      for (EGLint i = 0; i < count; ++i) {
        EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) return d;
      }
    }
  }
  if (has_extension(client, "EGL_MESA_platform_surfaceless") && eglGetPlatformDisplayEXT) {
    EGLDisplay d =
        eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) return d;
  }
  EGLDisplay d = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) return d;
  return EGL_NO_DISPLAY;
}

}  // namespace

HeadlessContext::HeadlessContext() {
  if (!gladLoaderLoadEGL(nullptr))
    throw GlUnavailable("no EGL library found (install libegl1 and Mesa's libegl-mesa0)");
  EGLDisplay display = open_display();
  if (display == EGL_NO_DISPLAY)
    throw GlUnavailable("EGL found no display to render headless on (no GPU driver and no Mesa)");
  gladLoaderLoadEGL(display);  // now with the display's extensions
  display_ = display;
  if (!eglBindAPI(EGL_OPENGL_API))
    throw GlUnavailable("this EGL driver does not offer desktop OpenGL");
  const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  eglChooseConfig(display, config_attributes, &config, 1, &configs);
  const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                       4,
                                       EGL_CONTEXT_MINOR_VERSION,
                                       5,
                                       EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                       EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                       EGL_NONE};
  EGLContext context = eglCreateContext(display, configs > 0 ? config : EGL_NO_CONFIG_KHR,
                                        EGL_NO_CONTEXT, context_attributes);
  if (context == EGL_NO_CONTEXT)
    throw GlUnavailable("this machine offers no OpenGL 4.5 core context through EGL");
  context_ = context;
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
    throw GlUnavailable("cannot make the headless OpenGL context current (no surfaceless support)");
  const int version = gladLoadGL(reinterpret_cast<GLADloadfunc>(eglGetProcAddress));
  if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 45)
    throw GlUnavailable("OpenGL 4.5 core is required; this driver offers " +
                        std::to_string(GLAD_VERSION_MAJOR(version)) + "." +
                        std::to_string(GLAD_VERSION_MINOR(version)));
}

HeadlessContext::~HeadlessContext() {
  auto display = static_cast<EGLDisplay>(display_);
  if (!display) return;
  eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (context_) eglDestroyContext(display, static_cast<EGLContext>(context_));
  eglTerminate(display);
  // libEGL stays loaded: Mesa keeps process-wide state in it, and unloading it first made
  // LeakSanitizer report the driver's own allocations without names.
}

std::string HeadlessContext::renderer() const {
  return reinterpret_cast<const char*>(glGetString(GL_RENDERER));
}

}  // namespace clothlab::vis
