/* The framebuffer-object entry points the FBO benches load through
 * OSMesaGetProcAddress, as MuJoCo does (load_fbo_functions). Include after
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
