/* A multisampled default framebuffer through EGL: a surfaceless display's
 * pbuffer of a config with EGL_SAMPLE_BUFFERS 1 and EGL_SAMPLES argv[2]
 * (llvmpipe rounds 2 up to 4), RGBA8 + depth 24 + stencil 8. Draws
 * triangles (depth-tested, smooth), wide lines and points, and writes what
 * glReadPixels returns for colour and depth, and prints the config's and
 * GL's sample counts. Built against Khronos' headers (-lEGL -lOpenGL). */
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>

#define W 37
#define H 29
#define CHECK(c) do { if (!(c)) { fprintf(stderr, "%s:%d: %s\n", __FILE__, __LINE__, #c); exit(1); } } while (0)

static void dump(const char *dir, const char *name, const void *data, size_t n) {
  char path[4096];
  snprintf(path, sizeof path, "%s/%s", dir, name);
  FILE *f = fopen(path, "wb");
  CHECK(f && fwrite(data, 1, n, f) == n);
  fclose(f);
}

int main(int argc, char **argv) {
  CHECK(argc > 2);
  int samples = atoi(argv[2]);
  EGLDisplay dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
  CHECK(dpy != EGL_NO_DISPLAY && eglInitialize(dpy, NULL, NULL));
  EGLint want[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                   EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
                   EGL_DEPTH_SIZE, 24, EGL_STENCIL_SIZE, 8,
                   EGL_SAMPLE_BUFFERS, samples > 0, EGL_SAMPLES, samples, EGL_NONE};
  EGLConfig config;
  EGLint n = 0, cs = -1, csb = -1, alpha = -1;
  CHECK(eglChooseConfig(dpy, want, &config, 1, &n) && n == 1);
  eglGetConfigAttrib(dpy, config, EGL_SAMPLES, &cs);
  eglGetConfigAttrib(dpy, config, EGL_SAMPLE_BUFFERS, &csb);
  eglGetConfigAttrib(dpy, config, EGL_ALPHA_SIZE, &alpha);
  printf("config: samples %d, sample buffers %d, alpha %d\n", cs, csb, alpha);
  CHECK(eglBindAPI(EGL_OPENGL_API));
  EGLint size[] = {EGL_WIDTH, W, EGL_HEIGHT, H, EGL_NONE};
  EGLSurface surface = eglCreatePbufferSurface(dpy, config, size);
  EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, NULL);
  CHECK(surface != EGL_NO_SURFACE && ctx != EGL_NO_CONTEXT);
  CHECK(eglMakeCurrent(dpy, surface, surface, ctx));
  GLint gs = -1, gsb = -1;
  glGetIntegerv(GL_SAMPLES, &gs);
  glGetIntegerv(GL_SAMPLE_BUFFERS, &gsb);
  printf("GL_SAMPLES %d, GL_SAMPLE_BUFFERS %d, multisample %d\n", gs, gsb, glIsEnabled(GL_MULTISAMPLE));

  glMatrixMode(GL_PROJECTION);
  glOrtho(0, W, 0, H, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glClearColor(0.1f, 0.1f, 0.2f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glShadeModel(GL_SMOOTH);
  glBegin(GL_TRIANGLES);
  glColor3f(0.9f, 0.2f, 0.1f); glVertex3f(2.3f, 1.7f, -0.5f);
  glColor3f(0.2f, 0.9f, 0.3f); glVertex3f(33.1f, 6.2f, 0.5f);
  glColor3f(0.1f, 0.3f, 0.9f); glVertex3f(12.6f, 27.4f, 0.0f);
  glColor3f(0.9f, 0.9f, 0.2f); glVertex3f(5.2f, 20.1f, 0.3f);
  glColor3f(0.8f, 0.2f, 0.9f); glVertex3f(35.7f, 24.9f, -0.4f);
  glColor3f(0.2f, 0.8f, 0.8f); glVertex3f(20.3f, 2.2f, 0.2f);
  glEnd();
  glDisable(GL_DEPTH_TEST);
  glLineWidth(2.5f);
  glBegin(GL_LINES);
  glColor3f(1, 1, 1); glVertex2f(1.2f, 26.3f); glVertex2f(30.7f, 14.1f);
  glEnd();
  glPointSize(3.3f);
  glBegin(GL_POINTS);
  glColor3f(1, 0.5f, 0); glVertex2f(30.4f, 3.6f); glVertex2f(6.1f, 8.8f);
  glEnd();

  static unsigned char color[W * H * 4];
  static float depth[W * H];
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, color);
  glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
  printf("error 0x%x\n", glGetError());
  dump(argv[1], "color", color, sizeof color);
  dump(argv[1], "depth", depth, sizeof depth);
  CHECK(eglSwapBuffers(dpy, surface));
  CHECK(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  CHECK(eglDestroyContext(dpy, ctx) && eglDestroySurface(dpy, surface) && eglTerminate(dpy));
  printf("done\n");
  return 0;
}
