/* MuJoCo's render-to-texture pattern through the OSMesa C ABI (not a test):
 * a 4096² GL_DEPTH24_STENCIL8 depth texture on GL_DEPTH_ATTACHMENT of its
 * own framebuffer object (draw and read buffers GL_NONE), per frame and per
 * shadow light: bind it, clear its depth, glViewport(1, 1, 4094, 4094),
 * draw the casters depth-only with polygon offset; bind the 4x multisampled
 * offscreen object again and draw the lit pass sampling the map (unit 1,
 * GL_COMPARE_R_TO_TEXTURE, projective eye-linear texgen on S, T, R, Q,
 * additive blend); at the end resolve by glBlitFramebuffer into a
 * single-sampled object and glReadPixels from it (docs/mujoco-trace.txt).
 * Rows (`ROW MEDIAN_MS`, FRAMES frames after one warm-up):
 *   quad-WxH    the casters and receivers are one quad: what is left is the
 *               cost around the passes (binding, clearing, resolving);
 *   plane-WxH   MuJoCo's 200x200-quad floor list as both.
 *   cc -O2 osmesa/bench/shadow_fbo.c -o /tmp/sfbo -lOSMesa -lm
 *   /tmp/sfbo [FRAMES] [SIZE] [ROWS]       e.g. 5 320x240 quad,plane */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench.h"
#include "bench_fbo.h"

static GLuint fbo_ms, fbo_resolve, fbo_shadow, shadow_tex;
static int W, H;
static unsigned char *readback;

static GLuint renderbuffer(int samples, GLenum format) {
  GLuint rb;
  GenRenderbuffers(1, &rb);
  BindRenderbuffer(GL_RENDERBUFFER, rb);
  RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, W, H);
  return rb;
}

static void setup(void) {
  GenFramebuffers(1, &fbo_ms);
  BindFramebuffer(GL_FRAMEBUFFER, fbo_ms);
  FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffer(4, GL_RGBA8));
  FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                          renderbuffer(4, GL_DEPTH24_STENCIL8));
  if (CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) exit(3);
  GenFramebuffers(1, &fbo_resolve);
  BindFramebuffer(GL_FRAMEBUFFER, fbo_resolve);
  FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffer(0, GL_RGBA8));
  FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                          renderbuffer(0, GL_DEPTH24_STENCIL8));
  if (CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) exit(3);
  ActiveTexture(GL_TEXTURE1);
  glGenTextures(1, &shadow_tex);
  glBindTexture(GL_TEXTURE_2D, shadow_tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 4096, 4096, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, NULL);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_GEQUAL);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_INTENSITY);
  GenFramebuffers(1, &fbo_shadow);
  BindFramebuffer(GL_FRAMEBUFFER, fbo_shadow);
  FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, shadow_tex, 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  if (CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) exit(3);
  ActiveTexture(GL_TEXTURE0);
  BindFramebuffer(GL_FRAMEBUFFER, fbo_ms);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glDrawBuffer(GL_COLOR_ATTACHMENT0);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GEQUAL);
  glClearDepth(0);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_MULTISAMPLE);
  readback = malloc((size_t)W * H * 3);
}

static void camera(void) {
  static const GLfloat view[16] = {0.741298497f, -0.300687939f, 0.600052893f, 0, 0.671175599f, 0.332103133f,
                                   -0.662744999f, 0, 0, 0.894032598f, 0.448001951f, 0, -0.0200352669f,
                                   0.0281088352f, -3.62750769f, 1};
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glScalef(1, 1, -1);
  glFrustum(-0.0134893097, 0.0134893097, -0.0101169823, 0.0101169823, 0.0244245548, 122.12278);
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixf(view);
}

/* One frame: two shadow lights, each a depth pass into the map and a lit pass sampling it. */
static void frame(GLuint l) {
  static const GLfloat sp[4] = {0.196390659f, -0.0113302302f, 0.0566511452f, 0.273395419f};
  static const GLfloat tp[4] = {0, 0.200736657f, 0.0401473343f, 0.339410663f};
  static const GLfloat rp[4] = {-0.00231138477f, -0.00154092337f, 0.00770461652f, 0.969381571f};
  static const GLfloat qp[4] = {0, 0, 0, 1};
  static const GLfloat light[16] = {0.959350884f, 0, -0.282216281f, 0, -0.055347167f, 0.980580747f, -0.188144207f, 0,
                                    0.276735812f, 0.196116149f, 0.940720975f, 0, -1.10694325f, -0.784464598f,
                                    -3.7628839f, 1};
  BindFramebuffer(GL_FRAMEBUFFER, fbo_ms);
  glViewport(0, 0, W, H);
  glScissor(0, 0, W, H);
  glEnable(GL_SCISSOR_TEST);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  camera();
  glCallList(l);
  for (int light_i = 0; light_i < 2; light_i++) {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glTranslatef(0, 0, 0.5);
    glScalef(1, 1, -0.5);
    glOrtho(-2.44245553, 2.44245553, -2.44245553, 2.44245553, 0.0244245548, 122.12278);
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixf(light);
    BindFramebuffer(GL_FRAMEBUFFER, fbo_shadow);
    glDrawBuffer(GL_NONE);
    glClear(GL_DEPTH_BUFFER_BIT);
    glViewport(1, 1, 4094, 4094);
    glShadeModel(GL_FLAT);
    glDisable(GL_LIGHTING);
    glColorMask(0, 0, 0, 0);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(-1.5, -4);
    glCallList(l);
    BindFramebuffer(GL_FRAMEBUFFER, fbo_ms);
    glDrawBuffer(GL_COLOR_ATTACHMENT0);
    glViewport(0, 0, W, H);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glShadeModel(GL_SMOOTH);
    glEnable(GL_LIGHTING);
    glColorMask(1, 1, 1, 1);
    camera();
    ActiveTexture(GL_TEXTURE1);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glEnable(GL_TEXTURE_GEN_R);
    glEnable(GL_TEXTURE_GEN_Q);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glBindTexture(GL_TEXTURE_2D, shadow_tex);
    glTexGenfv(GL_S, GL_EYE_PLANE, sp);
    glTexGenfv(GL_T, GL_EYE_PLANE, tp);
    glTexGenfv(GL_R, GL_EYE_PLANE, rp);
    glTexGenfv(GL_Q, GL_EYE_PLANE, qp);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glCallList(l);
    glDisable(GL_BLEND);
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_GEN_T);
    glDisable(GL_TEXTURE_GEN_R);
    glDisable(GL_TEXTURE_GEN_Q);
    glDisable(GL_TEXTURE_2D);
    ActiveTexture(GL_TEXTURE0);
  }
  BindFramebuffer(GL_READ_FRAMEBUFFER, fbo_ms);
  BindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_resolve);
  BlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  BindFramebuffer(GL_READ_FRAMEBUFFER, fbo_resolve);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, W, H, GL_RGB, GL_UNSIGNED_BYTE, readback);
  BindFramebuffer(GL_FRAMEBUFFER, fbo_ms);
}

static void time_row(const char *row, int frames, GLuint l) {
  double t[64];
  if (frames > 64) frames = 64;
  for (int i = 0; i <= frames; i++) {
    double t0 = now();
    frame(l);
    if (i) t[i - 1] = 1000 * (now() - t0);
  }
  qsort(t, frames, sizeof t[0], cmp);
  unsigned sum = 0;
  for (size_t i = 0; i < (size_t)W * H * 3; i++) sum = sum * 31 + readback[i];
  printf("%s %.3f (checksum %08x, error 0x%x)\n", row, t[frames / 2], sum, glGetError());
  fflush(stdout);
}

int main(int argc, char **argv) {
  int frames = argc > 1 ? atoi(argv[1]) : 5;
  const char *size = argc > 2 ? argv[2] : "320x240";
  const char *rows = argc > 3 ? argv[3] : "quad,plane";
  if (sscanf(size, "%dx%d", &W, &H) != 2) return 2;
  float *px = malloc((size_t)W * H * 4 * sizeof(float));
  OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  if (!c || !OSMesaMakeCurrent(c, px, GL_FLOAT, W, H)) return 1;
  load_fbo_functions();
  setup();
  char row[64];
  if (strstr(rows, "quad")) {
    GLuint l = plane_list(1, 0);
    snprintf(row, sizeof row, "quad-%dx%d", W, H);
    time_row(row, frames, l);
  }
  if (strstr(rows, "plane")) {
    GLuint l = plane_list(200, 0);
    snprintf(row, sizeof row, "plane-%dx%d", W, H);
    time_row(row, frames, l);
  }
  OSMesaDestroyContext(c);
  free(px);
  return 0;
}
