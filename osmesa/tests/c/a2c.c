/* GL_SAMPLE_ALPHA_TO_COVERAGE and GL_SAMPLE_ALPHA_TO_ONE in a 4x RGBA8 +
 * DEPTH24_STENCIL8 framebuffer object, resolved by glBlitFramebuffer into a
 * single-sampled one and read back, against llvmpipe. Scenes (a2c.<k>):
 * 0: alpha to coverage on smooth alpha gradients and flat alphas of exactly
 *    0, 0.25, 0.5, 0.75 and 1 (llvmpipe keeps sample s when alpha > s/4);
 * 1: with alpha to one and blending (SRC_ALPHA, ONE_MINUS_SRC_ALPHA);
 * 2: with the depth test: the killed samples write no depth (a quad
 *    behind shows through them);
 * 3: textured alpha (MODULATE), alpha test, GL_MULTISAMPLE off (no effect);
 * 4: bitmaps (alpha above 0.5 keeps them) and alpha to one alone;
 * 5: GL_MULTISAMPLE off after multisampled drawing: depth and stencil in
 *    sample 0 only;
 * 6: pixel rectangles (alpha above 0.5 keeps them, as bitmaps), zoomed,
 *    with alpha to one and blending, alpha from pixel transfer. */
#define GL_GLEXT_PROTOTYPES
#include "common.h"
#include <GL/glext.h>

enum { W = 64, H = 48 };
static unsigned char buf[W * H * 4];
static unsigned char out[W * H * 4];

static GLuint fbo(int samples) {
  GLuint fb, rb[2];
  glGenFramebuffers(1, &fb);
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glGenRenderbuffers(2, rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, W, H);
  glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH24_STENCIL8, W, H);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
  CHECK(glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE);
  return fb;
}

static void gradient(float x0, float y0, float x1, float y1, float a0, float a1) {
  glBegin(GL_QUADS);
  glColor4f(0.9f, 0.3f, 0.1f, a0); glVertex2f(x0, y0);
  glColor4f(0.2f, 0.8f, 0.4f, a1); glVertex2f(x1, y0);
  glColor4f(0.1f, 0.4f, 0.9f, a1); glVertex2f(x1, y1);
  glColor4f(0.7f, 0.7f, 0.2f, a0); glVertex2f(x0, y1);
  glEnd();
}

static void flats(float y0, float y1) {
  for (int i = 0; i < 5; i++) {
    glColor4f(1, 1, 1, 0.25f * i);
    glBegin(GL_TRIANGLES);
    glVertex2f(2 + 12 * i, y0); glVertex2f(12 + 12 * i, y0 + 1); glVertex2f(5 + 12 * i, y1);
    glEnd();
  }
}

static void scene(int k, GLuint ms, GLuint single) {
  glBindFramebuffer(GL_FRAMEBUFFER, ms);
  glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
  glClearDepth(1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION); glLoadIdentity(); glOrtho(0, W, 0, H, -1, 1);
  glMatrixMode(GL_MODELVIEW); glLoadIdentity();
  glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  switch (k) {
  case 0:
    gradient(1, 1, 63, 20, 0, 1);
    gradient(1, 22, 40, 30, 0.3f, 0.55f);
    flats(32, 47);
    break;
  case 1:
    glEnable(GL_SAMPLE_ALPHA_TO_ONE);
    glEnable(GL_BLEND); glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gradient(1, 1, 63, 20, 0, 1);
    flats(32, 47);
    glDisable(GL_SAMPLE_ALPHA_TO_ONE);
    gradient(1, 22, 63, 30, 0.1f, 0.9f);
    glDisable(GL_BLEND);
    break;
  case 2:
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_TRIANGLES);
    glColor4f(1, 0, 0, 0.2f); glVertex3f(2, 2, 0.5f);
    glColor4f(1, 0, 0, 0.9f); glVertex3f(60, 10, 0.5f);
    glColor4f(1, 0, 0, 0.6f); glVertex3f(20, 45, 0.5f);
    glEnd();
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glColor4f(0, 1, 0, 1);
    glBegin(GL_QUADS);
    glVertex3f(0, 0, -0.1f); glVertex3f(64, 0, -0.1f); glVertex3f(64, 48, -0.1f); glVertex3f(0, 48, -0.1f);
    glEnd();
    glDisable(GL_DEPTH_TEST);
    break;
  case 3: {
    GLuint t; glGenTextures(1, &t); glBindTexture(GL_TEXTURE_2D, t);
    unsigned char tex[8 * 4];
    for (int i = 0; i < 8; i++) { tex[4*i] = 200; tex[4*i+1] = 30 * i; tex[4*i+2] = 90; tex[4*i+3] = 36 * i + 3; }
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glEnable(GL_TEXTURE_2D);
    glColor4f(1, 1, 1, 0.9f);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(1, 1); glTexCoord2f(1, 0); glVertex2f(63, 1);
    glTexCoord2f(1, 1); glVertex2f(63, 20); glTexCoord2f(0, 1); glVertex2f(1, 20);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glDeleteTextures(1, &t);
    glEnable(GL_ALPHA_TEST); glAlphaFunc(GL_GREATER, 0.3f);
    gradient(1, 22, 63, 30, 0, 1);
    glDisable(GL_ALPHA_TEST);
    glDisable(GL_MULTISAMPLE);
    flats(32, 47);
    glEnable(GL_MULTISAMPLE);
    break;
  }
  case 4: {
    static const GLubyte glyph[8] = {0x18, 0x3c, 0x66, 0x66, 0x7e, 0x66, 0x66, 0xff};
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    float alphas[4] = {0.4f, 0.5f, 0.6f, 1.0f};
    for (int i = 0; i < 4; i++) {
      glColor4f(1, 1, 0, alphas[i]);
      glRasterPos2i(4 + 14 * i, 4);
      glBitmap(8, 8, 0, 0, 0, 0, glyph);
    }
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glEnable(GL_SAMPLE_ALPHA_TO_ONE);
    glEnable(GL_BLEND); glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    flats(20, 45);
    glDisable(GL_BLEND);
    glDisable(GL_SAMPLE_ALPHA_TO_ONE);
    break;
  }
  case 6: {
    /* Pixel rectangles: drawn with multisampling off in llvmpipe's
     * rasterizer state, as bitmaps: alpha above 0.5 keeps them whole. */
    static unsigned char img[32 * 6 * 4];
    for (int y = 0; y < 6; y++)
      for (int x = 0; x < 32; x++) {
        unsigned char *p = img + 4 * (32 * y + x);
        p[0] = 8 * x; p[1] = 200 - 30 * y; p[2] = 90; p[3] = x == 16 ? 128 : x == 15 ? 127 : 8 * x + y;
      }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glRasterPos2i(2, 2);
    glDrawPixels(32, 6, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glPixelZoom(1.5f, 2.0f);
    glRasterPos2i(2, 10);
    glDrawPixels(32, 6, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glPixelZoom(1, 1);
    glEnable(GL_SAMPLE_ALPHA_TO_ONE);
    glEnable(GL_BLEND); glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glRasterPos2i(2, 26);
    glDrawPixels(32, 6, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glDisable(GL_BLEND);
    glDisable(GL_SAMPLE_ALPHA_TO_ONE);
    /* Colour from the current raster colour's alpha: GL_LUMINANCE images. */
    static unsigned char lum[16 * 4];
    for (int i = 0; i < 64; i++) lum[i] = 4 * i;
    glPixelTransferf(GL_ALPHA_SCALE, 0.0f);
    glPixelTransferf(GL_ALPHA_BIAS, 0.6f);
    glRasterPos2i(40, 30);
    glDrawPixels(16, 4, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);
    glPixelTransferf(GL_ALPHA_BIAS, 0.4f);
    glRasterPos2i(40, 36);
    glDrawPixels(16, 4, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);
    glPixelTransferf(GL_ALPHA_SCALE, 1.0f);
    glPixelTransferf(GL_ALPHA_BIAS, 0.0f);
    break;
  }
  case 5:
    /* Multisampled drawing leaves the samples' depths apart (edges, a
     * steep depth slope); with GL_MULTISAMPLE off llvmpipe tests and writes
     * depth and stencil in sample 0 only, colour in every sample. */
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xff); glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex3f(3, 2, -0.9f); glVertex3f(61, 9, 0.9f); glVertex3f(17, 46, 0.9f);
    glColor3f(0, 0, 1); glVertex3f(40, 3, 0.9f); glVertex3f(63, 40, -0.9f); glVertex3f(30, 44, -0.2f);
    glEnd();
    glDisable(GL_MULTISAMPLE);
    glStencilFunc(GL_EQUAL, 1, 0xff); glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    glColor3f(0, 1, 0);
    glBegin(GL_QUADS);
    glVertex3f(0, 0, 0); glVertex3f(64, 0, 0); glVertex3f(64, 48, 0); glVertex3f(0, 48, 0);
    glEnd();
    glDisable(GL_STENCIL_TEST);
    glColor3f(1, 1, 0);
    glBegin(GL_TRIANGLES);
    glVertex3f(0, 20, 0.5f); glVertex3f(64, 24, -0.5f); glVertex3f(10, 47, 0.1f);
    glEnd();
    glEnable(GL_MULTISAMPLE);
    glColor3f(1, 1, 1);
    glBegin(GL_TRIANGLES);
    glVertex3f(5, 30, -0.3f); glVertex3f(60, 35, 0.3f); glVertex3f(30, 5, 0.05f);
    glEnd();
    glDisable(GL_DEPTH_TEST);
    break;
  }
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, ms);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, single);
  glBlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, single);
  glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, out);
  char name[32];
  snprintf(name, sizeof name, "a2c.%d", k);
  dump(name, out, sizeof out);
  printf("scene %d err %x\n", k, glGetError());
}

int main(int argc, char **argv) {
  start(argc, argv);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(ctx);
  CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
  GLuint ms = fbo(4), single = fbo(0);
  for (int k = 0; k < 7; k++) scene(k, ms, single);
  OSMesaDestroyContext(ctx);
  printf("done\n");
  return 0;
}
