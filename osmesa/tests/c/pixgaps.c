/* Pixel-path gaps of issue 14, against llvmpipe:
 * 0: glDrawPixels and glCopyPixels textured (a uniform texture, so that the
 *    texture coordinates do not matter: llvmpipe's unit 0 reads the image's
 *    own, GL the raster position's): MODULATE, REPLACE, DECAL, ADD, blended;
 * 1: pixel transfer (scale, bias, GL_MAP_COLOR) on glTexImage2D,
 *    glTexSubImage2D and glCopyTexImage2D uploads, drawn as textured quads;
 * then glReadPixels through scale and bias, depth scale and bias, index
 * shift and offset, printed. (Mesa's glReadPixels through GL_MAP_COLOR gave
 * different bytes in two runs of this program: maps are checked in Rust.) */
#define GL_GLEXT_PROTOTYPES
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
  case 1: {
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    GLuint t[4]; glGenTextures(4, t);
    /* Scale and bias on glTexImage2D (RGBA and RGB data, RGBA8 and RGB565-like RGB5). */
    glPixelTransferf(GL_RED_SCALE, 0.5f); glPixelTransferf(GL_GREEN_BIAS, 0.25f);
    glPixelTransferf(GL_BLUE_SCALE, 2.0f); glPixelTransferf(GL_ALPHA_BIAS, -0.125f);
    glBindTexture(GL_TEXTURE_2D, t[0]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    nearest(); tquad(0, 0, 16, 16);
    glBindTexture(GL_TEXTURE_2D, t[1]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB5, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, src + 300);
    nearest(); tquad(16, 0, 32, 16);
    /* Luminance data into a luminance texture: L scaled as red. */
    glBindTexture(GL_TEXTURE_2D, t[2]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 8, 8, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, src + 600);
    nearest(); tquad(32, 0, 48, 16);
    /* glTexSubImage2D through colour maps (sizes 8 and 4) and a bias. */
    glPixelTransferf(GL_RED_SCALE, 1); glPixelTransferf(GL_GREEN_BIAS, 0);
    glPixelTransferf(GL_BLUE_SCALE, 1); glPixelTransferf(GL_ALPHA_BIAS, 0);
    float rmap[8] = {1, 0.9f, 0.7f, 0.5f, 0.3f, 0.2f, 0.1f, 0}, gmap[4] = {0.2f, 0.8f, 0.4f, 1};
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 8, rmap); glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 4, gmap);
    glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
    glPixelTransferf(GL_BLUE_BIAS, 0.3f);
    glBindTexture(GL_TEXTURE_2D, t[0]);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 2, 5, 4, GL_RGBA, GL_UNSIGNED_BYTE, src + 1000);
    tquad(48, 0, 64, 16);
    glPixelTransferi(GL_MAP_COLOR, GL_FALSE); glPixelTransferf(GL_BLUE_BIAS, 0);
    /* glCopyTexImage2D of the framebuffer through scale and bias. */
    glPixelTransferf(GL_RED_SCALE, 0.75f); glPixelTransferf(GL_GREEN_SCALE, 1.5f);
    glPixelTransferf(GL_BLUE_BIAS, -0.2f);
    glBindTexture(GL_TEXTURE_2D, t[3]);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 4, 16, 8, 0);
    nearest(); tquad(0, 16, 32, 48);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 4, 2, 40, 4, 8, 4);
    tquad(32, 16, 64, 48);
    glPixelTransferf(GL_RED_SCALE, 1); glPixelTransferf(GL_GREEN_SCALE, 1);
    glPixelTransferf(GL_BLUE_BIAS, 0);
    glDisable(GL_TEXTURE_2D);
    glDeleteTextures(4, t);
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
  for (int k = 0; k < 2; k++) scene(k);
  /* glReadPixels through the transfer operations. */
  unsigned char ub[8 * 4]; float fl[8 * 4]; unsigned short us[8];
  glPixelTransferf(GL_RED_SCALE, 0.5f); glPixelTransferf(GL_GREEN_BIAS, 0.25f);
  glPixelTransferf(GL_ALPHA_SCALE, 0.0f); glPixelTransferf(GL_ALPHA_BIAS, 0.6f);
  glReadPixels(3, 5, 8, 1, GL_RGBA, GL_UNSIGNED_BYTE, ub);
  glReadPixels(3, 5, 8, 1, GL_RGBA, GL_FLOAT, fl);
  for (int i = 0; i < 32; i++) printf("%d%c", ub[i], i == 31 ? '\n' : ' ');
  for (int i = 0; i < 32; i++) printf("%.6f%c", fl[i], i == 31 ? '\n' : ' ');
  glReadPixels(20, 10, 8, 1, GL_BGRA, GL_UNSIGNED_BYTE, ub);
  for (int i = 0; i < 32; i++) printf("%d%c", ub[i], i == 31 ? '\n' : ' ');
  glReadPixels(20, 10, 8, 1, GL_RGB, GL_UNSIGNED_SHORT, us);
  for (int i = 0; i < 8; i++) printf("%u%c", us[i], i == 7 ? '\n' : ' ');
  glPixelTransferf(GL_RED_SCALE, 1); glPixelTransferf(GL_GREEN_BIAS, 0);
  glPixelTransferf(GL_ALPHA_SCALE, 1); glPixelTransferf(GL_ALPHA_BIAS, 0);
  /* Depth and stencil. */
  glClearDepth(0.25); glClearStencil(5);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glPixelTransferf(GL_DEPTH_SCALE, 2.0f); glPixelTransferf(GL_DEPTH_BIAS, 0.125f);
  glReadPixels(0, 0, 2, 1, GL_DEPTH_COMPONENT, GL_FLOAT, fl);
  printf("depth %.6f %.6f\n", fl[0], fl[1]);
  glPixelTransferf(GL_DEPTH_SCALE, 1.0f); glPixelTransferf(GL_DEPTH_BIAS, 0);
  glPixelTransferi(GL_INDEX_SHIFT, 2); glPixelTransferi(GL_INDEX_OFFSET, 3);
  glReadPixels(0, 0, 2, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, ub);
  printf("stencil %d %d\n", ub[0], ub[1]);
  glPixelTransferi(GL_INDEX_SHIFT, 0); glPixelTransferi(GL_INDEX_OFFSET, 0);
  printf("err %x\n", glGetError());
  /* Selection and feedback of raster positions, bitmaps and pixel rectangles. */
  glMatrixMode(GL_PROJECTION); glLoadIdentity(); glFrustum(-1, 1, -1, 1, 1, 10);
  glMatrixMode(GL_MODELVIEW); glLoadIdentity();
  static GLuint sel[64];
  glSelectBuffer(64, sel);
  glRenderMode(GL_SELECT);
  glInitNames(); glPushName(7);
  glRasterPos3f(0.2f, 0.1f, -2);
  glRasterPos3f(-0.5f, 0.3f, -5);
  glLoadName(8);
  glRasterPos3f(30, 0, -2);             /* invalid: no hit */
  glLoadName(9);
  glWindowPos3f(3, 4, 0.75f);
  glBitmap(0, 0, 0, 0, 2, 3, NULL);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, src);
  glLoadName(10);
  glBitmap(0, 0, 0, 0, 2, 3, NULL);     /* no hit: only raster positions */
  int hits = glRenderMode(GL_RENDER);
  printf("select hits %d:", hits);
  for (int i = 0; i < 12; i++) printf(" %u", sel[i]);
  printf("\n");
  static float fb[256];
  GLenum types[2] = {GL_3D_COLOR_TEXTURE, GL_4D_COLOR_TEXTURE};
  for (int t = 0; t < 2; t++) {
    glFeedbackBuffer(256, types[t], fb);
    glRenderMode(GL_FEEDBACK);
    glColor4f(0.25f, 0.5f, 0.75f, 1); glTexCoord4f(1, 2, 3, 4);
    glRasterPos4f(0.2f, 0.1f, -2, 1);
    glColor3f(1, 0, 0);
    unsigned char bits[2] = {0xff, 0x80};
    glBitmap(9, 1, 0, 0, 1.5f, -2, bits);
    glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glCopyPixels(0, 0, 3, 3, GL_COLOR);
    glPassThrough(5);
    glWindowPos2f(10, 11);
    glDrawPixels(0, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glRasterPos3f(30, 0, -2);           /* invalid: nothing */
    glBitmap(9, 1, 0, 0, 1.5f, -2, bits);
    glCopyPixels(0, 0, 3, 3, GL_COLOR);
    int n = glRenderMode(GL_RENDER);
    printf("feedback %d:", n);
    for (int i = 0; i < n; i++) printf(" %g", fb[i]);
    printf("\n");
  }
  printf("err %x\n", glGetError());
  OSMesaDestroyContext(ctx);
  printf("done\n");
  return 0;
}
