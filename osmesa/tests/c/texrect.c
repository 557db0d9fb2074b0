/* Rectangle textures (GL_ARB_texture_rectangle): state and defaults, the
 * errors of every call that takes the target, push/pop and display lists,
 * and scenes sampling odd-sized (37x19) rectangles at unnormalized
 * coordinates: NEAREST and LINEAR, CLAMP / CLAMP_TO_EDGE / CLAMP_TO_BORDER
 * with a border colour, texgen and the texture matrix, projective q, min !=
 * mag filters, a depth rectangle with compare, the enable priority, and
 * render-to-rectangle through a framebuffer object then sampling. State and
 * errors are printed one per line (the line "max rectangle size" is each
 * implementation's own limit); the scenes are written to texrect.color. */
#include "common.h"
#include <GL/glext.h>
#include <math.h>

static PFNGLGENFRAMEBUFFERSPROC GenFramebuffers;
static PFNGLBINDFRAMEBUFFERPROC BindFramebuffer;
static PFNGLCHECKFRAMEBUFFERSTATUSPROC CheckFramebufferStatus;
static PFNGLFRAMEBUFFERTEXTURE2DPROC FramebufferTexture2D;
static PFNGLGENERATEMIPMAPPROC GenerateMipmap;
static PFNGLGETFRAMEBUFFERATTACHMENTPARAMETERIVPROC GetFramebufferAttachmentParameteriv;
static PFNGLACTIVETEXTUREPROC ActiveTexture;

#define LOAD(var, name) do { var = (void *)OSMesaGetProcAddress(name); CHECK(var); } while (0)
#define E(call) do { call; printf("%-78s 0x%04x\n", #call, glGetError()); } while (0)

#define W 320
#define H 192
#define CELL 64
#define TW 37
#define TH 19

static GLubyte texels[TH][TW][4];

static void geti(const char *name, GLenum pname) {
  GLint v[4] = {-1, -1, -1, -1};
  glGetIntegerv(pname, v);
  printf("get %-40s %d 0x%04x\n", name, v[0], glGetError());
}

static void getb(const char *name, GLenum pname) {
  GLboolean v = 7;
  glGetBooleanv(pname, &v);
  printf("getb %-40s %d enabled %d 0x%04x\n", name, v, glIsEnabled(pname), glGetError());
}

static void param(const char *name, GLenum pname) {
  GLint v = -1;
  glGetTexParameteriv(GL_TEXTURE_RECTANGLE_ARB, pname, &v);
  printf("param %-30s 0x%x 0x%04x\n", name, v, glGetError());
}

static void level(const char *what, GLenum target, GLint lvl) {
  GLint w = -1, h = -1, b = -1, f = -1;
  glGetTexLevelParameteriv(target, lvl, GL_TEXTURE_WIDTH, &w);
  glGetTexLevelParameteriv(target, lvl, GL_TEXTURE_HEIGHT, &h);
  glGetTexLevelParameteriv(target, lvl, GL_TEXTURE_BORDER, &b);
  glGetTexLevelParameteriv(target, lvl, GL_TEXTURE_INTERNAL_FORMAT, &f);
  printf("level %-30s %dx%d border %d format 0x%x 0x%04x\n", what, w, h, b, f, glGetError());
}

/* Cell (cx, cy) of the W x H image. */
static void cell(int cx, int cy) {
  glViewport(cx * CELL, cy * CELL, CELL, CELL);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

/* A quad over the cell (slightly inset, at odd positions) with texture
 * coordinates s0..s1, t0..t1. */
static void quad(float s0, float t0, float s1, float t1) {
  glBegin(GL_QUADS);
  glTexCoord2f(s0, t0); glVertex2f(-0.93f, -0.91f);
  glTexCoord2f(s1, t0); glVertex2f(0.95f, -0.91f);
  glTexCoord2f(s1, t1); glVertex2f(0.95f, 0.89f);
  glTexCoord2f(s0, t1); glVertex2f(-0.93f, 0.89f);
  glEnd();
}

static void filters(GLenum min, GLenum mag) {
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MIN_FILTER, min);
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MAG_FILTER, mag);
}

static void wraps(GLenum w) {
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_S, w);
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_T, w);
}

int main(int argc, char **argv) {
  start(argc, argv);
  static GLubyte buf[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(ctx);
  CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
  LOAD(GenFramebuffers, "glGenFramebuffers");
  LOAD(BindFramebuffer, "glBindFramebuffer");
  LOAD(CheckFramebufferStatus, "glCheckFramebufferStatus");
  LOAD(FramebufferTexture2D, "glFramebufferTexture2D");
  LOAD(GenerateMipmap, "glGenerateMipmap");
  LOAD(GetFramebufferAttachmentParameteriv, "glGetFramebufferAttachmentParameteriv");
  LOAD(ActiveTexture, "glActiveTexture");
  printf("extension ARB %d EXT %d NV %d\n",
         strstr((const char *)glGetString(GL_EXTENSIONS), "GL_ARB_texture_rectangle ") != NULL,
         strstr((const char *)glGetString(GL_EXTENSIONS), "GL_EXT_texture_rectangle ") != NULL,
         strstr((const char *)glGetString(GL_EXTENSIONS), "GL_NV_texture_rectangle ") != NULL);

  for (int y = 0; y < TH; y++)
    for (int x = 0; x < TW; x++) {
      texels[y][x][0] = (GLubyte)(x * 7 + (y & 1) * 90);
      texels[y][x][1] = (GLubyte)(y * 13 + (x % 3) * 40);
      texels[y][x][2] = (GLubyte)((x ^ y) * 11);
      texels[y][x][3] = (GLubyte)(255 - x * 3);
    }

  /* ----- state: defaults and queries ----- */
  GLint max = -1;
  glGetIntegerv(GL_MAX_RECTANGLE_TEXTURE_SIZE_ARB, &max);
  printf("max rectangle size %d 0x%04x\n", max, glGetError());
  getb("TEXTURE_RECTANGLE", GL_TEXTURE_RECTANGLE_ARB);
  geti("TEXTURE_BINDING_RECTANGLE", GL_TEXTURE_BINDING_RECTANGLE_ARB);
  param("default WRAP_S", GL_TEXTURE_WRAP_S);
  param("default WRAP_T", GL_TEXTURE_WRAP_T);
  param("default WRAP_R", GL_TEXTURE_WRAP_R);
  param("default MIN_FILTER", GL_TEXTURE_MIN_FILTER);
  param("default MAG_FILTER", GL_TEXTURE_MAG_FILTER);
  param("default BASE_LEVEL", GL_TEXTURE_BASE_LEVEL);
  param("default MAX_LEVEL", GL_TEXTURE_MAX_LEVEL);
  level("default texture", GL_TEXTURE_RECTANGLE_ARB, 0);

  GLuint tex[10];
  glGenTextures(10, tex);
  E(glBindTexture(GL_TEXTURE_RECTANGLE_ARB, tex[0]));
  geti("TEXTURE_BINDING_RECTANGLE", GL_TEXTURE_BINDING_RECTANGLE_ARB);
  param("new WRAP_S", GL_TEXTURE_WRAP_S);
  param("new MIN_FILTER", GL_TEXTURE_MIN_FILTER);
  E(glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA8, TW, TH, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels));
  level("37x19", GL_TEXTURE_RECTANGLE_ARB, 0);

  /* ----- errors ----- */
  E(glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 1, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
  E(glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 1, GL_RGBA8, 8, 8, 0, GL_RGBA, 0x1234, NULL));
  E(glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA8, 8, 8, 1, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
  E(glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA8, -1, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
  E(glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA8, 20000, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
  E(glTexImage1D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
  E(glTexImage3D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA8, 8, 8, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
  E(glTexSubImage2D(GL_TEXTURE_RECTANGLE_ARB, 1, 0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, texels));
  E(glTexSubImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, 36, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, texels));
  E(glTexSubImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, 0, 18, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, texels));
  E(glCopyTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 1, GL_RGBA8, 0, 0, 8, 8, 0));
  E(glCopyTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA8, 0, 0, 8, 8, 1));
  E(glCopyTexSubImage2D(GL_TEXTURE_RECTANGLE_ARB, 1, 0, 0, 0, 0, 2, 2));
  E(glCopyTexSubImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, 30, 0, 0, 0, 8, 2));
  E(glCopyTexSubImage1D(GL_TEXTURE_RECTANGLE_ARB, 0, 0, 0, 0, 2));
  static GLubyte back[TW * TH * 4];
  E(glGetTexImage(GL_TEXTURE_RECTANGLE_ARB, 1, GL_RGBA, GL_UNSIGNED_BYTE, back));
  GLint v = -1;
  E(glGetTexLevelParameteriv(GL_TEXTURE_RECTANGLE_ARB, 1, GL_TEXTURE_WIDTH, &v));
  E(glGetTexLevelParameteriv(GL_PROXY_TEXTURE_RECTANGLE_ARB, 1, GL_TEXTURE_WIDTH, &v));
  E(glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_S, GL_REPEAT));
  E(glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_T, GL_MIRRORED_REPEAT));
  E(glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_R, GL_REPEAT));
  E(glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_S, GL_CLAMP));
  E(glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER));
  E(glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_R, GL_CLAMP));
  E(glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR));
  E(glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST));
  E(glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MIN_FILTER, GL_NEAREST));
  E(glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_BASE_LEVEL, 1));
  E(glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_BASE_LEVEL, 0));
  E(glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_BASE_LEVEL, -1));
  E(glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MAX_LEVEL, 1));
  E(glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MAX_LEVEL, -1));
  E(glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MAX_LEVEL, 1000));
  E(glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MAX_LEVEL, 0));
  E(glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MAX_LEVEL, 1000));
  E(glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_GENERATE_MIPMAP, GL_TRUE));
  param("GENERATE_MIPMAP", GL_GENERATE_MIPMAP);
  E(glTexSubImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, 0, 0, TW, TH, GL_RGBA, GL_UNSIGNED_BYTE, texels));
  E(glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_GENERATE_MIPMAP, GL_FALSE));
  E(GenerateMipmap(GL_TEXTURE_RECTANGLE_ARB));
  param("WRAP_S after", GL_TEXTURE_WRAP_S);
  param("WRAP_T after", GL_TEXTURE_WRAP_T);
  param("WRAP_R after", GL_TEXTURE_WRAP_R);
  param("MIN_FILTER after", GL_TEXTURE_MIN_FILTER);
  param("BASE_LEVEL after", GL_TEXTURE_BASE_LEVEL);
  param("MAX_LEVEL after", GL_TEXTURE_MAX_LEVEL);
  E(glBindTexture(GL_TEXTURE_2D, tex[0]));
  E(glBindTexture(GL_TEXTURE_2D, tex[7]));
  E(glBindTexture(GL_TEXTURE_RECTANGLE_ARB, tex[7]));
  E(glBindTexture(GL_TEXTURE_RECTANGLE_ARB, tex[0]));
  /* Proxies. */
  E(glTexImage2D(GL_PROXY_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA8, TW, TH, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
  level("proxy 37x19", GL_PROXY_TEXTURE_RECTANGLE_ARB, 0);
  E(glTexImage2D(GL_PROXY_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA8, 20000, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
  level("proxy 20000x4", GL_PROXY_TEXTURE_RECTANGLE_ARB, 0);
  E(glTexImage2D(GL_PROXY_TEXTURE_RECTANGLE_ARB, 1, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
  E(glTexImage2D(GL_PROXY_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA8, 8, 8, 1, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
  E(glTexSubImage2D(GL_PROXY_TEXTURE_RECTANGLE_ARB, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels));
  E(glBindTexture(GL_PROXY_TEXTURE_RECTANGLE_ARB, tex[0]));
  E(glEnable(GL_PROXY_TEXTURE_RECTANGLE_ARB));
  E(glGetIntegerv(GL_PROXY_TEXTURE_RECTANGLE_ARB, &v));

  /* Readback of the image. */
  memset(back, 0, sizeof back);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  E(glGetTexImage(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA, GL_UNSIGNED_BYTE, back));
  printf("readback equal %d\n", memcmp(back, texels, sizeof back) == 0);

  /* ----- enables, push/pop, display lists ----- */
  E(glEnable(GL_TEXTURE_RECTANGLE_ARB));
  getb("TEXTURE_RECTANGLE enabled", GL_TEXTURE_RECTANGLE_ARB);
  E(glPushAttrib(GL_ENABLE_BIT));
  E(glDisable(GL_TEXTURE_RECTANGLE_ARB));
  getb("TEXTURE_RECTANGLE in push", GL_TEXTURE_RECTANGLE_ARB);
  E(glPopAttrib());
  getb("TEXTURE_RECTANGLE popped", GL_TEXTURE_RECTANGLE_ARB);
  E(glPushAttrib(GL_TEXTURE_BIT));
  E(glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MAX_LEVEL, 0));
  E(glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE));
  E(glBindTexture(GL_TEXTURE_RECTANGLE_ARB, tex[1]));
  E(glDisable(GL_TEXTURE_RECTANGLE_ARB));
  geti("TEXTURE_BINDING_RECTANGLE in push", GL_TEXTURE_BINDING_RECTANGLE_ARB);
  E(glPopAttrib());
  geti("TEXTURE_BINDING_RECTANGLE popped", GL_TEXTURE_BINDING_RECTANGLE_ARB);
  getb("TEXTURE_RECTANGLE popped", GL_TEXTURE_RECTANGLE_ARB);
  param("MAX_LEVEL popped", GL_TEXTURE_MAX_LEVEL);
  param("WRAP_S popped", GL_TEXTURE_WRAP_S);
  E(ActiveTexture(GL_TEXTURE1));
  getb("unit 1 TEXTURE_RECTANGLE", GL_TEXTURE_RECTANGLE_ARB);
  geti("unit 1 TEXTURE_BINDING_RECTANGLE", GL_TEXTURE_BINDING_RECTANGLE_ARB);
  E(ActiveTexture(GL_TEXTURE0));
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, tex[2]);
  glDisable(GL_TEXTURE_RECTANGLE_ARB);
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glEndList();
  printf("list compiled 0x%04x\n", glGetError());
  geti("TEXTURE_BINDING_RECTANGLE after compile", GL_TEXTURE_BINDING_RECTANGLE_ARB);
  getb("TEXTURE_RECTANGLE after compile", GL_TEXTURE_RECTANGLE_ARB);
  E(glCallList(list));
  geti("TEXTURE_BINDING_RECTANGLE after call", GL_TEXTURE_BINDING_RECTANGLE_ARB);
  getb("TEXTURE_RECTANGLE after call", GL_TEXTURE_RECTANGLE_ARB);
  E(glBindTexture(GL_TEXTURE_RECTANGLE_ARB, tex[0]));
  E(glEnable(GL_TEXTURE_RECTANGLE_ARB));

  /* ----- scenes ----- */
  glClearColor(0.05f, 0.1f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  /* 0: NEAREST, CLAMP_TO_EDGE, beyond the image on every side. */
  cell(0, 0);
  filters(GL_NEAREST, GL_NEAREST);
  wraps(GL_CLAMP_TO_EDGE);
  quad(-4.3f, -3.1f, TW + 5.2f, TH + 2.7f);
  /* 1: LINEAR, CLAMP_TO_EDGE. */
  cell(1, 0);
  filters(GL_LINEAR, GL_LINEAR);
  quad(-4.3f, -3.1f, TW + 5.2f, TH + 2.7f);
  /* 2: LINEAR, CLAMP with a border colour. */
  cell(2, 0);
  wraps(GL_CLAMP);
  GLfloat border[4] = {0.9f, 0.2f, 0.6f, 0.8f};
  glTexParameterfv(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_BORDER_COLOR, border);
  quad(-4.3f, -3.1f, TW + 5.2f, TH + 2.7f);
  /* 3: LINEAR, CLAMP_TO_BORDER. */
  cell(3, 0);
  wraps(GL_CLAMP_TO_BORDER);
  quad(-4.3f, -3.1f, TW + 5.2f, TH + 2.7f);
  /* 4: NEAREST, CLAMP_TO_BORDER, and NEAREST CLAMP on the top half. */
  cell(4, 0);
  filters(GL_NEAREST, GL_NEAREST);
  quad(-4.3f, -3.1f, TW + 5.2f, TH + 2.7f);
  wraps(GL_CLAMP);
  glBegin(GL_TRIANGLES);
  glTexCoord2f(-6, 10); glVertex2f(-1, 0.2f);
  glTexCoord2f(TW + 6, 10); glVertex2f(1, 0.2f);
  glTexCoord2f(TW / 2.0f, TH + 8); glVertex2f(0, 1);
  glEnd();
  wraps(GL_CLAMP_TO_EDGE);
  /* 5 (row 1, 0): texgen OBJECT_LINEAR taking x, y in [-1, 1] to texels,
   * and a rotating texture matrix. */
  cell(0, 1);
  filters(GL_LINEAR, GL_LINEAR);
  GLfloat sp[4] = {TW / 2.0f, 0, 0, TW / 2.0f}, tp[4] = {0, TH / 2.0f, 0, TH / 2.0f};
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGenfv(GL_S, GL_OBJECT_PLANE, sp);
  glTexGenfv(GL_T, GL_OBJECT_PLANE, tp);
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glTranslatef(TW / 2.0f, TH / 2.0f, 0);
  glRotatef(17, 0, 0, 1);
  glScalef(1.3f, 0.8f, 1);
  glTranslatef(-TW / 2.0f, -TH / 2.0f, 0);
  glMatrixMode(GL_MODELVIEW);
  glBegin(GL_TRIANGLES);
  glVertex2f(-0.97f, -0.9f); glVertex2f(0.93f, -0.8f); glVertex2f(0.1f, 0.95f);
  glEnd();
  glDisable(GL_TEXTURE_GEN_S);
  glDisable(GL_TEXTURE_GEN_T);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  /* 6: projective q, perspective-varying. */
  cell(1, 1);
  glBegin(GL_QUADS);
  glTexCoord4f(0, 0, 0, 1); glVertex2f(-0.9f, -0.9f);
  glTexCoord4f(TW * 2.5f, 0, 0, 2.5f); glVertex2f(0.9f, -0.9f);
  glTexCoord4f(TW * 0.5f, TH * 0.5f, 0, 0.5f); glVertex2f(0.9f, 0.9f);
  glTexCoord4f(0, TH * 1.7f, 0, 1.7f); glVertex2f(-0.9f, 0.9f);
  glEnd();
  /* 7: minified with NEAREST min and LINEAR mag (λ from the quad). */
  cell(2, 1);
  filters(GL_NEAREST, GL_LINEAR);
  quad(0, 0, TW, TH);
  glBegin(GL_TRIANGLES);
  glTexCoord2f(0, 0); glVertex2f(-0.2f, -0.2f);
  glTexCoord2f(TW, 0); glVertex2f(0.1f, -0.2f);
  glTexCoord2f(0, TH); glVertex2f(-0.2f, 0.1f);
  glEnd();
  /* 8: the enable priority: 2D and 3D enabled with the rectangle; then 1D. */
  cell(3, 1);
  filters(GL_NEAREST, GL_NEAREST);
  static GLubyte green[4 * 4 * 4], blue[2 * 2 * 2 * 4];
  for (int i = 0; i < 16; i++) { green[4 * i + 1] = 200; green[4 * i + 3] = 255; }
  for (int i = 0; i < 8; i++) { blue[4 * i + 2] = 210; blue[4 * i + 3] = 255; }
  glBindTexture(GL_TEXTURE_2D, tex[3]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, green);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  quad(0, 0, TW, TH); /* the rectangle */
  glBindTexture(GL_TEXTURE_3D, tex[4]);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 2, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, blue);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_3D);
  glBegin(GL_TRIANGLES); /* the 3D texture */
  glTexCoord2f(0.2f, 0.3f); glVertex2f(-0.5f, 0.3f);
  glTexCoord2f(0.7f, 0.3f); glVertex2f(0.5f, 0.3f);
  glTexCoord2f(0.4f, 0.8f); glVertex2f(0, 0.8f);
  glEnd();
  glDisable(GL_TEXTURE_3D);
  glDisable(GL_TEXTURE_2D);
  printf("priority scene 0x%04x\n", glGetError());
  /* 9: a luminance-alpha rectangle, MODULATE with the primary colour, blended. */
  cell(4, 1);
  static GLubyte la[5 * 3 * 2];
  for (int i = 0; i < 15; i++) { la[2 * i] = (GLubyte)(i * 17); la[2 * i + 1] = (GLubyte)(255 - i * 9); }
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, tex[5]);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_LUMINANCE_ALPHA, 5, 3, 0, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, la);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColor4f(1.0f, 0.6f, 0.3f, 1.0f);
  quad(-0.5f, -0.5f, 5.5f, 3.5f);
  glDisable(GL_BLEND);
  glColor4f(1, 1, 1, 1);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  printf("luminance alpha scene 0x%04x\n", glGetError());

  /* 10 (row 2, 0): a depth rectangle compared with r (LINEAR), alpha mode. */
  cell(0, 2);
  static GLfloat depth[TH][TW];
  for (int y = 0; y < TH; y++)
    for (int x = 0; x < TW; x++) depth[y][x] = (float)((x * 3 + y * 5) % 29) / 28.0f;
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, tex[6]);
  E(glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_DEPTH_COMPONENT24, TW, TH, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth));
  level("depth 37x19", GL_TEXTURE_RECTANGLE_ARB, 0);
  E(glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE));
  E(glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL));
  E(glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE));
  glBegin(GL_QUADS);
  glTexCoord3f(-2, -1, 0.1f); glVertex2f(-0.9f, -0.9f);
  glTexCoord3f(TW + 2, -1, 0.4f); glVertex2f(0.9f, -0.9f);
  glTexCoord3f(TW + 2, TH + 1, 0.9f); glVertex2f(0.9f, 0.9f);
  glTexCoord3f(-2, TH + 1, 0.6f); glVertex2f(-0.9f, 0.9f);
  glEnd();
  /* 11: the same depth texture NEAREST, without compare (its depths as luminance). */
  cell(1, 2);
  filters(GL_NEAREST, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_COMPARE_MODE, GL_NONE);
  quad(0, 0, TW, TH);
  printf("depth scenes 0x%04x\n", glGetError());

  /* 12, 13: render to a 45x23 rectangle through a framebuffer object, then sample it. */
  GLuint fbo, rt = tex[8];
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, rt);
  E(glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA8, 45, 23, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
  GenFramebuffers(1, &fbo);
  BindFramebuffer(GL_FRAMEBUFFER, fbo);
  E(FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_RECTANGLE_ARB, rt, 1));
  E(FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, rt, 0));
  E(FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_RECTANGLE_ARB, rt, 0));
  GLint att = -1;
  GetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &att);
  printf("attachment name is the rectangle %d 0x%04x\n", att == (GLint)rt, glGetError());
  GLenum st = CheckFramebufferStatus(GL_FRAMEBUFFER);
  printf("rectangle framebuffer complete %d\n", st == GL_FRAMEBUFFER_COMPLETE);
  glDisable(GL_TEXTURE_RECTANGLE_ARB);
  glViewport(0, 0, 45, 23);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 45, 0, 23, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0.3f, 0.3f, 0.3f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glShadeModel(GL_SMOOTH);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0); glVertex2f(1.5f, 1.25f);
  glColor3f(0, 1, 0); glVertex2f(43.7f, 4.5f);
  glColor3f(0, 0, 1); glVertex2f(20.2f, 22.1f);
  glEnd();
  glColor3f(1, 1, 1);
  BindFramebuffer(GL_FRAMEBUFFER, 0);
  static GLubyte rtback[45 * 23 * 4];
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, rt);
  E(glGetTexImage(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA, GL_UNSIGNED_BYTE, rtback));
  dump("texrect.rt", rtback, sizeof rtback);
  glEnable(GL_TEXTURE_RECTANGLE_ARB);
  cell(2, 2);
  filters(GL_NEAREST, GL_NEAREST);
  quad(0, 0, 45, 23);
  cell(3, 2);
  filters(GL_LINEAR, GL_LINEAR);
  wraps(GL_CLAMP_TO_BORDER);
  quad(-3.5f, -2.5f, 48.5f, 25.5f);
  /* 14: glCopyTexSubImage2D into the rectangle from the window, then sampled. */
  E(glCopyTexSubImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, 3, 2, 70, 10, 30, 15));
  E(glCopyTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA8, 130, 5, 41, 27, 0));
  level("copied 41x27", GL_TEXTURE_RECTANGLE_ARB, 0);
  cell(4, 2);
  wraps(GL_CLAMP_TO_EDGE);
  quad(0, 0, 41, 27);
  printf("render to rectangle 0x%04x\n", glGetError());

  glFinish();
  dump("texrect.color", buf, sizeof buf);
  printf("done\n");
  OSMesaDestroyContext(ctx);
  return 0;
}
