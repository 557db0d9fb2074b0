/* Framebuffer objects as MuJoCo uses them, and more: RGBA8 + DEPTH24_STENCIL8
 * renderbuffers, reverse Z, a resolve blit, RGB/UNSIGNED_BYTE and
 * DEPTH_COMPONENT/FLOAT readbacks with pack alignment 1; a depth texture
 * rendered from a light and sampled with compare; render to texture then
 * sampling and glGenerateMipmap; scaled, flipped, LINEAR and scissored
 * blits; 1x1 objects; completeness, queries and errors. Every function is
 * loaded through OSMesaGetProcAddress, as MuJoCo does. Images are written
 * to files, state and errors printed one per line. */
#include "common.h"
#include <GL/glext.h>

static PFNGLGENFRAMEBUFFERSPROC GenFramebuffers;
static PFNGLDELETEFRAMEBUFFERSPROC DeleteFramebuffers;
static PFNGLBINDFRAMEBUFFERPROC BindFramebuffer;
static PFNGLISFRAMEBUFFERPROC IsFramebuffer;
static PFNGLCHECKFRAMEBUFFERSTATUSPROC CheckFramebufferStatus;
static PFNGLGENRENDERBUFFERSPROC GenRenderbuffers;
static PFNGLDELETERENDERBUFFERSPROC DeleteRenderbuffers;
static PFNGLBINDRENDERBUFFERPROC BindRenderbuffer;
static PFNGLISRENDERBUFFERPROC IsRenderbuffer;
static PFNGLRENDERBUFFERSTORAGEPROC RenderbufferStorage;
static PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC RenderbufferStorageMultisample;
static PFNGLFRAMEBUFFERRENDERBUFFERPROC FramebufferRenderbuffer;
static PFNGLFRAMEBUFFERTEXTURE2DPROC FramebufferTexture2D;
static PFNGLFRAMEBUFFERTEXTURE3DPROC FramebufferTexture3D;
static PFNGLFRAMEBUFFERTEXTURELAYERPROC FramebufferTextureLayer;
static PFNGLGETFRAMEBUFFERATTACHMENTPARAMETERIVPROC GetFramebufferAttachmentParameteriv;
static PFNGLGETRENDERBUFFERPARAMETERIVPROC GetRenderbufferParameteriv;
static PFNGLBLITFRAMEBUFFERPROC BlitFramebuffer;
static PFNGLGENERATEMIPMAPPROC GenerateMipmap;
static PFNGLBINDFRAMEBUFFEREXTPROC BindFramebufferEXT;
static PFNGLBLITFRAMEBUFFEREXTPROC BlitFramebufferEXT;

#define LOAD(var, name) do { var = (void *)OSMesaGetProcAddress(name); CHECK(var); } while (0)
#define E(call) do { call; printf("%-70s 0x%04x\n", #call, glGetError()); } while (0)

static const char *status_name(GLenum s) {
  switch (s) {
  case GL_FRAMEBUFFER_COMPLETE: return "COMPLETE";
  case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "INCOMPLETE_ATTACHMENT";
  case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT: return "MISSING_ATTACHMENT";
  case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER: return "INCOMPLETE_DRAW_BUFFER";
  case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER: return "INCOMPLETE_READ_BUFFER";
  case GL_FRAMEBUFFER_UNSUPPORTED: return "UNSUPPORTED";
  case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: return "INCOMPLETE_MULTISAMPLE";
  case 0: return "0";
  default: return "other";
  }
}

static void status(const char *what) {
  GLenum s = CheckFramebufferStatus(GL_FRAMEBUFFER);
  printf("status %-40s %s 0x%04x\n", what, status_name(s), glGetError());
}

static void geti(const char *name, GLenum pname) {
  GLint v = -1;
  glGetIntegerv(pname, &v);
  printf("get %-40s %d 0x%04x\n", name, v, glGetError());
}

/* An FBO of an RGBA8 and a DEPTH24_STENCIL8 renderbuffer, w x h, bound. */
static GLuint rb_fbo(int w, int h, GLuint rb[2]) {
  GLuint fb;
  GenFramebuffers(1, &fb);
  BindFramebuffer(GL_FRAMEBUFFER, fb);
  GenRenderbuffers(2, rb);
  BindRenderbuffer(GL_RENDERBUFFER, rb[0]);
  RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, w, h);
  BindRenderbuffer(GL_RENDERBUFFER, rb[1]);
  RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, w, h);
  FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
  FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
  FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
  return fb;
}

/* A lit-looking scene: overlapping smooth triangles at several depths. */
static void scene(void) {
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0); glVertex3f(-0.9f, -0.8f, 0.5f);
  glColor3f(0, 1, 0); glVertex3f(0.8f, -0.6f, -0.2f);
  glColor3f(0, 0, 1); glVertex3f(-0.1f, 0.9f, 0.1f);
  glColor3f(1, 1, 0); glVertex3f(-0.5f, 0.7f, -0.6f);
  glColor3f(0, 1, 1); glVertex3f(0.9f, 0.8f, 0.3f);
  glColor3f(1, 0, 1); glVertex3f(0.2f, -0.9f, 0.0f);
  glEnd();
}

static void read_rgb(const char *name, int w, int h) {
  unsigned char *p = calloc((size_t)w * h * 3, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, p);
  dump(name, p, (size_t)w * h * 3);
  free(p);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
}

static void read_rgba(const char *name, int w, int h) {
  unsigned char *p = calloc((size_t)w * h * 4, 1);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, p);
  dump(name, p, (size_t)w * h * 4);
  free(p);
}

static void read_depth(const char *name, int w, int h) {
  float *p = calloc((size_t)w * h, 4);
  glReadPixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, p);
  dump(name, p, (size_t)w * h * 4);
  free(p);
}

enum { W = 96, H = 64 };

int main(int argc, char **argv) {
  start(argc, argv);
  static unsigned char window[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(ctx && OSMesaMakeCurrent(ctx, window, GL_UNSIGNED_BYTE, W, H));
  LOAD(GenFramebuffers, "glGenFramebuffers");
  LOAD(DeleteFramebuffers, "glDeleteFramebuffers");
  LOAD(BindFramebuffer, "glBindFramebuffer");
  LOAD(IsFramebuffer, "glIsFramebuffer");
  LOAD(CheckFramebufferStatus, "glCheckFramebufferStatus");
  LOAD(GenRenderbuffers, "glGenRenderbuffers");
  LOAD(DeleteRenderbuffers, "glDeleteRenderbuffers");
  LOAD(BindRenderbuffer, "glBindRenderbuffer");
  LOAD(IsRenderbuffer, "glIsRenderbuffer");
  LOAD(RenderbufferStorage, "glRenderbufferStorage");
  LOAD(RenderbufferStorageMultisample, "glRenderbufferStorageMultisample");
  LOAD(FramebufferRenderbuffer, "glFramebufferRenderbuffer");
  LOAD(FramebufferTexture2D, "glFramebufferTexture2D");
  LOAD(FramebufferTexture3D, "glFramebufferTexture3D");
  LOAD(FramebufferTextureLayer, "glFramebufferTextureLayer");
  LOAD(GetFramebufferAttachmentParameteriv, "glGetFramebufferAttachmentParameteriv");
  LOAD(GetRenderbufferParameteriv, "glGetRenderbufferParameteriv");
  LOAD(BlitFramebuffer, "glBlitFramebuffer");
  LOAD(GenerateMipmap, "glGenerateMipmap");
  LOAD(BindFramebufferEXT, "glBindFramebufferEXT");
  LOAD(BlitFramebufferEXT, "glBlitFramebufferEXT");

  geti("MAX_RENDERBUFFER_SIZE", GL_MAX_RENDERBUFFER_SIZE);
  geti("MAX_COLOR_ATTACHMENTS", GL_MAX_COLOR_ATTACHMENTS);
  geti("MAX_SAMPLES", GL_MAX_SAMPLES);
  geti("FRAMEBUFFER_BINDING", GL_FRAMEBUFFER_BINDING);
  status("window");

  /* 1. MuJoCo's path: render into RGBA8 + D24S8 with reverse Z, resolve
   * into a second object by a blit, read back RGB bytes and float depth. */
  GLuint rb[2], rb2[2];
  GLuint a = rb_fbo(W, H, rb);
  status("rgba8 + d24s8");
  geti("RED_BITS", GL_RED_BITS);
  geti("ALPHA_BITS", GL_ALPHA_BITS);
  geti("DEPTH_BITS", GL_DEPTH_BITS);
  geti("STENCIL_BITS", GL_STENCIL_BITS);
  geti("DRAW_BUFFER", GL_DRAW_BUFFER);
  geti("READ_BUFFER", GL_READ_BUFFER);
  geti("DOUBLEBUFFER", GL_DOUBLEBUFFER);
  geti("STEREO", GL_STEREO);
  geti("RENDERBUFFER_BINDING", GL_RENDERBUFFER_BINDING);
  glViewport(0, 0, W, H);
  glClearColor(0.1f, 0.2f, 0.3f, 1.0f);
  glClearDepth(0.0);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GEQUAL);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  scene();
  glDisable(GL_STENCIL_TEST);
  GLuint b = rb_fbo(W, H, rb2);
  BindFramebuffer(GL_READ_FRAMEBUFFER, a);
  BindFramebuffer(GL_DRAW_FRAMEBUFFER, b);
  geti("READ_FRAMEBUFFER_BINDING", GL_READ_FRAMEBUFFER_BINDING);
  geti("DRAW_FRAMEBUFFER_BINDING", GL_DRAW_FRAMEBUFFER_BINDING);
  E(BlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT, GL_NEAREST));
  BindFramebuffer(GL_READ_FRAMEBUFFER, b);
  read_rgb("fbo.resolve.rgb", W, H);
  read_depth("fbo.resolve.depth", W, H);
  {
    unsigned char s[W * H];
    glReadPixels(0, 0, W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
    dump("fbo.resolve.stencil", s, sizeof s);
  }
  printf("resolve read 0x%04x\n", glGetError());
  /* The window was not touched. */
  BindFramebuffer(GL_FRAMEBUFFER, 0);
  glFinish();
  printf("window untouched %d\n", window[0] == 0 && window[W * H * 4 - 1] == 0);

  /* 2. Blits from object a into an object c of 2W x 2H: scaled, flipped,
   * LINEAR, scissored, and EXT's name. */
  GLuint c_rb[2];
  GLuint c = rb_fbo(2 * W, 2 * H, c_rb);
  glViewport(0, 0, 2 * W, 2 * H);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  BindFramebuffer(GL_READ_FRAMEBUFFER, a);
  E(BlitFramebuffer(0, 0, W, H, 0, 0, W + 37, H + 21, GL_COLOR_BUFFER_BIT, GL_NEAREST));
  E(BlitFramebuffer(0, 0, W, H, 2 * W, 2 * H, W, H, GL_COLOR_BUFFER_BIT, GL_NEAREST));
  E(BlitFramebuffer(W, 0, 0, H, W, H, 2 * W, 0, GL_COLOR_BUFFER_BIT, GL_NEAREST));
  BindFramebuffer(GL_READ_FRAMEBUFFER, c);
  read_rgba("fbo.blit.nearest", 2 * W, 2 * H);
  BindFramebuffer(GL_FRAMEBUFFER, c);
  glClear(GL_COLOR_BUFFER_BIT);
  BindFramebuffer(GL_READ_FRAMEBUFFER, a);
  E(BlitFramebuffer(0, 0, W, H, 0, 0, 2 * W, 2 * H, GL_COLOR_BUFFER_BIT, GL_LINEAR));
  BindFramebuffer(GL_READ_FRAMEBUFFER, c);
  read_rgba("fbo.blit.linear_up", 2 * W, 2 * H);
  glClear(GL_COLOR_BUFFER_BIT);
  BindFramebuffer(GL_READ_FRAMEBUFFER, a);
  E(BlitFramebuffer(0, 0, W, H, 0, 0, W / 2 + 5, H / 2 + 3, GL_COLOR_BUFFER_BIT, GL_LINEAR));
  glEnable(GL_SCISSOR_TEST);
  glScissor(W, H / 2, W / 2, H);
  E(BlitFramebufferEXT(0, 0, W, H, W, 0, 2 * W, 2 * H, GL_COLOR_BUFFER_BIT, GL_NEAREST));
  glDisable(GL_SCISSOR_TEST);
  BindFramebuffer(GL_READ_FRAMEBUFFER, c);
  read_rgba("fbo.blit.linear_down", 2 * W, 2 * H);
  /* Depth blit, scaled: c's depth from a's. */
  BindFramebuffer(GL_READ_FRAMEBUFFER, a);
  E(BlitFramebuffer(0, 0, W, H, 0, 0, 2 * W, 2 * H, GL_DEPTH_BUFFER_BIT, GL_NEAREST));
  BindFramebuffer(GL_READ_FRAMEBUFFER, c);
  read_depth("fbo.blit.depth", 2 * W, 2 * H);

  /* 3. A depth texture rendered from a light, sampled with compare. */
  enum { S = 512 };
  GLuint shadow_tex, shadow_fb;
  glGenTextures(1, &shadow_tex);
  glBindTexture(GL_TEXTURE_2D, shadow_tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, S, S, 0, GL_DEPTH_COMPONENT, GL_FLOAT, NULL);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  GenFramebuffers(1, &shadow_fb);
  BindFramebuffer(GL_FRAMEBUFFER, shadow_fb);
  FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, shadow_tex, 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  status("depth texture, no colour");
  geti("DRAW_BUFFER none", GL_DRAW_BUFFER);
  geti("RED_BITS none", GL_RED_BITS);
  geti("DEPTH_BITS texture", GL_DEPTH_BITS);
  glViewport(0, 0, S, S);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glDepthFunc(GL_LESS);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(2.0f, 4.0f);
  scene();
  glDisable(GL_POLYGON_OFFSET_FILL);
  read_depth("fbo.shadow.depth", S, S);
  printf("shadow depth read 0x%04x\n", glGetError());
  BindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, W, H);
  glClearColor(0.5f, 0.5f, 0.5f, 1);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_DEPTH_TEST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glEnable(GL_TEXTURE_2D);
  glColor3f(1, 1, 1);
  glBegin(GL_QUADS);
  glTexCoord3f(0, 0, 0.45f); glVertex2f(-1, -1);
  glTexCoord3f(1, 0, 0.45f); glVertex2f(0, -1);
  glTexCoord3f(1, 1, 0.55f); glVertex2f(0, 1);
  glTexCoord3f(0, 1, 0.55f); glVertex2f(-1, 1);
  glEnd();
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0); glVertex2f(0, -1);
  glTexCoord2f(1, 0); glVertex2f(1, -1);
  glTexCoord2f(1, 1); glVertex2f(1, 1);
  glTexCoord2f(0, 1); glVertex2f(0, 1);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  read_rgba("fbo.shadow.sampled", W, H);

  /* 4. Render to an RGBA8 texture, sample it, mipmap it. */
  GLuint tex, tfb;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  GenFramebuffers(1, &tfb);
  BindFramebuffer(GL_FRAMEBUFFER, tfb);
  FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  status("rgba8 texture");
  {
    GLint v[6];
    GetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &v[0]);
    GetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &v[1]);
    GetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, &v[2]);
    GetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE, &v[3]);
    GetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &v[4]);
    GetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING, &v[5]);
    printf("texture attachment 0x%x %d %d %d 0x%x 0x%x 0x%04x\n", v[0], v[1] == (GLint)tex, v[2], v[3], v[4], v[5], glGetError());
  }
  glViewport(0, 0, 64, 64);
  glClearColor(0, 0, 0.5f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  scene();
  BindFramebuffer(GL_FRAMEBUFFER, 0);
  GenerateMipmap(GL_TEXTURE_2D);
  printf("mipmap 0x%04x\n", glGetError());
  glViewport(0, 0, W, H);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0); glVertex2f(-1, -1);
  glTexCoord2f(1, 0); glVertex2f(0.2f, -1);
  glTexCoord2f(1, 1); glVertex2f(0.2f, 1);
  glTexCoord2f(0, 1); glVertex2f(-1, 1);
  glEnd();
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0); glVertex2f(0.3f, -0.5f);
  glTexCoord2f(1, 0); glVertex2f(0.8f, -0.5f);
  glTexCoord2f(1, 1); glVertex2f(0.8f, 0.2f);
  glTexCoord2f(0, 1); glVertex2f(0.3f, 0.2f);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  read_rgba("fbo.rtt", W, H);

  /* 5. 1x1 objects. */
  GLuint one_rb[2];
  rb_fbo(1, 1, one_rb);
  status("1x1");
  glViewport(0, 0, 1, 1);
  glClearColor(0.25f, 0.5f, 0.75f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  scene();
  {
    unsigned char p[4];
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
    printf("1x1 %d %d %d %d 0x%04x\n", p[0], p[1], p[2], p[3], glGetError());
  }

  /* 6. Completeness, queries and errors. */
  GLuint f, r[4];
  GenFramebuffers(1, &f);
  GenRenderbuffers(4, r);
  printf("is before bind %d %d\n", IsFramebuffer(f), IsRenderbuffer(r[0]));
  BindFramebuffer(GL_FRAMEBUFFER, f);
  BindRenderbuffer(GL_RENDERBUFFER, r[0]);
  printf("is after bind %d %d\n", IsFramebuffer(f), IsRenderbuffer(r[0]));
  status("empty");
  E(glClear(GL_COLOR_BUFFER_BIT));
  {
    unsigned char p[4];
    E(glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p));
  }
  E(glBegin(GL_TRIANGLES); glVertex2f(0, 0); glVertex2f(1, 0); glVertex2f(0, 1); glEnd());
  FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, r[0]);
  status("renderbuffer without storage");
  E(RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, -1, 4));
  E(RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 16385, 4));
  E(RenderbufferStorage(GL_RENDERBUFFER, 0x1234, 4, 4));
  E(RenderbufferStorage(GL_TEXTURE_2D, GL_RGBA8, 4, 4));
  E(RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 8, 4));
  status("rgba8 8x4");
  E(RenderbufferStorageMultisample(GL_RENDERBUFFER, 5, GL_RGBA8, 8, 4));
  E(RenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_RGBA8, 8, 4));
  {
    GLint v[10];
    GetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_WIDTH, &v[0]);
    GetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_HEIGHT, &v[1]);
    GetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_INTERNAL_FORMAT, &v[2]);
    GetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &v[3]);
    GetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_RED_SIZE, &v[4]);
    GetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_ALPHA_SIZE, &v[5]);
    GetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_DEPTH_SIZE, &v[6]);
    printf("renderbuffer params %d %d 0x%x %d %d %d %d 0x%04x\n", v[0], v[1], v[2], v[3], v[4], v[5], v[6], glGetError());
  }
  E(GetRenderbufferParameteriv(GL_RENDERBUFFER, 0x1234, NULL));
  BindRenderbuffer(GL_RENDERBUFFER, r[1]);
  E(RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT16, 8, 4));
  FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, r[1]);
  status("samples 4 and 0 mixed");
  BindRenderbuffer(GL_RENDERBUFFER, r[0]);
  RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 8, 4);
  status("rgba8 + depth16");
  {
    GLint v[3];
    GetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &v[0]);
    GetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &v[1]);
    GetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &v[2]);
    printf("depth attachment %d 0x%x 0x%x 0x%04x\n", v[0], v[1], v[2], glGetError());
  }
  {
    GLint v = -7;
    E(GetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE, &v));
    E(GetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + 9, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &v));
    E(GetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, 0x1234, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &v));
  }
  BindRenderbuffer(GL_RENDERBUFFER, r[2]);
  RenderbufferStorage(GL_RENDERBUFFER, GL_STENCIL_INDEX8, 8, 4);
  FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, r[2]);
  status("separate depth and stencil");
  FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, 0);
  FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, r[0]);
  status("colour renderbuffer as depth");
  FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, r[1]);
  E(glDrawBuffer(GL_COLOR_ATTACHMENT0 + 1));
  status("draw buffer 1 empty");
  E(glDrawBuffer(GL_BACK));
  E(glDrawBuffer(GL_COLOR_ATTACHMENT0 + 9));
  E(glDrawBuffer(GL_COLOR_ATTACHMENT0));
  E(glReadBuffer(GL_FRONT));
  E(FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, 999));
  E(FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, r[0]));
  E(FramebufferRenderbuffer(0x1234, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, r[0]));
  E(FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 999, 0));
  E(FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, -1));
  E(FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_POSITIVE_X, tex, 0));
  E(BindFramebuffer(0x1234, f));
  E(BindRenderbuffer(0x1234, r[0]));
  E(CheckFramebufferStatus(0x1234));
  /* The draw and read buffers in the attribute stack. */
  glPushAttrib(GL_COLOR_BUFFER_BIT | GL_PIXEL_MODE_BIT);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  geti("DRAW_BUFFER pushed, set", GL_DRAW_BUFFER);
  glPopAttrib();
  geti("DRAW_BUFFER popped", GL_DRAW_BUFFER);
  geti("READ_BUFFER popped", GL_READ_BUFFER);
  /* Blit errors. */
  BindFramebuffer(GL_READ_FRAMEBUFFER, a);
  BindFramebuffer(GL_DRAW_FRAMEBUFFER, f);
  status("blit target");
  E(BlitFramebuffer(0, 0, 8, 4, 0, 0, 8, 4, GL_DEPTH_BUFFER_BIT, GL_LINEAR));
  E(BlitFramebuffer(0, 0, 8, 4, 0, 0, 8, 4, GL_COLOR_BUFFER_BIT, 0x1234));
  E(BlitFramebuffer(0, 0, 8, 4, 0, 0, 8, 4, 0x1, GL_NEAREST));
  E(BlitFramebuffer(0, 0, 8, 4, 0, 0, 8, 4, GL_DEPTH_BUFFER_BIT, GL_NEAREST));
  E(BlitFramebuffer(0, 0, 8, 4, 0, 0, 8, 4, GL_COLOR_BUFFER_BIT, GL_NEAREST));
  BindFramebuffer(GL_DRAW_FRAMEBUFFER, shadow_fb);
  E(BlitFramebuffer(0, 0, 8, 4, 0, 0, 8, 4, GL_COLOR_BUFFER_BIT, GL_NEAREST));
  BindFramebuffer(GL_DRAW_FRAMEBUFFER, tfb);
  FramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
  E(BlitFramebuffer(0, 0, 8, 4, 0, 0, 8, 4, GL_COLOR_BUFFER_BIT, GL_NEAREST));
  E(BlitFramebuffer(0, 0, 8, 4, 0, 0, 8, 4, GL_COLOR_BUFFER_BIT, GL_LINEAR));
  BindFramebufferEXT(GL_FRAMEBUFFER, 0);
  geti("FRAMEBUFFER_BINDING after EXT", GL_FRAMEBUFFER_BINDING);
  geti("DRAW_BUFFER window", GL_DRAW_BUFFER);
  glPushAttrib(GL_COLOR_BUFFER_BIT);
  E(glDrawBuffer(GL_NONE));
  geti("DRAW_BUFFER window none", GL_DRAW_BUFFER);
  glPopAttrib();
  geti("DRAW_BUFFER window popped", GL_DRAW_BUFFER);
  {
    /* The window draws again after GL_NONE was popped. */
    glViewport(0, 0, W, H);
    glClearColor(1, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    printf("window cleared %d %d %d\n", window[0], window[1], window[2]);
  }
  DeleteFramebuffers(1, &a);
  DeleteRenderbuffers(1, &rb[0]);
  printf("deleted %d %d 0x%04x\n", IsFramebuffer(a), IsRenderbuffer(rb[0]), glGetError());
  OSMesaDestroyContext(ctx);
  printf("done\n");
  return 0;
}
