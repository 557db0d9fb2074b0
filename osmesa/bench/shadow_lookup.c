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

static GLuint fbo_ms, fbo_resolve, fbo_shadow, shadow_tex, checker_tex;
static int W, H;

static GLuint renderbuffer(int samples, GLenum format) {
  GLuint rb;
  GenRenderbuffers(1, &rb);
  BindRenderbuffer(GL_RENDERBUFFER, rb);
  RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, W, H);
  return rb;
}

static void checker(GLint internal) {
  static unsigned char t[256 * 256 * 3];
  for (int y = 0; y < 256; y++)
    for (int x = 0; x < 256; x++) {
      int on = ((x / 128) ^ (y / 128)) & 1, edge = x == 0 || y == 0;
      unsigned char *p = t + (y * 256 + x) * 3;
      p[0] = edge ? 204 : on ? 51 : 26;
      p[1] = edge ? 204 : on ? 77 : 38;
      p[2] = edge ? 204 : on ? 102 : 51;
    }
  glGenTextures(1, &checker_tex);
  glBindTexture(GL_TEXTURE_2D, checker_tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  gluBuild2DMipmaps(GL_TEXTURE_2D, internal, 256, 256, GL_RGB, GL_UNSIGNED_BYTE, t);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
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

static const GLfloat light[16] = {0.959350884f, 0, -0.282216281f, 0, -0.055347167f, 0.980580747f, -0.188144207f, 0,
                                  0.276735812f, 0.196116149f, 0.940720975f, 0, -1.10694325f, -0.784464598f,
                                  -3.7628839f, 1};

/* The shadow map: the floor and a box-like caster from the light. */
static void shadow_pass(GLuint l) {
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
  ActiveTexture(GL_TEXTURE0);
  checker(strcmp(mode, "srgb") ? GL_RGB : GL_SRGB8);
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
