/* GL's colour renderbuffer formats in a GL 1.5-style program (an RGBA8
 * OSMesa context), each with a DEPTH24_STENCIL8 renderbuffer: sizes,
 * completeness, GL_*_BITS and the attachment's component type while bound
 * ("<fmt> ..." lines), then a scene read back as GL_FLOAT, GL_UNSIGNED_SHORT
 * and GL_UNSIGNED_BYTE (fmt.<fmt>.f/.us/.ub). Then clears past [0, 1]
 * (glClearColor is not clamped: "clear ..." lines with the bits read and
 * GL_COLOR_CLEAR_VALUE), half-float edges (denormals, overflow, truncation:
 * "half ..." lines), RGB formats' alpha through DST_ALPHA blending, blits
 * into and out of half and RGB formats (blit.<n>.f), and
 * GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE on each attachment point
 * ("type ..." lines). */
#define GL_GLEXT_PROTOTYPES
#include "common.h"
#include <GL/glext.h>
#include "fbo_object.h"
#include <math.h>

#define W 32
#define H 24

static void scene(void) {
  glViewport(0, 0, W, H);
  glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.5, 1.5, -1.1, 1.1, -5, 5);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glBegin(GL_TRIANGLES);
  glColor4f(1.0f, 0.1f, 0.2f, 1.0f);
  glVertex2f(-1.4f, -1.0f);
  glColor4f(0.0f, 0.9f, 0.3f, 0.6f);
  glVertex2f(0.3f, -0.9f);
  glColor4f(0.3f, 0.2f, 1.0f, 0.8f);
  glVertex2f(-0.5f, 0.9f);
  glEnd();
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glBegin(GL_QUADS);
  glColor4f(0.9f, 0.9f, 0.1f, 0.37f);
  glVertex2f(-1.2f, 0.2f);
  glVertex2f(0.2f, 0.2f);
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
  /* Destination alpha: 1 where the format stores none. */
  glBlendFunc(GL_ONE_MINUS_DST_ALPHA, GL_DST_ALPHA);
  glBegin(GL_TRIANGLES);
  glColor4f(0.5f, 0.25f, 0.75f, 0.5f);
  glVertex2f(0.5f, -1.0f);
  glVertex2f(1.5f, -1.0f);
  glVertex2f(1.0f, 0.0f);
  glEnd();
  glDisable(GL_BLEND);
}

/* An object of a colour renderbuffer of `format` and a DEPTH24_STENCIL8 one. */
static GLuint object(GLenum format, GLuint rbs[2]) { return colour_depth_object(format, 0, W, H, rbs); }

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

/* Pixel (x, y)'s channels as float bits. */
static void print_px(const char *what, int x, int y) {
  float p[4];
  unsigned u[4];
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_FLOAT, p);
  memcpy(u, p, sizeof u);
  printf("%s %08x %08x %08x %08x error 0x%x\n", what, u[0], u[1], u[2], u[3], glGetError());
}

static void print_type(const char *what, GLenum attachment) {
  GLint t = -1;
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &t);
  printf("type %s 0x%x error 0x%x\n", what, t, glGetError());
}

static const struct { GLenum format; const char *name; } formats[] = {
  {GL_RGBA2, "rgba2"}, {GL_RGBA4, "rgba4"}, {GL_RGB5_A1, "rgb5_a1"}, {GL_R3_G3_B2, "r3_g3_b2"},
  {GL_RGB4, "rgb4"}, {GL_RGB5, "rgb5"}, {GL_RGB565, "rgb565"}, {GL_RGB10, "rgb10"},
  {GL_RGB10_A2, "rgb10_a2"}, {GL_RGB12, "rgb12"}, {GL_RGBA12, "rgba12"}, {GL_RGB16, "rgb16"},
  {GL_RGBA16, "rgba16"}, {GL_RGB16F, "rgb16f"}, {GL_RGBA16F, "rgba16f"}, {GL_RGB32F, "rgb32f"},
  {GL_RGBA32F, "rgba32f"}, {GL_RGB8, "rgb8"}, {GL_RGBA8, "rgba8"},
};
#define N_FORMATS ((int)(sizeof formats / sizeof formats[0]))

static int index_of(const char *name) {
  for (int i = 0; i < N_FORMATS; i++)
    if (!strcmp(formats[i].name, name)) return i;
  return -1;
}

int main(int argc, char **argv) {
  start(argc, argv);
  static unsigned char window[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(ctx);
  CHECK(OSMesaMakeCurrent(ctx, window, GL_UNSIGNED_BYTE, W, H));
  glDisable(GL_DITHER);
  GLuint fbos[N_FORMATS], rbs[N_FORMATS][2];
  for (int i = 0; i < N_FORMATS; i++) {
    const char *n = formats[i].name;
    fbos[i] = object(formats[i].format, rbs[i]);
    GLint s[5];
    glBindRenderbuffer(GL_RENDERBUFFER, rbs[i][0]);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_RED_SIZE, &s[0]);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_GREEN_SIZE, &s[1]);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_BLUE_SIZE, &s[2]);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_ALPHA_SIZE, &s[3]);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_INTERNAL_FORMAT, &s[4]);
    printf("%s sizes %d %d %d %d internal 0x%x error 0x%x\n", n, s[0], s[1], s[2], s[3], s[4], glGetError());
    GLint a[4];
    for (int c = 0; c < 4; c++)
      glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                            GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE + c, &a[c]);
    printf("%s attachment sizes %d %d %d %d error 0x%x\n", n, a[0], a[1], a[2], a[3], glGetError());
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    printf("%s status 0x%x\n", n, status);
    if (status != GL_FRAMEBUFFER_COMPLETE) continue;
    GLint bits[4];
    glGetIntegerv(GL_RED_BITS, &bits[0]);
    glGetIntegerv(GL_GREEN_BITS, &bits[1]);
    glGetIntegerv(GL_BLUE_BITS, &bits[2]);
    glGetIntegerv(GL_ALPHA_BITS, &bits[3]);
    printf("%s bits %d %d %d %d\n", n, bits[0], bits[1], bits[2], bits[3]);
    char what[64];
    snprintf(what, sizeof what, "%s color", n);
    print_type(what, GL_COLOR_ATTACHMENT0);
    scene();
    printf("%s error 0x%x\n", n, glGetError());
    char file[64];
    snprintf(file, sizeof file, "fmt.%s", n);
    read_all(file);
  }

  /* Clears past [0, 1]: stored as given in float objects, clamped in unorm ones. */
  const char *cleared[] = {"rgba32f", "rgb32f", "rgba16f", "rgb16f", "rgba16", "rgb16", "rgba8"};
  for (int k = 0; k < 7; k++) {
    int i = index_of(cleared[k]);
    glBindFramebuffer(GL_FRAMEBUFFER, fbos[i]);
    glClearColor(2.5f, -1.0f, 70000.0f, 0.3f);
    glClear(GL_COLOR_BUFFER_BIT);
    float cv[4];
    glGetFloatv(GL_COLOR_CLEAR_VALUE, cv);
    printf("clear %s value %g %g %g %g\n", cleared[k], cv[0], cv[1], cv[2], cv[3]);
    char what[64];
    snprintf(what, sizeof what, "clear %s", cleared[k]);
    print_px(what, 3, 3);
    /* A scissored clear through a colour mask. */
    glEnable(GL_SCISSOR_TEST);
    glScissor(2, 2, 4, 4);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
    glClearColor(-0.5f, 9.0f, 1.0e-6f, 3.5f);
    glClear(GL_COLOR_BUFFER_BIT);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_SCISSOR_TEST);
    snprintf(what, sizeof what, "scissored clear %s", cleared[k]);
    print_px(what, 3, 3);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  float cv[4];
  glGetFloatv(GL_COLOR_CLEAR_VALUE, cv);
  printf("clear window value %g %g %g %g\n", cv[0], cv[1], cv[2], cv[3]);

  /* Half floats' edges: clears and additive blends onto them. */
  {
    const float clears[][4] = {
      {65519.0f, 3.0e-6f, -2.0e-8f, 100000.0f},
      {1000.0f, 0.001f, 3.0e-5f, 0.5f},
      {-65504.0f, 6.1e-5f, 5.9e-8f, -1.0e-7f},
      {INFINITY, -INFINITY, 0.3f, 0.6f},
    };
    const float colours[][4] = {
      {0.3f, 0.7f, 3.0e-6f, 0.9f},
      {1.0f, 0.0f, 1.0e-6f, 0.001f},
    };
    for (int k = 0; k < 2; k++) {
      int i = index_of(k ? "rgb16f" : "rgba16f");
      glBindFramebuffer(GL_FRAMEBUFFER, fbos[i]);
      for (int c = 0; c < 4; c++) {
        glClearColor(clears[c][0], clears[c][1], clears[c][2], clears[c][3]);
        glClear(GL_COLOR_BUFFER_BIT);
        char what[64];
        snprintf(what, sizeof what, "half %s clear %d", formats[i].name, c);
        print_px(what, 0, 0);
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ONE);
        for (int j = 0; j < 2; j++) {
          glColor4fv(colours[j]);
          glRectf(-2, -2, 2, 2);
          snprintf(what, sizeof what, "half %s clear %d plus %d", formats[i].name, c, j);
          print_px(what, 0, 0);
        }
        glDisable(GL_BLEND);
      }
    }
  }

  /* Blits into and out of the half and RGB formats (1:1 NEAREST). */
  {
    const struct { const char *from, *to; } blits[] = {
      {"rgba32f", "rgba16f"}, {"rgba16f", "rgba32f"}, {"rgb32f", "rgba32f"}, {"rgba8", "rgb16"},
      {"rgb16", "rgba16"}, {"rgba32f", "rgb16f"}, {"rgba16f", "rgba8"}, {"rgba12", "rgba8"},
    };
    for (int k = 0; k < 8; k++) {
      int from = index_of(blits[k].from), to = index_of(blits[k].to);
      glBindFramebuffer(GL_FRAMEBUFFER, fbos[from]);
      scene();
      glBindFramebuffer(GL_FRAMEBUFFER, fbos[to]);
      glClearColor(0, 0, 0, 0);
      glClear(GL_COLOR_BUFFER_BIT);
      glBindFramebuffer(GL_READ_FRAMEBUFFER, fbos[from]);
      glBlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_COLOR_BUFFER_BIT, GL_NEAREST);
      printf("blit %d error 0x%x\n", k, glGetError());
      glBindFramebuffer(GL_READ_FRAMEBUFFER, fbos[to]);
      char name[32];
      snprintf(name, sizeof name, "blit.%d", k);
      read_all(name);
    }
  }

  /* COMPONENT_TYPE of each attachment point. */
  {
    glBindFramebuffer(GL_FRAMEBUFFER, fbos[index_of("rgba16f")]);
    print_type("d24s8 depth", GL_DEPTH_ATTACHMENT);
    print_type("d24s8 stencil", GL_STENCIL_ATTACHMENT);
    print_type("d24s8 depth_stencil", GL_DEPTH_STENCIL_ATTACHMENT);
    print_type("unused color1", GL_COLOR_ATTACHMENT1);
    GLuint rb;
    glGenRenderbuffers(1, &rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH32F_STENCIL8, W, H);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb);
    print_type("d32fs8 depth", GL_DEPTH_ATTACHMENT);
    print_type("d32fs8 stencil", GL_STENCIL_ATTACHMENT);
    print_type("d32fs8 depth_stencil", GL_DEPTH_STENCIL_ATTACHMENT);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, 0);
    print_type("d32f alone depth_stencil", GL_DEPTH_STENCIL_ATTACHMENT);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, 0);
    print_type("none depth_stencil", GL_DEPTH_STENCIL_ATTACHMENT);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  printf("done\n");
  return 0;
}
