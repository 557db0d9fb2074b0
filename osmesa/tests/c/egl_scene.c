/* The scene of formats.c rendered twice in one process: through EGL (a
 * surfaceless display's W x H pbuffer, RGBA8 + depth 24 + stencil 8) and
 * through OSMesa (OSMESA_RGBA bytes, 24/8). Writes the colour and depth each
 * glReadPixels returns, for the test to compare byte for byte. Built against
 * Khronos' and Mesa's headers (-lEGL -lOSMesa); run on softgl, both names
 * resolve to the same library. */
#define main formats_main
#include "formats.c"
#undef main
#include <EGL/egl.h>
#include <EGL/eglext.h>

static void read_back(const char *color_name, const char *depth_name) {
  static unsigned char color[W * H * 4];
  static float depth[W * H];
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, color);
  glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
  CHECK(glGetError() == GL_NO_ERROR);
  dump(color_name, color, sizeof color);
  dump(depth_name, depth, sizeof depth);
}

int main(int argc, char **argv) {
  start(argc, argv);
  Dl_info info;
  if (dladdr((void *)eglGetDisplay, &info) && info.dli_fname) printf("egl %s\n", info.dli_fname);

  EGLDisplay dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
  CHECK(dpy != EGL_NO_DISPLAY);
  CHECK(eglInitialize(dpy, NULL, NULL));
  static const EGLint want[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                EGL_RED_SIZE, 8, EGL_ALPHA_SIZE, 8, EGL_DEPTH_SIZE, 24, EGL_STENCIL_SIZE, 8, EGL_NONE};
  EGLConfig config;
  EGLint n = 0;
  CHECK(eglChooseConfig(dpy, want, &config, 1, &n) && n == 1);
  CHECK(eglBindAPI(EGL_OPENGL_API));
  static const EGLint size[] = {EGL_WIDTH, W, EGL_HEIGHT, H, EGL_NONE};
  EGLSurface surface = eglCreatePbufferSurface(dpy, config, size);
  CHECK(surface != EGL_NO_SURFACE);
  EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, NULL);
  CHECK(ctx != EGL_NO_CONTEXT);
  CHECK(eglMakeCurrent(dpy, surface, surface, ctx));
  scene();
  read_back("egl_color", "egl_depth");
  CHECK(eglSwapBuffers(dpy, surface));
  CHECK(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));

  static unsigned char buf[W * H * 4];
  OSMesaContext os = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(os);
  CHECK(OSMesaMakeCurrent(os, buf, GL_UNSIGNED_BYTE, W, H));
  scene();
  read_back("osmesa_color", "osmesa_depth");
  dump("osmesa_buffer", buf, sizeof buf);
  OSMesaDestroyContext(os);

  CHECK(eglDestroyContext(dpy, ctx));
  CHECK(eglDestroySurface(dpy, surface));
  CHECK(eglTerminate(dpy));
  printf("done\n");
  return 0;
}
