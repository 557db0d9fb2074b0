/* glGetFramebufferAttachmentParameteriv on the window framebuffer (object 0,
 * GL 3.0 section 6.1.13), as piglit's probes use it once
 * GL_ARB_framebuffer_object is listed: every pname of every window
 * "attachment" (and some that are not one), on windows with and without depth
 * and stencil and of several colour formats. Prints value and error, one line
 * per query; the test compares the lines of Mesa and softgl. */
#include "common.h"
#include <GL/glext.h>

static PFNGLGETFRAMEBUFFERATTACHMENTPARAMETERIVPROC GetAttachment;

static const struct { GLenum e; const char *name; } attachments[] = {
  {GL_FRONT, "FRONT"}, {GL_FRONT_LEFT, "FRONT_LEFT"}, {GL_FRONT_RIGHT, "FRONT_RIGHT"},
  {GL_BACK, "BACK"}, {GL_BACK_LEFT, "BACK_LEFT"}, {GL_BACK_RIGHT, "BACK_RIGHT"},
  {GL_AUX0, "AUX0"}, {GL_DEPTH, "DEPTH"}, {GL_STENCIL, "STENCIL"},
  {GL_COLOR_ATTACHMENT0, "COLOR_ATTACHMENT0"}, {GL_DEPTH_ATTACHMENT, "DEPTH_ATTACHMENT"},
  {GL_STENCIL_ATTACHMENT, "STENCIL_ATTACHMENT"}, {GL_DEPTH_STENCIL_ATTACHMENT, "DEPTH_STENCIL_ATTACHMENT"},
  {GL_FRONT_AND_BACK, "FRONT_AND_BACK"},
};

static const struct { GLenum e; const char *name; } pnames[] = {
  {GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, "OBJECT_TYPE"},
  {GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, "OBJECT_NAME"},
  {GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, "TEXTURE_LEVEL"},
  {GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE, "CUBE_MAP_FACE"},
  {GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER, "TEXTURE_LAYER"},
  {GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING, "COLOR_ENCODING"},
  {GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, "COMPONENT_TYPE"},
  {GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE, "RED_SIZE"},
  {GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE, "GREEN_SIZE"},
  {GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE, "BLUE_SIZE"},
  {GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE, "ALPHA_SIZE"},
  {GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, "DEPTH_SIZE"},
  {GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, "STENCIL_SIZE"},
  {0x1234, "bad pname"},
};

static void window(GLenum format, int depth, int stencil, GLenum type, int bpp) {
  static float buf[8 * 8 * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(format, depth, stencil, 0, NULL);
  CHECK(ctx);
  CHECK(OSMesaMakeCurrent(ctx, buf, type, 8, 8));
  (void)bpp;
  printf("window format 0x%x depth %d stencil %d type 0x%x\n", format, depth, stencil, type);
  GetAttachment = (PFNGLGETFRAMEBUFFERATTACHMENTPARAMETERIVPROC)OSMesaGetProcAddress(
      "glGetFramebufferAttachmentParameteriv");
  CHECK(GetAttachment);
  while (glGetError()) {}
  const GLenum targets[] = {GL_FRAMEBUFFER, GL_READ_FRAMEBUFFER, GL_DRAW_FRAMEBUFFER};
  for (unsigned t = 0; t < 3; t++)
    for (unsigned a = 0; a < sizeof attachments / sizeof *attachments; a++)
      for (unsigned p = 0; p < sizeof pnames / sizeof *pnames; p++) {
        GLint v = -7;
        GetAttachment(targets[t], attachments[a].e, pnames[p].e, &v);
        printf("0x%x %s %s = 0x%x error 0x%x\n", targets[t], attachments[a].name, pnames[p].name, v,
               glGetError());
      }
  GLint v = -7;
  GetAttachment(0x1234, GL_FRONT_LEFT, GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE, &v);
  printf("bad target = 0x%x error 0x%x\n", v, glGetError());
  OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  OSMesaDestroyContext(ctx);
}

int main(int argc, char **argv) {
  start(argc, argv);
  window(OSMESA_RGBA, 24, 8, GL_UNSIGNED_BYTE, 4);
  window(OSMESA_RGBA, 16, 0, GL_UNSIGNED_BYTE, 4);
  window(OSMESA_RGBA, 32, 0, GL_UNSIGNED_BYTE, 4);
  window(OSMESA_RGBA, 0, 8, GL_UNSIGNED_BYTE, 4);
  window(OSMESA_RGBA, 0, 0, GL_UNSIGNED_BYTE, 4);
  window(OSMESA_BGRA, 24, 0, GL_UNSIGNED_BYTE, 4);
  window(OSMESA_RGB, 24, 8, GL_UNSIGNED_BYTE, 3);
  window(OSMESA_RGB_565, 16, 0, GL_UNSIGNED_SHORT_5_6_5, 2);
  window(OSMESA_RGBA, 24, 8, GL_FLOAT, 16);
  printf("done\n");
  return 0;
}
