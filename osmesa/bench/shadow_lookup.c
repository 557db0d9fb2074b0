/* One of MuJoCo's additive light passes through the OSMesa C ABI (not a
 * test): the 200x200-quad floor, lit, drawn into a 4x multisampled RGBA8 +
 * D24S8 object with unit 0 the floor's 256² checker (RGB, REPEAT,
 * LINEAR_MIPMAP_LINEAR, MODULATE) and unit 1 the 4096² GL_DEPTH24_STENCIL8
 * shadow map made once at set-up (NEAREST, CLAMP_TO_EDGE,
 * GL_COMPARE_R_TO_TEXTURE GEQUAL, INTENSITY, eye-linear texgen on S, T, R, Q),
 * additive blend, as docs/mujoco-trace.txt has it. Units to isolate their cost:
 *   both      both units (MuJoCo's light pass)
 *   depth     unit 1 only
 *   checker   unit 0 only
 *   none      no texture
 *   srgb      both, the checker uploaded as GL_SRGB8 (MuJoCo's sRGB PNG
 *             textures: sampled through the callout, llvmpipe's SoA path)
 * Per frame: clear, the pass, glFinish. Prints `ROW MEDIAN_MS` and, once, the
 * samples the floor covers (4 per covered pixel: the count per textured
 * fragment divides by it) and a checksum of the resolved image.
 *   cc -O2 osmesa/bench/shadow_lookup.c -o /tmp/slk -lOSMesa -lGLU -lm
 *   /tmp/slk [FRAMES] [SIZE] [MODE]        e.g. 5 320x240 both */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/glu.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench.h"
#include "bench_fbo.h"
#include "bench_checker.h"

static GLuint fbo_ms, fbo_resolve, fbo_shadow, shadow_tex, checker_tex;
static int W, H;

/* The shadow map: the floor and a box-like caster from the light. */
static void shadow_pass(GLuint l) {
  begin_shadow_pass(fbo_shadow);
  glCallList(l);
  /* A caster: a small raised quad. */
  glBegin(GL_QUADS);
  glVertex3f(-0.3f, -0.3f, 0.4f);
  glVertex3f(0.3f, -0.3f, 0.4f);
  glVertex3f(0.3f, 0.3f, 0.4f);
  glVertex3f(-0.3f, 0.3f, 0.4f);
  glEnd();
  glDisable(GL_POLYGON_OFFSET_FILL);
  glColorMask(1, 1, 1, 1);
  glShadeModel(GL_SMOOTH);
  BindFramebuffer(GL_FRAMEBUFFER, fbo_ms);
  glDrawBuffer(GL_COLOR_ATTACHMENT0);
  glViewport(0, 0, W, H);
}

static void setup(const char *mode) {
  fbo_ms = rgba8_d24s8_object(4, W, H);
  fbo_resolve = rgba8_d24s8_object(0, W, H);
  ActiveTexture(GL_TEXTURE0);
  checker_tex = checker_texture(strcmp(mode, "srgb") ? GL_RGB : GL_SRGB8);
  fbo_shadow = shadow_map_object(&shadow_tex);
  BindFramebuffer(GL_FRAMEBUFFER, fbo_ms);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glDrawBuffer(GL_COLOR_ATTACHMENT0);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GEQUAL);
  glClearDepth(0);
  glEnable(GL_NORMALIZE);
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
  glEnable(GL_LIGHT0);
  glEnable(GL_MULTISAMPLE);
  glColor4f(1, 1, 1, 1);
}

/* The lit pass with the units `mode` names. */
static void light_pass(GLuint l, const char *mode) {
  static const GLfloat sp[4] = {0.196390659f, -0.0113302302f, 0.0566511452f, 0.273395419f};
  static const GLfloat tp[4] = {0, 0.200736657f, 0.0401473343f, 0.339410663f};
  static const GLfloat rp[4] = {-0.00231138477f, -0.00154092337f, 0.00770461652f, 0.969381571f};
  static const GLfloat qp[4] = {0, 0, 0, 1};
  static const GLfloat pos[4] = {-0.3f, -0.2f, 1, 0}, dif[4] = {0.6f, 0.6f, 0.6f, 1};
  int checker_on = !strcmp(mode, "both") || !strcmp(mode, "checker") || !strcmp(mode, "srgb");
  int depth_on = !strcmp(mode, "both") || !strcmp(mode, "depth") || !strcmp(mode, "srgb");
  BindFramebuffer(GL_FRAMEBUFFER, fbo_ms);
  glViewport(0, 0, W, H);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  camera();
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, dif);
  glEnable(GL_LIGHTING);
  ActiveTexture(GL_TEXTURE0);
  if (checker_on) glEnable(GL_TEXTURE_2D);
  else glDisable(GL_TEXTURE_2D);
  ActiveTexture(GL_TEXTURE1);
  if (depth_on) glEnable(GL_TEXTURE_2D);
  else glDisable(GL_TEXTURE_2D);
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glEnable(GL_TEXTURE_GEN_R);
  glEnable(GL_TEXTURE_GEN_Q);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  glTexGenfv(GL_S, GL_EYE_PLANE, sp);
  glTexGenfv(GL_T, GL_EYE_PLANE, tp);
  glTexGenfv(GL_R, GL_EYE_PLANE, rp);
  glTexGenfv(GL_Q, GL_EYE_PLANE, qp);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glCallList(l);
  glDisable(GL_BLEND);
  ActiveTexture(GL_TEXTURE0);
  glFinish();
}

/* Pixels the floor covers (single-sampled, stencil-marked). */
static long covered(GLuint l) {
  BindFramebuffer(GL_FRAMEBUFFER, fbo_resolve);
  glViewport(0, 0, W, H);
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 255);
  glStencilOp(GL_REPLACE, GL_REPLACE, GL_REPLACE);
  glDisable(GL_DEPTH_TEST);
  camera();
  glCallList(l);
  glDisable(GL_STENCIL_TEST);
  glEnable(GL_DEPTH_TEST);
  unsigned char *s = malloc((size_t)W * H);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  BindFramebuffer(GL_READ_FRAMEBUFFER, fbo_resolve);
  glReadPixels(0, 0, W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
  long n = 0;
  for (long i = 0; i < (long)W * H; i++) n += s[i] != 0;
  free(s);
  BindFramebuffer(GL_FRAMEBUFFER, fbo_ms);
  return n;
}

int main(int argc, char **argv) {
  int frames = argc > 1 ? atoi(argv[1]) : 5;
  const char *size = argc > 2 ? argv[2] : "320x240";
  const char *mode = argc > 3 ? argv[3] : "both";
  if (sscanf(size, "%dx%d", &W, &H) != 2) return 2;
  float *px = malloc((size_t)W * H * 4 * sizeof(float));
  OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  if (!c || !OSMesaMakeCurrent(c, px, GL_FLOAT, W, H)) return 1;
  load_fbo_functions();
  setup(mode);
  GLuint l = plane_list(200, 1);
  shadow_pass(l);
  long n = covered(l);
  double t[64];
  if (frames > 64) frames = 64;
  for (int i = 0; i <= frames; i++) {
    double t0 = now();
    light_pass(l, mode);
    if (i) t[i - 1] = 1000 * (now() - t0);
  }
  qsort(t, frames, sizeof t[0], cmp);
  BindFramebuffer(GL_READ_FRAMEBUFFER, fbo_ms);
  BindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_resolve);
  BlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  BindFramebuffer(GL_READ_FRAMEBUFFER, fbo_resolve);
  unsigned char *rb = malloc((size_t)W * H * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, W, H, GL_RGB, GL_UNSIGNED_BYTE, rb);
  unsigned sum = 0;
  for (size_t i = 0; i < (size_t)W * H * 3; i++) sum = sum * 31 + rb[i];
  printf("%s-%s %.3f (samples %ld, checksum %08x, error 0x%x)\n", mode, size, frames ? t[frames / 2] : 0.0, 4 * n,
         sum, glGetError());
  OSMesaDestroyContext(c);
  free(px);
  free(rb);
  return 0;
}
