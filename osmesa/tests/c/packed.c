/* GL_EXT_packed_depth_stencil: DEPTH24_STENCIL8 / DEPTH_STENCIL textures,
 * DEPTH_STENCIL + UNSIGNED_INT_24_8 uploads and readbacks, level queries,
 * the format/type errors, such a texture on an FBO's depth, stencil and
 * depth-stencil attachments (stencil drawn into it, read back), and
 * MuJoCo's shadow pass: a 4096^2 DEPTH24_STENCIL8 texture rendered on
 * GL_DEPTH_ATTACHMENT, then sampled with compare and eye-linear texgen on
 * S/T/R/Q. Results are written to files, state and errors printed. */
#include "common.h"
#include <GL/glext.h>

static PFNGLGENFRAMEBUFFERSPROC GenFramebuffers;
static PFNGLBINDFRAMEBUFFERPROC BindFramebuffer;
static PFNGLCHECKFRAMEBUFFERSTATUSPROC CheckFramebufferStatus;
static PFNGLFRAMEBUFFERTEXTURE2DPROC FramebufferTexture2D;

#define LOAD(var, name) do { var = (void *)OSMesaGetProcAddress(name); CHECK(var); } while (0)
#define E(call) do { call; printf("%-90s 0x%04x\n", #call, glGetError()); } while (0)

static void level(const char *what) {
  GLint d = -1, s = -1, f = -1, w = -1;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &d);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_STENCIL_SIZE, &s);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &f);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
  printf("level %-30s depth %d stencil %d internal 0x%04x width %d 0x%04x\n", what, d, s, f, w, glGetError());
}

static void status(const char *what) {
  GLenum s = CheckFramebufferStatus(GL_FRAMEBUFFER);
  printf("status %-40s 0x%04x 0x%04x\n", what, s, glGetError());
}

enum { W = 128, H = 96, S = 4096, N = 8 };

int main(int argc, char **argv) {
  start(argc, argv);
  static unsigned char window[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(ctx && OSMesaMakeCurrent(ctx, window, GL_UNSIGNED_BYTE, W, H));
  LOAD(GenFramebuffers, "glGenFramebuffers");
  LOAD(BindFramebuffer, "glBindFramebuffer");
  LOAD(CheckFramebufferStatus, "glCheckFramebufferStatus");
  LOAD(FramebufferTexture2D, "glFramebufferTexture2D");
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);

  /* 1. Upload and read back. */
  static GLuint ds[N * N], out[N * N], outz[N * N];
  for (int i = 0; i < N * N; i++)
    ds[i] = ((GLuint)(i * 262139u + 12345u) & 0xffffffu) << 8 | (GLuint)((i * 37 + 5) & 0xff);
  ds[0] = 0xffffff00u | 0x7f; ds[1] = 0; ds[2] = 0x80000000u | 0xff;
  GLuint tex[3];
  glGenTextures(3, tex);
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, N, N, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, ds));
  level("DEPTH24_STENCIL8");
  E(glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, out));
  dump("packed.get.ds", out, sizeof out);
  E(glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, outz));
  dump("packed.get.z", outz, sizeof outz);
  {
    GLuint sub[4] = {0x12345678u, 0x9abcdef0u, 0x0fedcba9u, 0x87654321u};
    E(glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 3, 2, 2, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, sub));
    E(glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, out));
    dump("packed.get.sub", out, sizeof out);
  }
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, N, N, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, ds));
  level("DEPTH_STENCIL");
  E(glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, out));
  dump("packed.get.ds2", out, sizeof out);

  /* 2. Errors. */
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, N, N, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT, ds));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, N, N, 0, GL_DEPTH_STENCIL, GL_FLOAT, ds));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, N, N, 0, GL_RGBA, GL_UNSIGNED_INT_24_8, ds));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, N, N, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_24_8, ds));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, N, N, 0, GL_RGBA, GL_UNSIGNED_BYTE, ds));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, N, N, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, ds));
  E(glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT, out));
  level("after errors");
  glBindTexture(GL_TEXTURE_2D, tex[2]);
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, N, N, 0, GL_DEPTH_COMPONENT, GL_FLOAT, NULL));
  E(glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, out));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, N, N, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, ds));
  level("DEPTH_COMPONENT24 from DS");
  E(glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, outz));
  dump("packed.get.z24", outz, sizeof outz);

  /* 3. Attachments; stencil and depth drawn into a DS texture. */
  GLuint fb[3];
  GenFramebuffers(3, fb);
  GLuint st;
  glGenTextures(1, &st);
  glBindTexture(GL_TEXTURE_2D, st);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 32, 32, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, NULL));
  BindFramebuffer(GL_FRAMEBUFFER, fb[0]);
  E(FramebufferTexture2D(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_TEXTURE_2D, st, 0));
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  status("stencil only");
  E(FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, st, 0));
  status("depth + stencil");
  BindFramebuffer(GL_FRAMEBUFFER, fb[1]);
  E(FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, st, 0));
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  status("DEPTH_STENCIL_ATTACHMENT");
  {
    GLint v[2] = {-1, -1};
    glGetIntegerv(GL_DEPTH_BITS, &v[0]);
    glGetIntegerv(GL_STENCIL_BITS, &v[1]);
    printf("bits depth %d stencil %d 0x%04x\n", v[0], v[1], glGetError());
  }
  glViewport(0, 0, 32, 32);
  glClearDepth(0.75);
  glClearStencil(3);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glStencilOp(GL_KEEP, GL_INCR, GL_REPLACE);
  glStencilFunc(GL_ALWAYS, 0x5a, 0xff);
  glBegin(GL_TRIANGLES);
  glVertex3f(-1, -1, -0.5f); glVertex3f(1, -1, 0.5f); glVertex3f(-1, 1, 0.9f);
  glVertex3f(1, 1, 0.2f); glVertex3f(-1, 1, 0.2f); glVertex3f(1, -1, 0.2f);
  glEnd();
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_DEPTH_TEST);
  BindFramebuffer(GL_FRAMEBUFFER, 0);
  {
    static GLuint got[32 * 32];
    E(glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, got));
    dump("packed.fbo.ds", got, sizeof got);
  }

  /* 4. MuJoCo's shadow map: 4096^2 DEPTH24_STENCIL8, compare + texgen. */
  GLuint shadow;
  glGenTextures(1, &shadow);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, shadow);
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, S, S, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, NULL));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_INTENSITY);
  BindFramebuffer(GL_FRAMEBUFFER, fb[2]);
  E(FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, shadow, 0));
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  status("shadow");
  /* The light's view: an orthographic box looking down -z. */
  glViewport(0, 0, S, S);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-2, 2, -2, 2, 1, 5);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, 0, -3);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(2.0f, 4.0f);
  /* An occluder over a floor. */
  glBegin(GL_QUADS);
  glVertex3f(-0.6f, -0.5f, 0.8f); glVertex3f(0.4f, -0.7f, 0.9f);
  glVertex3f(0.5f, 0.6f, 0.7f); glVertex3f(-0.5f, 0.5f, 0.8f);
  glVertex3f(-2, -2, -1); glVertex3f(2, -2, -1); glVertex3f(2, 2, -1); glVertex3f(-2, 2, -1);
  glEnd();
  glDisable(GL_POLYGON_OFFSET_FILL);
  BindFramebuffer(GL_FRAMEBUFFER, 0);
  /* The eye's view, texgen eye-linear from the light's bias * projection * view. */
  glViewport(0, 0, W, H);
  glClearColor(0.2f, 0.3f, 0.4f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.6, 0.6, -0.45, 0.45, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, 0, -4);
  glRotatef(-35, 1, 0, 0);
  /* Planes given with the modelview identity = eye space = world here is
   * not MuJoCo's exact order, but the same texgen path: planes in eye space. */
  {
    GLfloat m[16];
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glTranslatef(0.5f, 0.5f, 0.5f);
    glScalef(0.5f, 0.5f, 0.5f);
    glOrtho(-2, 2, -2, 2, 1, 5);
    glTranslatef(0, 0, -3);
    glGetFloatv(GL_TEXTURE_MATRIX, m);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    GLfloat s[4] = {m[0], m[4], m[8], m[12]}, t[4] = {m[1], m[5], m[9], m[13]};
    GLfloat r[4] = {m[2], m[6], m[10], m[14]}, q[4] = {m[3], m[7], m[11], m[15]};
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGenfv(GL_S, GL_EYE_PLANE, s);
    glTexGenfv(GL_T, GL_EYE_PLANE, t);
    glTexGenfv(GL_R, GL_EYE_PLANE, r);
    glTexGenfv(GL_Q, GL_EYE_PLANE, q);
  }
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glEnable(GL_TEXTURE_GEN_R);
  glEnable(GL_TEXTURE_GEN_Q);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glColor3f(1, 0.8f, 0.6f);
  glBegin(GL_QUADS);
  glVertex3f(-2, -2, -1); glVertex3f(2, -2, -1); glVertex3f(2, 2, -1); glVertex3f(-2, 2, -1);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  printf("shadow pass 0x%04x\n", glGetError());
  glFinish();
  dump("packed.shadow", window, sizeof window);

  /* 5. glReadPixels, glDrawPixels and glCopyPixels of DEPTH_STENCIL on the window. */
  glDisable(GL_TEXTURE_GEN_S);
  glDisable(GL_TEXTURE_GEN_T);
  glDisable(GL_TEXTURE_GEN_R);
  glDisable(GL_TEXTURE_GEN_Q);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearDepth(0.25);
  glClearStencil(9);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0x33, 0xff);
  glStencilOp(GL_KEEP, GL_DECR, GL_REPLACE);
  glDepthFunc(GL_GREATER);
  glBegin(GL_TRIANGLES);
  glVertex3f(-1, -1, -0.8f); glVertex3f(1, -1, 0.6f); glVertex3f(-1, 1, 0.3f);
  glEnd();
  glDisable(GL_STENCIL_TEST);
  {
    static GLuint px[W * H];
    E(glReadPixels(0, 0, W, H, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, px));
    dump("packed.read", px, sizeof px);
    E(glReadPixels(0, 0, W, H, GL_DEPTH_STENCIL, GL_UNSIGNED_INT, px));
    E(glReadPixels(0, 0, W, H, GL_DEPTH_STENCIL, GL_FLOAT, px));
    E(glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_INT_24_8, px));
    E(glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_24_8, px));
    /* Draw an image of DEPTH_STENCIL at the raster position, zoomed. */
    GLuint img[16 * 8];
    for (int i = 0; i < 16 * 8; i++) img[i] = ((GLuint)(i * 104729u) & 0xffffffu) << 8 | (GLuint)(i * 7);
    glRasterPos2f(-0.5f, -0.5f);
    glPixelZoom(2, 3);
    glStencilMask(0x7f);
    E(glDrawPixels(16, 8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, img));
    glStencilMask(0xff);
    glPixelZoom(1, 1);
    E(glDrawPixels(16, 8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT, img));
    E(glDrawPixels(16, 8, GL_RGBA, GL_UNSIGNED_INT_24_8, img));
    glReadPixels(0, 0, W, H, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, px);
    dump("packed.draw", px, sizeof px);
    /* Depth mask off: stencil only. */
    glDepthMask(GL_FALSE);
    glRasterPos2f(0.5f, 0.2f);
    E(glDrawPixels(16, 8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, img));
    glDepthMask(GL_TRUE);
    glReadPixels(0, 0, W, H, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, px);
    dump("packed.draw.nodepth", px, sizeof px);
    glRasterPos2f(0.1f, -0.9f);
    E(glCopyPixels(10, 20, 40, 30, GL_DEPTH_STENCIL));
    glReadPixels(0, 0, W, H, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, px);
    dump("packed.copy", px, sizeof px);
  }
  OSMesaDestroyContext(ctx);

  /* 6. No stencil buffer: INVALID_OPERATION. */
  ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  CHECK(ctx && OSMesaMakeCurrent(ctx, window, GL_UNSIGNED_BYTE, W, H));
  {
    GLuint px[4] = {0}, img[4] = {0};
    E(glReadPixels(0, 0, 2, 2, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, px));
    E(glDrawPixels(2, 2, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, img));
    E(glCopyPixels(0, 0, 2, 2, GL_DEPTH_STENCIL));
  }
  OSMesaDestroyContext(ctx);
  printf("done\n");
  return 0;
}
