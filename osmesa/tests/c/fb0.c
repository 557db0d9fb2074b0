/* glGetFramebufferAttachmentParameteriv on the default framebuffer (GL 3.0
 * §6.1.13), as piglit's probes call it when ARB_framebuffer_object is listed:
 * every attachment name × every pname, through GL_FRAMEBUFFER and, with an
 * object bound for drawing only, GL_READ_FRAMEBUFFER; for three visuals
 * (depth 24 + stencil 8, depth 16, no depth or stencil). Values and errors
 * printed one per line. */
#include "common.h"
#include <GL/glext.h>

static PFNGLGETFRAMEBUFFERATTACHMENTPARAMETERIVPROC GetAttachmentParameteriv;
static PFNGLGENFRAMEBUFFERSPROC GenFramebuffers;
static PFNGLBINDFRAMEBUFFERPROC BindFramebuffer;

#define LOAD(var, name) do { var = (void *)OSMesaGetProcAddress(name); CHECK(var); } while (0)

static const GLenum attachments[] = {
  GL_FRONT_LEFT, GL_FRONT_RIGHT, GL_BACK_LEFT, GL_BACK_RIGHT, GL_FRONT,
  GL_DEPTH, GL_STENCIL, GL_AUX0, GL_COLOR_ATTACHMENT0, GL_DEPTH_ATTACHMENT, 0x1234,
};
static const GLenum pnames[] = {
  GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME,
  GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING,
  GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE,
  GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE, GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE,
  GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE,
  GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, 0x1234,
};

static void queries(const char *what, GLenum target) {
  for (unsigned a = 0; a < sizeof attachments / sizeof *attachments; a++) {
    for (unsigned p = 0; p < sizeof pnames / sizeof *pnames; p++) {
      GLint v = -7;
      GetAttachmentParameteriv(target, attachments[a], pnames[p], &v);
      GLenum e = glGetError();
      printf("%s 0x%04x 0x%04x: %d 0x%04x\n", what, attachments[a], pnames[p], e ? -7 : v, e);
    }
  }
}

enum { W = 16, H = 8 };

int main(int argc, char **argv) {
  start(argc, argv);
  static unsigned char window[W * H * 4];
  static const int visuals[][2] = { { 24, 8 }, { 16, 0 }, { 0, 0 } };
  for (unsigned i = 0; i < 3; i++) {
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, visuals[i][0], visuals[i][1], 0, NULL);
    CHECK(ctx && OSMesaMakeCurrent(ctx, window, GL_UNSIGNED_BYTE, W, H));
    LOAD(GetAttachmentParameteriv, "glGetFramebufferAttachmentParameteriv");
    LOAD(GenFramebuffers, "glGenFramebuffers");
    LOAD(BindFramebuffer, "glBindFramebuffer");
    printf("visual depth %d stencil %d\n", visuals[i][0], visuals[i][1]);
    queries("fb", GL_FRAMEBUFFER);
    GLuint fbo;
    GenFramebuffers(1, &fbo);
    BindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
    queries("read", GL_READ_FRAMEBUFFER);
    BindFramebuffer(GL_FRAMEBUFFER, 0);
    OSMesaDestroyContext(ctx);
  }
  printf("done\n");
  return 0;
}
