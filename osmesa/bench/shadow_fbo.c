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

static void setup(void) {
  fbo_ms = rgba8_d24s8_object(4, W, H);
  fbo_resolve = rgba8_d24s8_object(0, W, H);
  fbo_shadow = shadow_map_object(&shadow_tex);
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

/* One frame: two shadow lights, each a depth pass into the map and a lit pass sampling it. */
static void frame(GLuint l) {
  static const GLfloat sp[4] = {0.196390659f, -0.0113302302f, 0.0566511452f, 0.273395419f};
  static const GLfloat tp[4] = {0, 0.200736657f, 0.0401473343f, 0.339410663f};
  static const GLfloat rp[4] = {-0.00231138477f, -0.00154092337f, 0.00770461652f, 0.969381571f};
  static const GLfloat qp[4] = {0, 0, 0, 1};
  BindFramebuffer(GL_FRAMEBUFFER, fbo_ms);
  glViewport(0, 0, W, H);
  glScissor(0, 0, W, H);
  glEnable(GL_SCISSOR_TEST);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  camera();
  glCallList(l);
  for (int light_i = 0; light_i < 2; light_i++) {
    begin_shadow_pass(fbo_shadow);
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
