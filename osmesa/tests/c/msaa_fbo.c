/* MuJoCo's multisampled offscreen path: a 4x RGBA8 + DEPTH24_STENCIL8
 * framebuffer object drawn with GL_MULTISAMPLE on (depth-tested smooth
 * triangles, a blended one, a bitmap string from glRasterPos + glBitmap),
 * resolved by glBlitFramebuffer of the colour (GL_NEAREST) and then of the
 * depth into a single-sampled object, read back as GL_RGB/GL_UNSIGNED_BYTE
 * and GL_DEPTH_COMPONENT/GL_FLOAT. The object is unbound, the window drawn,
 * and the object bound again and drawn on (its samples kept). Queries and
 * the errors of multisampled reads and blits are printed. */
#include "common.h"
#include <GL/glext.h>

static PFNGLGENFRAMEBUFFERSPROC GenFramebuffers;
static PFNGLBINDFRAMEBUFFERPROC BindFramebuffer;
static PFNGLCHECKFRAMEBUFFERSTATUSPROC CheckFramebufferStatus;
static PFNGLGENRENDERBUFFERSPROC GenRenderbuffers;
static PFNGLBINDRENDERBUFFERPROC BindRenderbuffer;
static PFNGLRENDERBUFFERSTORAGEPROC RenderbufferStorage;
static PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC RenderbufferStorageMultisample;
static PFNGLFRAMEBUFFERRENDERBUFFERPROC FramebufferRenderbuffer;
static PFNGLGETRENDERBUFFERPARAMETERIVPROC GetRenderbufferParameteriv;
static PFNGLBLITFRAMEBUFFERPROC BlitFramebuffer;

#define LOAD(var, name) do { var = (void *)OSMesaGetProcAddress(name); CHECK(var); } while (0)
#define E(call) do { call; printf("%-70s 0x%04x\n", #call, glGetError()); } while (0)

enum { W = 96, H = 64 };

static void geti(const char *name, GLenum pname) {
  GLint v = -1;
  glGetIntegerv(pname, &v);
  printf("get %-40s %d 0x%04x\n", name, v, glGetError());
}

/* An object of an RGBA8 and a DEPTH24_STENCIL8 renderbuffer of `samples`. */
static GLuint rb_fbo(int samples, GLuint rb[2]) {
  GLuint fb;
  GenFramebuffers(1, &fb);
  BindFramebuffer(GL_FRAMEBUFFER, fb);
  GenRenderbuffers(2, rb);
  BindRenderbuffer(GL_RENDERBUFFER, rb[0]);
  RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, W, H);
  BindRenderbuffer(GL_RENDERBUFFER, rb[1]);
  RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH24_STENCIL8, W, H);
  FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
  FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
  printf("status samples %d: 0x%04x 0x%04x\n", samples, CheckFramebufferStatus(GL_FRAMEBUFFER), glGetError());
  return fb;
}

static void scene(float shift) {
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0); glVertex3f(-0.9f + shift, -0.8f, 0.5f);
  glColor3f(0, 1, 0); glVertex3f(0.8f, -0.6f + shift, -0.2f);
  glColor3f(0, 0, 1); glVertex3f(-0.1f, 0.9f, 0.1f);
  glColor3f(1, 1, 0); glVertex3f(-0.5f, 0.7f - shift, -0.6f);
  glColor3f(0, 1, 1); glVertex3f(0.9f, 0.8f, 0.3f);
  glColor3f(1, 0, 1); glVertex3f(0.2f + shift, -0.9f, 0.0f);
  glEnd();
  /* Blended, depth-tested, no depth writes: MuJoCo's transparent geoms. */
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  glBegin(GL_TRIANGLES);
  glColor4f(1, 1, 1, 0.5f); glVertex3f(-0.7f, -0.3f, -0.9f);
  glColor4f(0.2f, 0.4f, 1, 0.3f); glVertex3f(0.7f, -0.1f, 0.9f);
  glColor4f(1, 0.5f, 0, 0.7f); glVertex3f(0.1f, 0.6f + shift, 0.0f);
  glEnd();
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

/* A string of 8x8 glyphs, as MuJoCo's font display lists draw text. */
static void text(float x, float y, float z) {
  static const GLubyte glyphs[3][8] = {
    {0x18, 0x3c, 0x66, 0x66, 0x7e, 0x66, 0x66, 0x00},
    {0x7c, 0x66, 0x66, 0x7c, 0x66, 0x66, 0x7c, 0x00},
    {0x3c, 0x66, 0x60, 0x60, 0x60, 0x66, 0x3c, 0x81},
  };
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glColor3f(1, 1, 1);
  glRasterPos3f(x, y, z);
  for (int i = 0; i < 7; i++)
    glBitmap(8, 8, 0, 0, 9, 0, glyphs[i % 3]);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
}

static void read_rgb(const char *name) {
  unsigned char *p = calloc((size_t)W * H * 3, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, W, H, GL_RGB, GL_UNSIGNED_BYTE, p);
  dump(name, p, (size_t)W * H * 3);
  free(p);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
}

static void read_depth(const char *name) {
  float *p = calloc((size_t)W * H, 4);
  glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_FLOAT, p);
  dump(name, p, (size_t)W * H * 4);
  free(p);
}

/* Resolves `from` into `to` as MuJoCo does (colour, then depth) and reads it. */
static void resolve(GLuint from, GLuint to, const char *rgb, const char *depth) {
  BindFramebuffer(GL_READ_FRAMEBUFFER, from);
  BindFramebuffer(GL_DRAW_FRAMEBUFFER, to);
  E(BlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_COLOR_BUFFER_BIT, GL_NEAREST));
  E(BlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_DEPTH_BUFFER_BIT, GL_NEAREST));
  BindFramebuffer(GL_READ_FRAMEBUFFER, to);
  read_rgb(rgb);
  read_depth(depth);
  printf("read %s 0x%04x\n", rgb, glGetError());
}

int main(int argc, char **argv) {
  start(argc, argv);
  static unsigned char window[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(ctx && OSMesaMakeCurrent(ctx, window, GL_UNSIGNED_BYTE, W, H));
  LOAD(GenFramebuffers, "glGenFramebuffers");
  LOAD(BindFramebuffer, "glBindFramebuffer");
  LOAD(CheckFramebufferStatus, "glCheckFramebufferStatus");
  LOAD(GenRenderbuffers, "glGenRenderbuffers");
  LOAD(BindRenderbuffer, "glBindRenderbuffer");
  LOAD(RenderbufferStorage, "glRenderbufferStorage");
  LOAD(RenderbufferStorageMultisample, "glRenderbufferStorageMultisample");
  LOAD(FramebufferRenderbuffer, "glFramebufferRenderbuffer");
  LOAD(GetRenderbufferParameteriv, "glGetRenderbufferParameteriv");
  LOAD(BlitFramebuffer, "glBlitFramebuffer");

  geti("MAX_SAMPLES", GL_MAX_SAMPLES);
  geti("window SAMPLES", GL_SAMPLES);
  geti("window SAMPLE_BUFFERS", GL_SAMPLE_BUFFERS);

  /* The samples a renderbuffer gets for each count asked. */
  {
    GLuint r;
    GenRenderbuffers(1, &r);
    BindRenderbuffer(GL_RENDERBUFFER, r);
    for (int s = 0; s <= 5; s++) {
      GLint v = -1;
      RenderbufferStorageMultisample(GL_RENDERBUFFER, s, GL_RGBA8, 4, 4);
      GLenum e = glGetError();
      GetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &v);
      printf("renderbuffer samples asked %d: 0x%04x %d\n", s, e, v);
    }
  }

  GLuint ms_rb[2], ss_rb[2];
  GLuint ss = rb_fbo(0, ss_rb);
  GLuint ms = rb_fbo(4, ms_rb);
  geti("fbo SAMPLES", GL_SAMPLES);
  geti("fbo SAMPLE_BUFFERS", GL_SAMPLE_BUFFERS);
  geti("fbo DEPTH_BITS", GL_DEPTH_BITS);

  glViewport(0, 0, W, H);
  glEnable(GL_MULTISAMPLE);
  glClearColor(0.1f, 0.2f, 0.3f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  scene(0);
  text(-0.8f, -0.2f, -0.5f);
  text(-0.9f, 0.5f, 0.95f); /* behind the triangles: depth-tested away there */

  /* Reads and copies from a multisampled object: INVALID_OPERATION. */
  BindFramebuffer(GL_READ_FRAMEBUFFER, ms);
  {
    unsigned char p[4];
    E(glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p));
    E(glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, p));
    GLuint t;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    E(glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 0, 0, 4, 4, 0));
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    E(glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 4, 4));
    glDeleteTextures(1, &t);
  }
  /* Multisample blit errors (nothing drawn): scaled, into the same object. */
  BindFramebuffer(GL_DRAW_FRAMEBUFFER, ss);
  E(BlitFramebuffer(0, 0, W, H, 0, 0, W / 2, H, GL_COLOR_BUFFER_BIT, GL_NEAREST));
  E(BlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_COLOR_BUFFER_BIT, GL_LINEAR));
  E(BlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_DEPTH_BUFFER_BIT, GL_LINEAR));
  BindFramebuffer(GL_DRAW_FRAMEBUFFER, ms);

  resolve(ms, ss, "msaa.1.rgb", "msaa.1.depth");
  {
    unsigned char s[W * H];
    glReadPixels(0, 0, W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
    printf("stencil read 0x%04x\n", glGetError());
  }

  /* The window drawn between two frames of the object. */
  BindFramebuffer(GL_FRAMEBUFFER, 0);
  geti("window again SAMPLES", GL_SAMPLES);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  scene(0.1f);
  glFinish();
  dump("msaa.window", window, sizeof window);

  /* Stencil-tested drawing into the object, after binding it again. */
  BindFramebuffer(GL_FRAMEBUFFER, ms);
  geti("fbo again SAMPLES", GL_SAMPLES);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  scene(0.25f);
  glStencilFunc(GL_EQUAL, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glDisable(GL_DEPTH_TEST);
  glBegin(GL_TRIANGLES);
  glColor3f(0.5f, 0.5f, 0.5f);
  glVertex2f(-1, -1); glVertex2f(1, -1); glVertex2f(0, 1);
  glEnd();
  glDisable(GL_STENCIL_TEST);
  text(-0.3f, -0.7f, 0.0f);
  resolve(ms, ss, "msaa.2.rgb", "msaa.2.depth");

  /* A resolve into the window, and GL_MULTISAMPLE off. */
  BindFramebuffer(GL_FRAMEBUFFER, ms);
  glDisable(GL_MULTISAMPLE);
  glEnable(GL_DEPTH_TEST);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  scene(-0.2f);
  BindFramebuffer(GL_READ_FRAMEBUFFER, ms);
  BindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  E(BlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_COLOR_BUFFER_BIT, GL_NEAREST));
  BindFramebuffer(GL_FRAMEBUFFER, 0);
  read_rgb("msaa.3.rgb");
  /* The same frame single-sampled: the reference for GL_MULTISAMPLE off. */
  BindFramebuffer(GL_FRAMEBUFFER, ss);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  scene(-0.2f);
  read_rgb("msaa.3.single.rgb");
  printf("final error 0x%04x\n", glGetError());
  printf("done\n");
  OSMesaDestroyContext(ctx);
  return 0;
}
