/* Pixel-path gaps of issue 14, against llvmpipe:
 * 0: glDrawPixels and glCopyPixels textured (a uniform texture, so that the
 *    texture coordinates do not matter: llvmpipe's unit 0 reads the image's
 *    own, GL the raster position's): MODULATE, REPLACE, DECAL, ADD, blended;
 * 1: pixel transfer (scale, bias, GL_MAP_COLOR) on glTexImage2D,
 *    glTexSubImage2D and glCopyTexImage2D uploads, drawn as textured quads;
 * then glReadPixels through scale, bias and maps, printed. */
#include "common.h"
#include <GL/glext.h>

#define W 64
#define H 48
static unsigned char buf[W * H * 4];
static unsigned char src[32 * 32 * 4];
static unsigned rnd = 77;
static unsigned ri(void) { rnd = rnd * 1103515245u + 12345u; return rnd >> 8; }

static void ortho(void) {
  glMatrixMode(GL_PROJECTION); glLoadIdentity(); glOrtho(0, W, 0, H, -1, 1);
  glMatrixMode(GL_MODELVIEW); glLoadIdentity();
}

static void tquad(float x0, float y0, float x1, float y1) {
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0); glVertex2f(x0, y0); glTexCoord2f(1, 0); glVertex2f(x1, y0);
  glTexCoord2f(1, 1); glVertex2f(x1, y1); glTexCoord2f(0, 1); glVertex2f(x0, y1);
  glEnd();
}

static void nearest(void) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

static void scene(int k) {
  glClearColor(0.1f, 0.2f, 0.3f, 0.5f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  ortho();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  switch (k) {
  case 0: {
    GLuint t; glGenTextures(1, &t); glBindTexture(GL_TEXTURE_2D, t);
    unsigned char texel[4 * 4];
    for (int i = 0; i < 4; i++) { texel[4*i] = 128; texel[4*i+1] = 204; texel[4*i+2] = 64; texel[4*i+3] = 153; }
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    nearest();
    glEnable(GL_TEXTURE_2D);
    GLenum modes[4] = {GL_MODULATE, GL_REPLACE, GL_DECAL, GL_ADD};
    for (int m = 0; m < 4; m++) {
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, modes[m]);
      glRasterPos2i(2 + 15 * m, 2);
      glDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, src);
    }
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glRasterPos2i(2, 14);
    glPixelZoom(2, 1.5f);
    glDrawPixels(8, 6, GL_RGB, GL_UNSIGNED_BYTE, src + 100);
    glPixelZoom(1, 1);
    glEnable(GL_BLEND); glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glRasterPos2i(22, 14);
    glDrawPixels(10, 9, GL_RGBA, GL_UNSIGNED_BYTE, src + 400);
    glDisable(GL_BLEND);
    /* Mesa blits a plain copy, untextured (`blit_copy_pixels`): the alpha
     * test (ALWAYS) sends it down its textured path. */
    glEnable(GL_ALPHA_TEST); glAlphaFunc(GL_ALWAYS, 0);
    glRasterPos2i(36, 14);
    glCopyPixels(2, 2, 12, 10, GL_COLOR);
    glDisable(GL_ALPHA_TEST);
    glDisable(GL_TEXTURE_2D);
    glDeleteTextures(1, &t);
    break;
  }
  }
  glFinish();
  char name[32];
  snprintf(name, sizeof name, "pixgaps.%d", k);
  dump(name, buf, sizeof buf);
  printf("scene %d err %x\n", k, glGetError());
}

int main(int argc, char **argv) {
  start(argc, argv);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(ctx);
  CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
  for (int i = 0; i < (int)sizeof src; i++) src[i] = (unsigned char)ri();
  for (int k = 0; k < 1; k++) scene(k);
  OSMesaDestroyContext(ctx);
  printf("done\n");
  return 0;
}
