/* What MuJoCo's classic renderer asks of an OSMesa, one line per feature:
 * `name err=0x.... value...`. Every GL function is loaded through
 * OSMesaGetProcAddress, as MuJoCo's glad loader does; a NULL one prints
 * `name NULL` and the features needing it are skipped. The calls and
 * arguments are those of MuJoCo 4.0's traces (docs/mujoco.md).
 *
 *   cc -o probe probe.c -lOSMesa && ./probe      (LD_LIBRARY_PATH picks the library) */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define LOAD(name) __typeof__(&name) p_##name = (__typeof__(&name))OSMesaGetProcAddress(#name)
#define HAVE(name) (p_##name ? 1 : (printf("%s NULL\n", #name), 0))

static GLenum (*get_error)(void);

/* Errors of a call not reported on its own line. */
static void drain(void) {
  for (int i = 0; i < 8 && get_error(); i++) {
  }
}

static void report(const char *what) {
  GLenum e = get_error(), e2;
  printf("%-44s err=0x%04x", what, e);
  while ((e2 = get_error()) != 0) printf(",0x%04x", e2);
  printf("\n");
}

int main(void) {
  static const char *names[] = {
#include "called.inc"
  };
  int w = 64, h = 48;
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  float *buf = calloc((size_t)w * h * 4, sizeof(float));
  if (!ctx || !OSMesaMakeCurrent(ctx, buf, GL_FLOAT, w, h)) {
    printf("OSMesaMakeCurrent(GL_FLOAT) failed\n");
    return 1;
  }
  get_error = (GLenum (*)(void))OSMesaGetProcAddress("glGetError");
  int nulls = 0;
  for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
    if (!OSMesaGetProcAddress(names[i])) { printf("proc %s NULL\n", names[i]); nulls++; }
  printf("procs called by MuJoCo: %zu, NULL: %d\n", sizeof names / sizeof names[0], nulls);

  LOAD(glGetString); LOAD(glGetIntegerv); LOAD(glGetBooleanv); LOAD(glGetFloatv); LOAD(glEnable);
  LOAD(glDisable); LOAD(glIsEnabled); LOAD(glFogi); LOAD(glHint); LOAD(glTexImage2D);
  LOAD(glTexParameteri); LOAD(glBindTexture); LOAD(glGenTextures); LOAD(glActiveTexture);
  LOAD(glTexGeni); LOAD(glTexGenfv); LOAD(glGenerateMipmap); LOAD(glDrawBuffer); LOAD(glReadBuffer);
  LOAD(glLightModeli); LOAD(glColorMaterial); LOAD(glClipPlane); LOAD(glRasterPos3f); LOAD(glBitmap);
  LOAD(glNewList); LOAD(glEndList); LOAD(glGenLists); LOAD(glListBase); LOAD(glCallLists);
  LOAD(glReadPixels); LOAD(glPixelStorei); LOAD(glPolygonOffset); LOAD(glPolygonMode);
  LOAD(glAlphaFunc); LOAD(glDepthRange); LOAD(glClearDepth); LOAD(glDepthFunc); LOAD(glClear);
  LOAD(glDrawElements); LOAD(glVertexPointer); LOAD(glEnableClientState); LOAD(glDisableClientState);
  LOAD(glGenBuffers); LOAD(glBindBuffer); LOAD(glBufferData); LOAD(glDeleteBuffers);
  LOAD(glGenFramebuffers); LOAD(glBindFramebuffer); LOAD(glCheckFramebufferStatus);
  LOAD(glGenRenderbuffers); LOAD(glBindRenderbuffer); LOAD(glRenderbufferStorage);
  LOAD(glRenderbufferStorageMultisample); LOAD(glFramebufferRenderbuffer); LOAD(glFramebufferTexture2D);
  LOAD(glGetRenderbufferParameteriv); LOAD(glBlitFramebuffer); LOAD(glClipControl);
  LOAD(glStencilFunc); LOAD(glStencilOp); LOAD(glClearStencil); LOAD(glCullFace);

  printf("GL_VERSION \"%s\"\n", (const char *)p_glGetString(GL_VERSION));
  const char *ext = (const char *)p_glGetString(GL_EXTENSIONS);
  static const char *glad_ext[] = {"GL_ARB_clip_control", "GL_ARB_depth_buffer_float",
    "GL_ARB_framebuffer_object", "GL_ARB_seamless_cube_map", "GL_ARB_vertex_buffer_object",
    "GL_EXT_texture_sRGB", "GL_KHR_debug"};
  for (int i = 0; i < 7; i++) {
    const char *p = ext ? strstr(ext, glad_ext[i]) : NULL;
    int has = p && (p[strlen(glad_ext[i])] == ' ' || p[strlen(glad_ext[i])] == 0);
    printf("extension %s %s\n", glad_ext[i], has ? "yes" : "no");
  }
  report("glGetString");

  /* Queries, with what they answer. */
  static const struct { GLenum e; const char *n; } ints[] = {
    {GL_MAX_LIGHTS, "GL_MAX_LIGHTS"}, {GL_MAX_SAMPLES, "GL_MAX_SAMPLES"},
    {GL_SAMPLE_BUFFERS, "GL_SAMPLE_BUFFERS"}, {GL_SAMPLES, "GL_SAMPLES"},
    {GL_MAX_RENDERBUFFER_SIZE, "GL_MAX_RENDERBUFFER_SIZE"}, {GL_MAX_TEXTURE_SIZE, "GL_MAX_TEXTURE_SIZE"},
    {GL_MAX_CUBE_MAP_TEXTURE_SIZE, "GL_MAX_CUBE_MAP_TEXTURE_SIZE"},
    {GL_MAX_TEXTURE_UNITS, "GL_MAX_TEXTURE_UNITS"}, {GL_CULL_FACE_MODE, "GL_CULL_FACE_MODE"},
    {GL_RED_BITS, "GL_RED_BITS"}, {GL_DEPTH_BITS, "GL_DEPTH_BITS"}, {GL_STENCIL_BITS, "GL_STENCIL_BITS"},
  };
  for (size_t i = 0; i < sizeof ints / sizeof ints[0]; i++) {
    GLint v = -12345;
    p_glGetIntegerv(ints[i].e, &v);
    char what[64];
    snprintf(what, sizeof what, "glGetIntegerv(%s)=%d", ints[i].n, v);
    report(what);
  }
  GLboolean b = 77;
  p_glGetBooleanv(GL_STEREO, &b); printf("GL_STEREO=%d\n", b); report("glGetBooleanv(GL_STEREO)");
  b = 77;
  p_glGetBooleanv(GL_DOUBLEBUFFER, &b); printf("GL_DOUBLEBUFFER=%d\n", b); report("glGetBooleanv(GL_DOUBLEBUFFER)");
  GLfloat m[16];
  p_glGetFloatv(GL_PROJECTION_MATRIX, m); report("glGetFloatv(GL_PROJECTION_MATRIX)");
  p_glGetFloatv(GL_MODELVIEW_MATRIX, m); report("glGetFloatv(GL_MODELVIEW_MATRIX)");
  p_glIsEnabled(GL_CULL_FACE); report("glIsEnabled(GL_CULL_FACE)");

  /* State MuJoCo sets. */
  p_glEnable(GL_MULTISAMPLE); report("glEnable(GL_MULTISAMPLE)");
  p_glDisable(GL_MULTISAMPLE); report("glDisable(GL_MULTISAMPLE)");
  p_glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS); report("glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS)");
  p_glDisable(GL_TEXTURE_CUBE_MAP_SEAMLESS); drain();
  p_glEnable(GL_NORMALIZE); report("glEnable(GL_NORMALIZE)");
  p_glEnable(GL_COLOR_MATERIAL); p_glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  report("glColorMaterial(FRONT_AND_BACK, AMBIENT_AND_DIFFUSE)");
  p_glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1); report("glLightModeli(LOCAL_VIEWER, 1)");
  p_glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH); report("glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH)");
  p_glHint(GL_FOG_HINT, GL_NICEST); report("glHint(GL_FOG_HINT, GL_NICEST)");
  p_glAlphaFunc(GL_GEQUAL, 0.99f); report("glAlphaFunc(GL_GEQUAL, 0.99)");
  p_glDepthFunc(GL_GEQUAL); p_glClearDepth(0.0); p_glDepthRange(0, 1); report("glDepthFunc(GEQUAL) glClearDepth(0)");
  p_glPolygonMode(GL_FRONT_AND_BACK, GL_FILL); report("glPolygonMode(FRONT_AND_BACK, FILL)");
  p_glEnable(GL_POLYGON_OFFSET_FILL); p_glPolygonOffset(-1.5f, -4.0f); report("glPolygonOffset(-1.5, -4)");
  p_glDisable(GL_POLYGON_OFFSET_FILL); drain();
  p_glEnable(GL_STENCIL_TEST); p_glClearStencil(0); p_glStencilFunc(GL_EQUAL, 1, 255);
  p_glStencilOp(GL_REPLACE, GL_REPLACE, GL_REPLACE); report("stencil func/op/clear");
  p_glDisable(GL_STENCIL_TEST); drain();
  GLdouble plane[4] = {0, 0, -1, 0};
  p_glEnable(GL_CLIP_PLANE0); p_glClipPlane(GL_CLIP_PLANE0, plane); report("glClipPlane(GL_CLIP_PLANE0)");
  p_glDisable(GL_CLIP_PLANE0); drain();
  p_glCullFace(GL_FRONT); p_glCullFace(GL_BACK); report("glCullFace(FRONT/BACK)");
  if (p_glClipControl) { p_glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE); report("glClipControl(LOWER_LEFT, ZERO_TO_ONE)");
    p_glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE); drain(); }

  /* Textures: the shadow map, the sRGB and plain 2D textures, the skybox cube. */
  GLuint tex[4];
  p_glGenTextures(4, tex); drain();
  p_glActiveTexture(GL_TEXTURE1); report("glActiveTexture(GL_TEXTURE1)");
  p_glBindTexture(GL_TEXTURE_2D, tex[0]);
  p_glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 4096, 4096, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, NULL);
  report("glTexImage2D(DEPTH24_STENCIL8 4096^2)");
  p_glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE); report("TEXTURE_COMPARE_MODE R_TO_TEXTURE");
  p_glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_GEQUAL); report("TEXTURE_COMPARE_FUNC GEQUAL");
  p_glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_INTENSITY); report("DEPTH_TEXTURE_MODE INTENSITY");
  p_glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR); report("glTexGeni(Q, EYE_LINEAR)");
  GLfloat qp[4] = {0, 0, 0, 1};
  p_glTexGenfv(GL_Q, GL_EYE_PLANE, qp); report("glTexGenfv(Q, EYE_PLANE)");
  p_glEnable(GL_TEXTURE_GEN_Q); report("glEnable(GL_TEXTURE_GEN_Q)");
  p_glDisable(GL_TEXTURE_GEN_Q); drain();
  p_glActiveTexture(GL_TEXTURE0); drain();
  unsigned char rgb[64 * 64 * 3];
  memset(rgb, 128, sizeof rgb);
  p_glBindTexture(GL_TEXTURE_2D, tex[1]);
  p_glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8, 64, 64, 0, GL_RGB, GL_UNSIGNED_BYTE, rgb); report("glTexImage2D(GL_SRGB8)");
  p_glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgb); report("glTexImage2D(GL_SRGB8_ALPHA8)");
  p_glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR); drain();
  p_glGenerateMipmap(GL_TEXTURE_2D); report("glGenerateMipmap(GL_TEXTURE_2D)");
  p_glBindTexture(GL_TEXTURE_CUBE_MAP, tex[2]); report("glBindTexture(GL_TEXTURE_CUBE_MAP)");
  for (int i = 0; i < 6; i++)
    p_glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + i, 0, GL_RGB, 64, 64, 0, GL_RGB, GL_UNSIGNED_BYTE, rgb);
  report("glTexImage2D(CUBE_MAP faces, RGB 64)");
  p_glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE); report("glTexParameteri(CUBE_MAP, WRAP_R)");
  p_glGenerateMipmap(GL_TEXTURE_CUBE_MAP); report("glGenerateMipmap(GL_TEXTURE_CUBE_MAP)");
  p_glEnable(GL_TEXTURE_CUBE_MAP); report("glEnable(GL_TEXTURE_CUBE_MAP)");
  p_glDisable(GL_TEXTURE_CUBE_MAP); drain();
  p_glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR); report("glTexGeni(R, OBJECT_LINEAR)");

  /* Text: bitmaps in lists, placed with glRasterPos. */
  GLuint base = p_glGenLists(128); drain();
  static const GLubyte glyph[4] = {0xff, 0x81, 0x81, 0xff};
  p_glNewList(base + 'A', GL_COMPILE); p_glBitmap(8, 4, 0, 0, 8, 0, glyph); p_glEndList();
  report("glBitmap in glNewList");
  p_glRasterPos3f(3, 5, 0); report("glRasterPos3f");
  p_glListBase(base); p_glCallLists(1, GL_UNSIGNED_BYTE, "A"); report("glCallLists(UNSIGNED_BYTE) of glBitmap");

  /* Client arrays with GL_UNSIGNED_INT indices (skins use them from a VBO). */
  static const GLfloat v[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  static const GLuint idx[3] = {0, 1, 2};
  p_glEnableClientState(GL_VERTEX_ARRAY); p_glVertexPointer(3, GL_FLOAT, 0, v);
  p_glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, idx); report("glDrawElements(UNSIGNED_INT) client array");
  if (HAVE(glGenBuffers) && HAVE(glBindBuffer) && HAVE(glBufferData)) {
    GLuint vbo[2];
    p_glGenBuffers(2, vbo);
    p_glBindBuffer(GL_ARRAY_BUFFER, vbo[0]); p_glBufferData(GL_ARRAY_BUFFER, sizeof v, v, GL_STREAM_DRAW);
    p_glVertexPointer(3, GL_FLOAT, 0, NULL);
    p_glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, vbo[1]); p_glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx, idx, GL_STATIC_DRAW);
    p_glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, NULL); report("glDrawElements from VBOs");
    p_glBindBuffer(GL_ARRAY_BUFFER, 0); p_glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  }
  p_glDisableClientState(GL_VERTEX_ARRAY); drain();

  /* Framebuffers: the default one, MuJoCo's offscreen and shadow FBOs, the resolve. */
  if (HAVE(glBindFramebuffer) && HAVE(glCheckFramebufferStatus)) {
    p_glBindFramebuffer(GL_FRAMEBUFFER, 0);
    GLenum st = p_glCheckFramebufferStatus(GL_FRAMEBUFFER);
    printf("default framebuffer status 0x%04x\n", st); report("glCheckFramebufferStatus(0)");
  }
  if (HAVE(glGenFramebuffers) && HAVE(glRenderbufferStorageMultisample) && HAVE(glBlitFramebuffer)) {
    GLuint fbo[3], rb[4];
    p_glGenFramebuffers(3, fbo); p_glGenRenderbuffers(4, rb);
    p_glBindFramebuffer(GL_FRAMEBUFFER, fbo[0]);
    p_glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
    p_glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_RGBA8, 640, 480);
    p_glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
    p_glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
    p_glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_DEPTH24_STENCIL8, 640, 480);
    p_glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
    printf("msaa fbo status 0x%04x\n", p_glCheckFramebufferStatus(GL_FRAMEBUFFER));
    GLint s = -1; p_glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &s);
    printf("samples %d\n", s); report("4x RGBA8 + DEPTH24_STENCIL8 FBO");
    p_glBindFramebuffer(GL_FRAMEBUFFER, fbo[1]);
    p_glBindRenderbuffer(GL_RENDERBUFFER, rb[2]); p_glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 640, 480);
    p_glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[2]);
    p_glBindRenderbuffer(GL_RENDERBUFFER, rb[3]); p_glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, 640, 480);
    p_glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb[3]);
    printf("resolve fbo status 0x%04x\n", p_glCheckFramebufferStatus(GL_FRAMEBUFFER)); report("RGBA8 + DEPTH24_STENCIL8 FBO");
    p_glBindFramebuffer(GL_FRAMEBUFFER, fbo[2]);
    p_glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, tex[0], 0);
    p_glDrawBuffer(GL_NONE); p_glReadBuffer(GL_NONE);
    printf("shadow fbo status 0x%04x\n", p_glCheckFramebufferStatus(GL_FRAMEBUFFER)); report("depth-texture FBO, draw/read NONE");
    p_glBindFramebuffer(GL_FRAMEBUFFER, fbo[0]);
    p_glDrawBuffer(GL_COLOR_ATTACHMENT0); p_glReadBuffer(GL_COLOR_ATTACHMENT0); report("glDrawBuffer(COLOR_ATTACHMENT0)");
    p_glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    p_glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo[0]); p_glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo[1]);
    p_glBlitFramebuffer(0, 0, 320, 240, 0, 0, 320, 240, GL_COLOR_BUFFER_BIT, GL_NEAREST); report("glBlitFramebuffer colour resolve");
    p_glBlitFramebuffer(0, 0, 320, 240, 0, 0, 320, 240, GL_DEPTH_BUFFER_BIT, GL_NEAREST); report("glBlitFramebuffer depth resolve");
    p_glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo[1]);
    p_glPixelStorei(GL_PACK_ALIGNMENT, 1);
    static unsigned char px[320 * 240 * 3]; static float dz[320 * 240];
    p_glReadPixels(0, 0, 320, 240, GL_RGB, GL_UNSIGNED_BYTE, px); report("glReadPixels(RGB, UNSIGNED_BYTE) from FBO");
    p_glReadPixels(0, 0, 320, 240, GL_DEPTH_COMPONENT, GL_FLOAT, dz); report("glReadPixels(DEPTH_COMPONENT, FLOAT) from FBO");
    p_glBindFramebuffer(GL_FRAMEBUFFER, 0); drain();
  }
  p_glDrawBuffer(GL_FRONT); p_glReadBuffer(GL_FRONT); report("glDrawBuffer/glReadBuffer(GL_FRONT)");
  p_glPixelStorei(GL_PACK_ALIGNMENT, 1);
  static unsigned char px2[64 * 48 * 3]; static float dz2[64 * 48];
  p_glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, px2); report("glReadPixels(RGB, UNSIGNED_BYTE) window");
  p_glReadPixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, dz2); report("glReadPixels(DEPTH_COMPONENT, FLOAT) window");
  printf("done\n");
  OSMesaDestroyContext(ctx);
  free(buf);
  return 0;
}
