/* ARB_depth_buffer_float and ARB_clip_control, as MuJoCo uses them (reverse Z
 * into a DEPTH32F_STENCIL8 renderbuffer with glClipControl(GL_LOWER_LEFT,
 * GL_ZERO_TO_ONE)) and around: their queries and errors, GL_UPPER_LEFT's
 * flip and facing, polygon offset on float depth, glReadPixels of float
 * depth (GL_FLOAT, GL_UNSIGNED_INT, both DEPTH_STENCIL types), depth
 * blits (and the error when depth formats differ), glDrawPixels and
 * glCopyPixels of depth, a DEPTH_COMPONENT32F texture uploaded, read back,
 * rendered into and sampled with compare, the raster position. Results are
 * written to files, state and errors printed. */
#define GL_GLEXT_PROTOTYPES
#include "common.h"
#include <GL/glext.h>
#include <math.h>

static PFNGLGENFRAMEBUFFERSPROC GenFramebuffers;
static PFNGLBINDFRAMEBUFFERPROC BindFramebuffer;
static PFNGLCHECKFRAMEBUFFERSTATUSPROC CheckFramebufferStatus;
static PFNGLFRAMEBUFFERTEXTURE2DPROC FramebufferTexture2D;
static PFNGLGENRENDERBUFFERSPROC GenRenderbuffers;
static PFNGLBINDRENDERBUFFERPROC BindRenderbuffer;
static PFNGLRENDERBUFFERSTORAGEPROC RenderbufferStorage;
static PFNGLFRAMEBUFFERRENDERBUFFERPROC FramebufferRenderbuffer;
static PFNGLGETRENDERBUFFERPARAMETERIVPROC GetRenderbufferParameteriv;
static PFNGLBLITFRAMEBUFFERPROC BlitFramebuffer;
static PFNGLCLIPCONTROLPROC ClipControl;

#define LOAD(var, name) do { var = (void *)OSMesaGetProcAddress(name); CHECK(var); } while (0)
#define E(call) do { call; printf("%-90s 0x%04x\n", #call, glGetError()); } while (0)

enum { W = 64, H = 48, N = 8 };

static void clip_state(const char *what) {
  GLint o = -1, d = -1;
  glGetIntegerv(GL_CLIP_ORIGIN, &o);
  glGetIntegerv(GL_CLIP_DEPTH_MODE, &d);
  printf("clip %-40s origin 0x%04x depth 0x%04x 0x%04x\n", what, o, d, glGetError());
}

/* A colour + DEPTH32F_STENCIL8 (or `depth`) renderbuffer object of W x H. */
static GLuint make_fbo(GLenum depth) {
  GLuint fb, rb[2];
  GenFramebuffers(1, &fb);
  BindFramebuffer(GL_FRAMEBUFFER, fb);
  GenRenderbuffers(2, rb);
  BindRenderbuffer(GL_RENDERBUFFER, rb[0]);
  RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, W, H);
  FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
  BindRenderbuffer(GL_RENDERBUFFER, rb[1]);
  RenderbufferStorage(GL_RENDERBUFFER, depth, W, H);
  GLenum at = (depth == GL_DEPTH_COMPONENT32F) ? GL_DEPTH_ATTACHMENT : GL_DEPTH_STENCIL_ATTACHMENT;
  FramebufferRenderbuffer(GL_FRAMEBUFFER, at, GL_RENDERBUFFER, rb[1]);
  GLint d = -1, s = -1, bits = -1, type = -1, stype = -1;
  PFNGLGETFRAMEBUFFERATTACHMENTPARAMETERIVPROC GetAttachment =
      (void *)OSMesaGetProcAddress("glGetFramebufferAttachmentParameteriv");
  GetAttachment(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &type);
  if (at == GL_DEPTH_STENCIL_ATTACHMENT)
    GetAttachment(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &stype);
  printf("fbo 0x%04x component types 0x%04x 0x%04x 0x%04x\n", depth, type, stype, glGetError());
  GetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_DEPTH_SIZE, &d);
  GetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_STENCIL_SIZE, &s);
  glGetIntegerv(GL_DEPTH_BITS, &bits);
  printf("fbo 0x%04x status 0x%04x depth %d stencil %d DEPTH_BITS %d 0x%04x\n", depth,
         CheckFramebufferStatus(GL_FRAMEBUFFER), d, s, bits, glGetError());
  return fb;
}

/* MuJoCo's reverse-Z perspective: a frustum, then z' = 0.5 w - 0.5 z (near
 * at 1, far at 0 with GL_ZERO_TO_ONE). `zero_to_one` 0: plain GL. */
static void projection(int reverse) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  if (reverse) {
    glTranslatef(0, 0, 0.5f);
    glScalef(1, 1, -0.5f);
  }
  glFrustum(-1, 1, -0.75, 0.75, 1, 1000);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

/* Overlapping sloped triangles at depths from near to very far, one facing
 * away (clockwise), a quad crossing the near plane. */
static void scene(void) {
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0); glVertex3f(-2, -1.5, -2); glVertex3f(2, -1, -3); glVertex3f(0, 2, -2.5);
  glColor3f(0, 1, 0); glVertex3f(-3, 1, -1.5); glVertex3f(1, -2, -5); glVertex3f(2, 2, -4);
  glColor3f(0, 0, 1); glVertex3f(-400, -300, -900); glVertex3f(400, -300, -800); glVertex3f(0, 300, -990);
  glColor3f(1, 1, 0); glVertex3f(-40, -30, -100.5); glVertex3f(40, -30, -100); glVertex3f(0, 30, -100.25);
  /* clockwise */
  glColor3f(1, 0, 1); glVertex3f(-1, 0.5, -1.2); glVertex3f(0, -0.5, -1.2); glVertex3f(-1.5, -0.5, -1.2);
  glEnd();
  glBegin(GL_QUADS);
  glColor3f(0, 1, 1); glVertex3f(0.2, -0.6, -0.5); glVertex3f(1, -0.6, -0.5); glVertex3f(1, 0.6, -3); glVertex3f(0.2, 0.6, -3);
  glEnd();
}

static void read_all(const char *name) {
  static unsigned char rgba[W * H * 4];
  static float z[W * H];
  static GLuint zi[W * H], ds[W * H], ds2[W * H * 2];
  glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_FLOAT, z);
  glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, zi);
  glReadPixels(0, 0, W, H, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, ds);
  glReadPixels(0, 0, W, H, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, ds2);
  char n[256];
  snprintf(n, sizeof n, "%s.rgba", name); dump(n, rgba, sizeof rgba);
  snprintf(n, sizeof n, "%s.zf", name); dump(n, z, sizeof z);
  snprintf(n, sizeof n, "%s.zui", name); dump(n, zi, sizeof zi);
  snprintf(n, sizeof n, "%s.ds", name); dump(n, ds, sizeof ds);
  snprintf(n, sizeof n, "%s.ds2", name); dump(n, ds2, sizeof ds2);
  printf("read %-30s 0x%04x\n", name, glGetError());
}

int main(int argc, char **argv) {
  start(argc, argv);
  static unsigned char window[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(ctx && OSMesaMakeCurrent(ctx, window, GL_UNSIGNED_BYTE, W, H));
  LOAD(GenFramebuffers, "glGenFramebuffers");
  LOAD(BindFramebuffer, "glBindFramebuffer");
  LOAD(CheckFramebufferStatus, "glCheckFramebufferStatus");
  LOAD(FramebufferTexture2D, "glFramebufferTexture2D");
  LOAD(GenRenderbuffers, "glGenRenderbuffers");
  LOAD(BindRenderbuffer, "glBindRenderbuffer");
  LOAD(RenderbufferStorage, "glRenderbufferStorage");
  LOAD(FramebufferRenderbuffer, "glFramebufferRenderbuffer");
  LOAD(GetRenderbufferParameteriv, "glGetRenderbufferParameteriv");
  LOAD(BlitFramebuffer, "glBlitFramebuffer");
  LOAD(ClipControl, "glClipControl");
  const char *ext = (const char *)glGetString(GL_EXTENSIONS);
  printf("GL_ARB_clip_control %d GL_ARB_depth_buffer_float %d\n", strstr(ext, "GL_ARB_clip_control ") != NULL,
         strstr(ext, "GL_ARB_depth_buffer_float ") != NULL);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);

  /* 1. glClipControl: defaults, errors, lists, the attribute stack. */
  clip_state("default");
  E(ClipControl(GL_UPPER_LEFT + 5, GL_ZERO_TO_ONE));
  E(ClipControl(GL_LOWER_LEFT, GL_LOWER_LEFT));
  E(ClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE));
  glBegin(GL_TRIANGLES);
  ClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
  glEnd();
  printf("%-90s 0x%04x\n", "ClipControl inside glBegin", glGetError());
  clip_state("after errors");
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  ClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
  glEndList();
  clip_state("compiled, not run");
  glCallList(list);
  clip_state("list called");
  glPushAttrib(GL_TRANSFORM_BIT);
  E(ClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE));
  glPopAttrib();
  clip_state("popped TRANSFORM_BIT");
  glPushAttrib(GL_VIEWPORT_BIT);
  E(ClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE));
  glPopAttrib();
  clip_state("popped VIEWPORT_BIT");
  E(ClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE));

  /* 2. The raster position and glWindowPos under each mode. */
  GLfloat rp[4];
  projection(0);
  for (int mode = 0; mode < 4; mode++) {
    ClipControl(mode & 1 ? GL_UPPER_LEFT : GL_LOWER_LEFT, mode & 2 ? GL_ZERO_TO_ONE : GL_NEGATIVE_ONE_TO_ONE);
    GLboolean valid;
    glRasterPos3f(0.25f, 0.5f, -2.0f);
    glGetFloatv(GL_CURRENT_RASTER_POSITION, rp);
    glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
    printf("rasterpos mode %d %.9g %.9g %.9g %.9g valid %d\n", mode, rp[0], rp[1], rp[2], rp[3], valid);
    /* Between the two near planes: z_clip in (-w, 0) */
    glMatrixMode(GL_PROJECTION); glPushMatrix(); glLoadIdentity();
    glRasterPos4f(0, 0, -0.5f, 1);
    glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
    glGetFloatv(GL_CURRENT_RASTER_POSITION, rp);
    printf("rasterpos mode %d z=-0.5: valid %d z %.9g\n", mode, valid, rp[2]);
    glPopMatrix(); glMatrixMode(GL_MODELVIEW);
    glWindowPos3f(3, 4, 0.25f);
    glGetFloatv(GL_CURRENT_RASTER_POSITION, rp);
    printf("windowpos mode %d %.9g %.9g %.9g\n", mode, rp[0], rp[1], rp[2]);
  }
  ClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);

  /* 3. MuJoCo's path: reverse Z, float depth, GEQUAL, cleared to 0. */
  GLuint fbf = make_fbo(GL_DEPTH32F_STENCIL8);
  glViewport(0, 0, W, H);
  E(ClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE));
  projection(1);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GEQUAL);
  glClearDepth(0);
  glClearColor(0.1f, 0.2f, 0.3f, 1);
  glClearStencil(0x35);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  scene();
  read_all("reverse");

  /* 4. The same through GL_UPPER_LEFT, back faces culled. */
  E(ClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE));
  glEnable(GL_CULL_FACE);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  scene();
  read_all("upper");
  glDisable(GL_CULL_FACE);

  /* 5. Polygon offset on float depth (MuJoCo's shadow offset), and a depth
   * range. */
  E(ClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE));
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-1.5f, -4);
  glDepthRange(0.125, 0.875);
  scene();
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDepthRange(0, 1);
  read_all("offset");

  /* 6. Plain GL depth mode into the float buffer, LESS from 1. */
  E(ClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE));
  projection(0);
  glDepthFunc(GL_LESS);
  glClearDepth(1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  scene();
  read_all("plain");

  /* 7. Depth blits: float to float exact; float to 24-bit an error. */
  GLuint fbf2 = make_fbo(GL_DEPTH_COMPONENT32F);
  GLuint fb24 = make_fbo(GL_DEPTH24_STENCIL8);
  BindFramebuffer(GL_READ_FRAMEBUFFER, fbf);
  BindFramebuffer(GL_DRAW_FRAMEBUFFER, fbf2);
  glClearDepth(0.75);
  glClear(GL_DEPTH_BUFFER_BIT);
  E(BlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_DEPTH_BUFFER_BIT, GL_NEAREST));
  E(BlitFramebuffer(0, 0, W / 2, H / 2, W / 2, H / 2, W, H, GL_DEPTH_BUFFER_BIT, GL_NEAREST));
  BindFramebuffer(GL_DRAW_FRAMEBUFFER, fb24);
  E(BlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_DEPTH_BUFFER_BIT, GL_NEAREST));
  BindFramebuffer(GL_FRAMEBUFFER, fbf2);
  {
    static float z[W * H];
    glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_FLOAT, z);
    dump("blit.zf", z, sizeof z);
  }

  /* 8. glDrawPixels of float depth (out of range values clamped) and
   * glCopyPixels of depth, into the float buffer. */
  {
    static float src[16 * 12], z[W * H];
    for (int i = 0; i < 16 * 12; i++) src[i] = (float)i / 150.0f - 0.1f;
    src[3] = 1e-30f; src[4] = 0.333333343f;
    glDepthFunc(GL_ALWAYS);
    glClearDepth(0.5);
    glClear(GL_DEPTH_BUFFER_BIT);
    glWindowPos2i(5, 7);
    E(glDrawPixels(16, 12, GL_DEPTH_COMPONENT, GL_FLOAT, src));
    glWindowPos2i(30, 20);
    E(glCopyPixels(3, 5, 20, 16, GL_DEPTH));
    glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_FLOAT, z);
    dump("pixels.zf", z, sizeof z);
  }

  /* 9. A DEPTH_COMPONENT32F texture: uploaded floats (clamped), read back,
   * rendered into on an FBO and sampled with compare. */
  {
    static float src[N * N], back[N * N];
    static GLuint backui[N * N];
    for (int i = 0; i < N * N; i++) src[i] = (float)i / 50.0f - 0.2f;
    src[5] = 0.1f; src[6] = 1e-20f;
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    E(glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, N, N, 0, GL_DEPTH_COMPONENT, GL_FLOAT, src));
    GLint d = -1, f = -1;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &d);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &f);
    printf("texture depth %d internal 0x%04x 0x%04x\n", d, f, glGetError());
    E(glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, back));
    dump("tex.get.zf", back, sizeof back);
    E(glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, backui));
    dump("tex.get.zui", backui, sizeof backui);

    GLuint shadow, sfb;
    glGenTextures(1, &shadow);
    glBindTexture(GL_TEXTURE_2D, shadow);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, 128, 128, 0, GL_DEPTH_COMPONENT, GL_FLOAT, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    GenFramebuffers(1, &sfb);
    BindFramebuffer(GL_FRAMEBUFFER, sfb);
    FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, shadow, 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    printf("shadow fbo status 0x%04x 0x%04x\n", CheckFramebufferStatus(GL_FRAMEBUFFER), glGetError());
    {
      GLint type = -1;
      PFNGLGETFRAMEBUFFERATTACHMENTPARAMETERIVPROC GetAttachment =
          (void *)OSMesaGetProcAddress("glGetFramebufferAttachmentParameteriv");
      GetAttachment(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &type);
      printf("shadow fbo depth component type 0x%04x 0x%04x\n", type, glGetError());
    }
    glViewport(0, 0, 128, 128);
    ClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    projection(1);
    glDepthFunc(GL_GEQUAL);
    glClearDepth(0);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(-1.5f, -4);
    scene();
    glDisable(GL_POLYGON_OFFSET_FILL);
    {
      static float z[128 * 128];
      glBindTexture(GL_TEXTURE_2D, shadow);
      glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, z);
      dump("shadow.zf", z, sizeof z);
    }
    /* Sample it with compare onto the window: a screen-filling quad whose
     * texture r sweeps the depths. */
    BindFramebuffer(GL_FRAMEBUFFER, 0);
    glDrawBuffer(GL_FRONT);
    ClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glViewport(0, 0, W, H);
    glDisable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION); glLoadIdentity(); glMatrixMode(GL_MODELVIEW); glLoadIdentity();
    glBindTexture(GL_TEXTURE_2D, shadow);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_GEQUAL);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glBegin(GL_QUADS);
    glTexCoord3f(0, 0, 0.0f); glVertex2f(-1, -1);
    glTexCoord3f(1, 0, 0.5f); glVertex2f(1, -1);
    glTexCoord3f(1, 1, 1.0f); glVertex2f(1, 1);
    glTexCoord3f(0, 1, 0.5f); glVertex2f(-1, 1);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    static unsigned char rgba[W * H * 4];
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    dump("shadow.sampled", rgba, sizeof rgba);
    printf("shadow sampled 0x%04x\n", glGetError());
    /* References outside [0, 1] (a float texture's are not clamped) and the
     * border (neither), with GEQUAL and LESS. */
    static const GLfloat border[4] = {1.25f, 0.5f, 0.5f, 1};
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
    glEnable(GL_TEXTURE_2D);
    for (int k = 0; k < 2; k++) {
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, k ? GL_LESS : GL_GEQUAL);
      glBegin(GL_QUADS);
      glTexCoord3f(-0.25f, -0.25f, -0.5f); glVertex2f(-1, -1);
      glTexCoord3f(1.25f, -0.25f, 0.5f); glVertex2f(1, -1);
      glTexCoord3f(1.25f, 1.25f, 1.5f); glVertex2f(1, 1);
      glTexCoord3f(-0.25f, 1.25f, 1.3f); glVertex2f(-1, 1);
      glEnd();
      glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
      dump(k ? "shadow.outside.less" : "shadow.outside.gequal", rgba, sizeof rgba);
    }
    glDisable(GL_TEXTURE_2D);
    printf("shadow outside 0x%04x\n", glGetError());
  }

  /* 10. GL_FLOAT_32_UNSIGNED_INT_24_8_REV uploads: DEPTH32F_STENCIL8 and
   * DEPTH24_STENCIL8 textures read back both ways, and glDrawPixels of it. */
  {
    static GLuint src[N * N * 2], back[N * N * 2], back24[N * N];
    for (int i = 0; i < N * N; i++) {
      float z = (float)i / 60.0f - 0.05f;
      memcpy(&src[2 * i], &z, 4);
      src[2 * i + 1] = 0xabcdef00u | (GLuint)(i * 7 + 1);
    }
    GLenum formats[2] = {GL_DEPTH32F_STENCIL8, GL_DEPTH24_STENCIL8};
    for (int k = 0; k < 2; k++) {
      GLuint tex;
      glGenTextures(1, &tex);
      glBindTexture(GL_TEXTURE_2D, tex);
      E(glTexImage2D(GL_TEXTURE_2D, 0, formats[k], N, N, 0, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, src));
      GLint d = -1, s = -1;
      glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &d);
      glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_STENCIL_SIZE, &s);
      printf("texture 0x%04x depth %d stencil %d 0x%04x\n", formats[k], d, s, glGetError());
      E(glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, back));
      E(glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, back24));
      dump(k ? "tex24.get.ds2" : "tex32f.get.ds2", back, sizeof back);
      dump(k ? "tex24.get.ds" : "tex32f.get.ds", back24, sizeof back24);
    }
    BindFramebuffer(GL_FRAMEBUFFER, fbf);
    glDrawBuffer(GL_COLOR_ATTACHMENT0);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glViewport(0, 0, W, H);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glClearDepth(0.5);
    glClearStencil(0x11);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glWindowPos2i(9, 3);
    E(glDrawPixels(N, N, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, src));
    static GLuint ds2[W * H * 2];
    glReadPixels(0, 0, W, H, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, ds2);
    dump("drawpix.ds2", ds2, sizeof ds2);
    printf("drawpix 0x%04x\n", glGetError());
  }

  /* 11. Format/type errors of the float depth-stencil transfer type. */
  {
    static GLuint buf[16];
    BindFramebuffer(GL_FRAMEBUFFER, fbf);
    E(glReadPixels(0, 0, 2, 2, GL_DEPTH_COMPONENT, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, buf));
    E(glReadPixels(0, 0, 2, 2, GL_RGBA, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, buf));
    E(glReadPixels(0, 0, 2, 2, GL_DEPTH_STENCIL, GL_FLOAT, buf));
  }
  printf("done\n");
  OSMesaDestroyContext(ctx);
  return 0;
}
