/* The framebuffer-object entry points the FBO benches load through
 * OSMesaGetProcAddress, as MuJoCo does (load_fbo_functions), and the objects
 * MuJoCo's frame renders into. Include after
 * GL/glext.h, stdio.h and stdlib.h. */

static PFNGLGENFRAMEBUFFERSPROC GenFramebuffers;
static PFNGLBINDFRAMEBUFFERPROC BindFramebuffer;
static PFNGLGENRENDERBUFFERSPROC GenRenderbuffers;
static PFNGLBINDRENDERBUFFERPROC BindRenderbuffer;
static PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC RenderbufferStorageMultisample;
static PFNGLFRAMEBUFFERRENDERBUFFERPROC FramebufferRenderbuffer;
static PFNGLFRAMEBUFFERTEXTURE2DPROC FramebufferTexture2D;
static PFNGLCHECKFRAMEBUFFERSTATUSPROC CheckFramebufferStatus;
static PFNGLBLITFRAMEBUFFERPROC BlitFramebuffer;
static PFNGLACTIVETEXTUREPROC ActiveTexture;

#define LOAD(v, name)                                                  \
  do {                                                                 \
    *(void **)&v = (void *)OSMesaGetProcAddress(name);                 \
    if (!v) {                                                          \
      fprintf(stderr, "no %s\n", name);                                \
      exit(1);                                                         \
    }                                                                  \
  } while (0)

static void load_fbo_functions(void) {
  LOAD(GenFramebuffers, "glGenFramebuffers");
  LOAD(BindFramebuffer, "glBindFramebuffer");
  LOAD(GenRenderbuffers, "glGenRenderbuffers");
  LOAD(BindRenderbuffer, "glBindRenderbuffer");
  LOAD(RenderbufferStorageMultisample, "glRenderbufferStorageMultisample");
  LOAD(FramebufferRenderbuffer, "glFramebufferRenderbuffer");
  LOAD(FramebufferTexture2D, "glFramebufferTexture2D");
  LOAD(CheckFramebufferStatus, "glCheckFramebufferStatus");
  LOAD(BlitFramebuffer, "glBlitFramebuffer");
  LOAD(ActiveTexture, "glActiveTexture");
}

/* A w×h renderbuffer of `format` with `samples` samples. */
static GLuint renderbuffer(int samples, int w, int h, GLenum format) {
  GLuint rb;
  GenRenderbuffers(1, &rb);
  BindRenderbuffer(GL_RENDERBUFFER, rb);
  RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, w, h);
  return rb;
}

/* A w×h object of RGBA8 colour and D24S8 depth-stencil renderbuffers with
 * `samples` samples, left bound (MuJoCo's offscreen and resolve objects). */
static GLuint rgba8_d24s8_object(int samples, int w, int h) {
  GLuint fbo;
  GenFramebuffers(1, &fbo);
  BindFramebuffer(GL_FRAMEBUFFER, fbo);
  FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffer(samples, w, h, GL_RGBA8));
  FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                          renderbuffer(samples, w, h, GL_DEPTH24_STENCIL8));
  if (CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) exit(3);
  return fbo;
}

/* MuJoCo's shadow map: a 4096² GL_DEPTH24_STENCIL8 texture on unit 1
 * (NEAREST, CLAMP_TO_EDGE, GL_COMPARE_R_TO_TEXTURE GEQUAL, INTENSITY) as the
 * depth of its own object (no colour); *tex names the texture. Leaves unit 0
 * active. */
static GLuint shadow_map_object(GLuint *tex) {
  GLuint fbo;
  ActiveTexture(GL_TEXTURE1);
  glGenTextures(1, tex);
  glBindTexture(GL_TEXTURE_2D, *tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 4096, 4096, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, NULL);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_GEQUAL);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_INTENSITY);
  GenFramebuffers(1, &fbo);
  BindFramebuffer(GL_FRAMEBUFFER, fbo);
  FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, *tex, 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  if (CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) exit(3);
  ActiveTexture(GL_TEXTURE0);
  return fbo;
}

/* Starts a pass into MuJoCo's shadow map `fbo` as MuJoCo does: the light's
 * orthographic view (reverse Z), the map cleared, a 1-texel border, flat
 * shading, no lighting or colour, polygon offset. */
static void begin_shadow_pass(GLuint fbo) {
  static const GLfloat light[16] = {0.959350884f, 0, -0.282216281f, 0, -0.055347167f, 0.980580747f, -0.188144207f, 0,
                                    0.276735812f, 0.196116149f, 0.940720975f, 0, -1.10694325f, -0.784464598f,
                                    -3.7628839f, 1};
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glTranslatef(0, 0, 0.5);
  glScalef(1, 1, -0.5);
  glOrtho(-2.44245553, 2.44245553, -2.44245553, 2.44245553, 0.0244245548, 122.12278);
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixf(light);
  BindFramebuffer(GL_FRAMEBUFFER, fbo);
  glDrawBuffer(GL_NONE);
  glClear(GL_DEPTH_BUFFER_BIT);
  glViewport(1, 1, 4094, 4094);
  glShadeModel(GL_FLAT);
  glDisable(GL_LIGHTING);
  glColorMask(0, 0, 0, 0);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-1.5, -4);
}
