/* Multisampled deep colour objects (4x GL_RGBA16, GL_RGBA32F, GL_RGBA16F,
 * GL_RGB16F with a 4x DEPTH24_STENCIL8), a scene drawn into each (smooth
 * colour, depth test, blending over and additive past 1, a bitmap, a
 * scissored clear past 1), resolved by glBlitFramebuffer into a
 * single-sampled object of the same format and into an RGBA8 one
 * (<fmt>.<n>.f/.us/.ub); lines: completeness, GL_SAMPLES, errors. */
#define GL_GLEXT_PROTOTYPES
#include "common.h"
#include <GL/glext.h>
#include "fbo_object.h"

#define W 40
#define H 30

static void scene(void) {
  glViewport(0, 0, W, H);
  glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.5, 1.5, -1.1, 1.1, -5, 5);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_DEPTH_TEST);
  glBegin(GL_TRIANGLES);
  glColor4f(1.0f, 0.1f, 0.2f, 1.0f);
  glVertex3f(-1.4f, -1.0f, 0.2f);
  glColor4f(0.0f, 0.9f, 0.3f, 0.6f);
  glVertex3f(0.3f, -0.9f, -0.4f);
  glColor4f(0.3f, 0.2f, 1.0f, 0.8f);
  glVertex3f(-0.5f, 0.9f, 0.1f);
  glEnd();
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glBegin(GL_TRIANGLES);
  glColor4f(0.9f, 0.9f, 0.1f, 0.37f);
  glVertex2f(-1.2f, 0.2f);
  glColor4f(0.1f, 0.8f, 0.9f, 0.71f);
  glVertex2f(0.2f, 0.8f);
  glVertex2f(-1.2f, 0.8f);
  glEnd();
  glBlendFunc(GL_ONE, GL_ONE);
  glBegin(GL_TRIANGLES);
  glColor4f(0.8f, 0.7f, 0.6f, 0.9f);
  glVertex2f(-0.3f, -0.8f);
  glVertex2f(1.4f, -0.6f);
  glVertex2f(0.9f, 0.6f);
  glEnd();
  glDisable(GL_BLEND);
  static const GLubyte bits[8] = {0xff, 0x81, 0xbd, 0xa5, 0xa5, 0xbd, 0x81, 0xff};
  glColor4f(0.2f, 1.0f, 0.6f, 1.0f);
  glRasterPos2f(0.6f, 0.5f);
  glBitmap(8, 8, 0, 0, 8, 0, bits);
  glEnable(GL_SCISSOR_TEST);
  glScissor(30, 2, 6, 5);
  glClearColor(2.5f, 0.125f, 0.3f, 0.6f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
}

static GLuint object(GLenum format, int samples) {
  GLuint rbs[2];
  return colour_depth_object(format, samples, W, H, rbs);
}

static float f[W * H * 4];
static unsigned short us[W * H * 4];
static unsigned char ub[W * H * 4];

static void read_all(const char *name) {
  char file[64];
  memset(f, 0, sizeof f);
  memset(us, 0, sizeof us);
  memset(ub, 0, sizeof ub);
  glReadPixels(0, 0, W, H, GL_RGBA, GL_FLOAT, f);
  glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_SHORT, us);
  glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, ub);
  snprintf(file, sizeof file, "%s.f", name);
  dump(file, f, sizeof f);
  snprintf(file, sizeof file, "%s.us", name);
  dump(file, us, sizeof us);
  snprintf(file, sizeof file, "%s.ub", name);
  dump(file, ub, sizeof ub);
}

int main(int argc, char **argv) {
  start(argc, argv);
  static unsigned char window[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(ctx);
  CHECK(OSMesaMakeCurrent(ctx, window, GL_UNSIGNED_BYTE, W, H));
  const struct { GLenum format; const char *name; } formats[] = {
    {GL_RGBA16, "rgba16"}, {GL_RGBA32F, "rgba32f"}, {GL_RGBA16F, "rgba16f"}, {GL_RGB16F, "rgb16f"},
  };
  GLuint rgba8 = object(GL_RGBA8, 0);
  for (int i = 0; i < 4; i++) {
    const char *n = formats[i].name;
    GLuint ms = object(formats[i].format, 4);
    GLint samples = -1;
    glGetIntegerv(GL_SAMPLES, &samples);
    printf("%s status 0x%x samples %d\n", n, glCheckFramebufferStatus(GL_FRAMEBUFFER), samples);
    scene();
    printf("%s drawn error 0x%x\n", n, glGetError());
    GLuint single = object(formats[i].format, 0);
    GLuint to[2] = {single, rgba8};
    for (int k = 0; k < 2; k++) {
      glBindFramebuffer(GL_DRAW_FRAMEBUFFER, to[k]);
      glClearColor(0, 0, 0, 0);
      glClear(GL_COLOR_BUFFER_BIT);
      glBindFramebuffer(GL_READ_FRAMEBUFFER, ms);
      glBlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_COLOR_BUFFER_BIT, GL_NEAREST);
      printf("%s resolve %d error 0x%x\n", n, k, glGetError());
      glBindFramebuffer(GL_READ_FRAMEBUFFER, to[k]);
      char name[32];
      snprintf(name, sizeof name, "%s.%d", n, k);
      read_all(name);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }
  printf("done\n");
  return 0;
}
