/* glDrawPixels, glCopyPixels, glPixelZoom, glPixelTransfer and glPixelMap:
 * 96x80 scenes written to drawpix.<k> (colour), drawpix.<k>.z (depth) and
 * drawpix.<k>.s (stencil).
 * 0: colour formats and types (packed ones too) with unpack state;
 * 1: pixel zoom (integer, fractional, negative);
 * 2: scale and bias, colour maps, colour indices through the I_TO_* maps;
 * 3: depth images (depth test, the raster colour), depth scale and bias;
 * 4: stencil images (write mask, scissor, index shift and offset, S_TO_S);
 * 5: glCopyPixels of colour (overlapping), depth and stencil, with zoom;
 * 6: blending, alpha test, logic op, colour mask on an image;
 * 7: raster positions: invalid (nothing), partly off the window;
 * 8: GL_MAP_COLOR.
 * Then the pixel state as glGet and glGetPixelMap read it, and errors. */
#include "common.h"
#include <GL/glext.h>

#define W 96
#define H 80
static unsigned char buf[W * H * 4];
static unsigned rnd = 4242;
static unsigned ri(void) { rnd = rnd * 1103515245u + 12345u; return rnd >> 8; }
static unsigned char src[4096 * 4];
static float fsrc[1024 * 4];

static void ortho(void) {
  glMatrixMode(GL_PROJECTION); glLoadIdentity(); glOrtho(0, W, 0, H, -1, 1);
  glMatrixMode(GL_MODELVIEW); glLoadIdentity();
}

static void quad(float x0, float y0, float x1, float y1, float z) {
  glBegin(GL_QUADS); glVertex3f(x0, y0, z); glVertex3f(x1, y0, z); glVertex3f(x1, y1, z); glVertex3f(x0, y1, z); glEnd();
}

static void scene(int k) {
  glClearColor(0.1f, 0.2f, 0.3f, 0.5f);
  glClearDepth(1.0);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  ortho();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  switch (k) {
  case 0: {
    struct { GLenum f, t; } ft[] = {
      {GL_RGBA, GL_UNSIGNED_BYTE}, {GL_RGB, GL_UNSIGNED_BYTE}, {GL_BGRA, GL_UNSIGNED_BYTE}, {GL_BGR, GL_UNSIGNED_BYTE},
      {GL_LUMINANCE, GL_UNSIGNED_BYTE}, {GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE}, {GL_ALPHA, GL_UNSIGNED_BYTE},
      {GL_RED, GL_UNSIGNED_BYTE}, {GL_GREEN, GL_UNSIGNED_BYTE}, {GL_BLUE, GL_UNSIGNED_BYTE},
      {GL_RGB, GL_UNSIGNED_SHORT_5_6_5}, {GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4}, {GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1},
      {GL_RGB, GL_UNSIGNED_BYTE_3_3_2}, {GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV}, {GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV},
      {GL_RGBA, GL_UNSIGNED_SHORT}, {GL_RGBA, GL_BYTE}, {GL_RGBA, GL_SHORT}, {GL_RGBA, GL_UNSIGNED_INT},
      {GL_RGBA, GL_INT}, {GL_RGB, GL_UNSIGNED_SHORT_5_6_5_REV}, {GL_BGRA, GL_UNSIGNED_SHORT_1_5_5_5_REV},
      {GL_RGBA, GL_UNSIGNED_INT_8_8_8_8},
    };
    int n = sizeof ft / sizeof ft[0];
    for (int i = 0; i < n; i++) {
      glPixelStorei(GL_UNPACK_ALIGNMENT, 1 << (i % 4));
      glPixelStorei(GL_UNPACK_SKIP_PIXELS, i % 3);
      glPixelStorei(GL_UNPACK_SKIP_ROWS, i % 2);
      glPixelStorei(GL_UNPACK_ROW_LENGTH, i % 5 ? 0 : 13);
      glRasterPos2i(2 + (i % 8) * 12, 2 + (i / 8) * 14);
      glDrawPixels(11, 12, ft[i].f, ft[i].t, src);
    }
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0); glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0); glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glRasterPos2i(2, 50);
    glDrawPixels(20, 12, GL_RGBA, GL_FLOAT, fsrc);
    glRasterPos2i(30, 50);
    glDrawPixels(20, 12, GL_LUMINANCE, GL_FLOAT, fsrc);
    break;
  }
  case 1: {
    float z[][2] = {{2, 2}, {3, 1}, {0.5f, 0.5f}, {-1, 1}, {1, -2}, {-2, -1.5f}, {1.5f, 2.5f}, {0.75f, 1.25f}};
    for (int i = 0; i < 8; i++) {
      glPixelZoom(z[i][0], z[i][1]);
      glRasterPos2f(10 + (i % 4) * 24 + 0.3f, 10 + (i / 4) * 36 + 0.6f);
      glDrawPixels(9, 7, GL_RGBA, GL_UNSIGNED_BYTE, src + 400);
    }
    glPixelZoom(1, 1);
    break;
  }
  case 2: {
    glPixelTransferf(GL_RED_SCALE, 0.5f); glPixelTransferf(GL_GREEN_BIAS, 0.25f);
    glPixelTransferf(GL_BLUE_SCALE, 2.0f); glPixelTransferf(GL_ALPHA_BIAS, -0.5f);
    glRasterPos2i(4, 4);
    glDrawPixels(30, 20, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glPixelTransferf(GL_RED_SCALE, 1); glPixelTransferf(GL_GREEN_BIAS, 0);
    glPixelTransferf(GL_BLUE_SCALE, 1); glPixelTransferf(GL_ALPHA_BIAS, 0);
    float ir[4] = {1, 0, 0.5f, 0.25f}, ig[4] = {0, 1, 0.5f, 0.75f}, ib[4] = {0.2f, 0.4f, 0.6f, 0.8f}, ia[4] = {1, 1, 1, 1};
    glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 4, ir); glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 4, ig);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 4, ib); glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 4, ia);
    /* (Mesa reads GL_UNSIGNED_BYTE indices ignoring the unpack alignment
     * and the index shift and offset: not compared, docs/llvmpipe-facts.md.) */
    glRasterPos2i(40, 40);
    glDrawPixels(30, 20, GL_COLOR_INDEX, GL_UNSIGNED_SHORT, src);
    /* (GL_BITMAP images: Mesa 22.3.6 reads colour-index bitmaps right in
     * their first row only, and loops printing "Unsupported format/type" on
     * stencil ones: not compared; src/pixel_rect.rs tests them.) */
    break;
  }
  case 3: {
    static float dz[40 * 30];
    for (int i = 0; i < 40 * 30; i++) dz[i] = (i % 40) / 40.0f;
    glEnable(GL_DEPTH_TEST);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glRasterPos2i(5, 5);
    glDrawPixels(40, 30, GL_DEPTH_COMPONENT, GL_FLOAT, dz);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glColor3f(1, 0.5f, 0);
    quad(0, 0, W, H, 0); /* z 0.5: in front where the image is deeper */
    glDepthFunc(GL_ALWAYS);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glRasterPos2i(50, 40);
    glDrawPixels(40, 30, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, src);
    /* (Depth scale and bias: Mesa applies them to 16-bit images only, and
     * not as GL says: not compared, docs/llvmpipe-facts.md.) */
    glRasterPos2i(50, 5);
    glDrawPixels(40, 30, GL_DEPTH_COMPONENT, GL_FLOAT, dz);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthFunc(GL_LESS);
    glColor3f(0, 0.5f, 1);
    quad(0, 0, W, H, 0.2f);
    glDisable(GL_DEPTH_TEST);
    break;
  }
  case 4: {
    glStencilMask(0x3f);
    glRasterPos2i(3, 3);
    glDrawPixels(40, 30, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, src);
    glEnable(GL_SCISSOR_TEST); glScissor(50, 10, 30, 30);
    glStencilMask(0xff);
    /* (Mesa ignores the index shift, offset and GL_MAP_STENCIL for stencil
     * images: not compared, docs/llvmpipe-facts.md.) */
    glRasterPos2i(45, 5);
    glDrawPixels(40, 40, GL_STENCIL_INDEX, GL_UNSIGNED_SHORT, src);
    glDisable(GL_SCISSOR_TEST);
    glRasterPos2i(10, 50);
    glDrawPixels(30, 20, GL_STENCIL_INDEX, GL_FLOAT, fsrc);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_LESS, 20, 0xff); glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glColor3f(1, 1, 0);
    quad(0, 0, W, H, 0);
    glDisable(GL_STENCIL_TEST);
    break;
  }
  case 5: {
    glRasterPos2i(0, 0);
    glDrawPixels(60, 50, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glRasterPos2i(3, 2);
    glCopyPixels(0, 0, 40, 30, GL_COLOR);  /* overlapping, up and right */
    glRasterPos2i(10, 10);
    glCopyPixels(20, 20, 30, 20, GL_COLOR); /* overlapping, down and left */
    glPixelZoom(2, -1);
    glRasterPos2i(40, 79);
    glCopyPixels(5, 5, 20, 15, GL_COLOR);
    glPixelZoom(1, 1);
    glRasterPos2i(90, 70);
    glCopyPixels(85, 70, 30, 30, GL_COLOR);  /* source partly outside (those pixels land off the window) */
    /* depth and stencil copies */
    glEnable(GL_DEPTH_TEST); glDepthFunc(GL_ALWAYS);
    glColor3f(0.5f, 0.5f, 0.5f);
    glBegin(GL_TRIANGLES); glVertex3f(0, 0, -1); glVertex3f(W, 0, 1); glVertex3f(0, H, 0.5f); glEnd();
    glDepthFunc(GL_LESS);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthFunc(GL_ALWAYS);
    glRasterPos2i(30, 30);
    glCopyPixels(0, 0, 40, 40, GL_DEPTH);
    glDepthFunc(GL_LESS);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glRasterPos2i(5, 60);
    glDrawPixels(20, 15, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, src);
    glRasterPos2i(8, 58);
    glCopyPixels(5, 60, 20, 15, GL_STENCIL);
    glDisable(GL_DEPTH_TEST);
    break;
  }
  case 6:
    glEnable(GL_BLEND); glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glRasterPos2i(4, 4);
    glDrawPixels(40, 30, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glDisable(GL_BLEND);
    glEnable(GL_ALPHA_TEST); glAlphaFunc(GL_GEQUAL, 0.5f);
    glRasterPos2i(50, 4);
    glDrawPixels(40, 30, GL_RGBA, GL_UNSIGNED_BYTE, src + 100);
    glDisable(GL_ALPHA_TEST);
    glEnable(GL_COLOR_LOGIC_OP); glLogicOp(GL_XOR);
    glRasterPos2i(4, 40);
    glDrawPixels(40, 30, GL_RGBA, GL_UNSIGNED_BYTE, src + 200);
    glDisable(GL_COLOR_LOGIC_OP);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glRasterPos2i(50, 40);
    glDrawPixels(40, 30, GL_RGBA, GL_UNSIGNED_BYTE, src + 300);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    break;
  case 8: /* GL_MAP_COLOR: only red and green are compared (Mesa's blue and
           * alpha look-ups sample the image, not the maps). */
    float map[8] = {1, 0.8f, 0.6f, 0.4f, 0.2f, 0.1f, 0.05f, 0};
    float ramp[2] = {0, 1};
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 8, map);
    glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 2, ramp);
    glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 1, map);
    glPixelMapfv(GL_PIXEL_MAP_A_TO_A, 2, ramp);
    glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
    glRasterPos2i(4, 4);
    glDrawPixels(30, 20, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
    break;
  case 7:
    glRasterPos2i(10, 10);
    glRasterPos2f(-500, 10); /* invalid */
    glDrawPixels(20, 20, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glCopyPixels(0, 0, 10, 10, GL_COLOR);
    glRasterPos2f(W, H); /* just valid: draws nothing inside */
    glDrawPixels(20, 20, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glRasterPos2f(80.4f, 70.6f);  /* rounds to (80, 71), partly off the window */
    glDrawPixels(30, 30, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glRasterPos2i(0, 0);
    glBitmap(0, 0, 0, 0, -20, -30, NULL); /* the raster position moves off the window */
    glDrawPixels(40, 50, GL_RGBA, GL_UNSIGNED_BYTE, src + 64);
    { /* A display list keeps a copy of the image, with the unpack state of its compilation. */
      GLuint l = glGenLists(1);
      glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
      glNewList(l, GL_COMPILE);
      glRasterPos2i(60, 5);
      glPixelZoom(2, 2);
      glDrawPixels(9, 10, GL_RGB, GL_UNSIGNED_BYTE, src + 512);
      glPixelZoom(1, 1);
      glEndList();
      glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
      unsigned char keep[270];
      memcpy(keep, src + 512, sizeof keep);
      memset(src + 512, 0, sizeof keep);
      glCallList(l);
      memcpy(src + 512, keep, sizeof keep);
    }
    break;
  }
  glFinish();
  static float depth[W * H];
  static unsigned char stencil[W * H];
  glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
  glReadPixels(0, 0, W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil);
  char name[32];
  snprintf(name, sizeof name, "drawpix.%d", k);
  dump(name, buf, sizeof buf);
  snprintf(name, sizeof name, "drawpix.%d.z", k);
  dump(name, depth, sizeof depth);
  snprintf(name, sizeof name, "drawpix.%d.s", k);
  dump(name, stencil, sizeof stencil);
  printf("scene %d err %x\n", k, glGetError());
}

int main(int argc, char **argv) {
  start(argc, argv);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(ctx);
  CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
  for (int i = 0; i < (int)sizeof src; i++) src[i] = (unsigned char)ri();
  for (int i = 0; i < 1024 * 4; i++) fsrc[i] = (ri() % 1000) / 800.0f - 0.1f;
  for (int k = 0; k < 9; k++) scene(k);
  /* The pixel state read back. */
  glPixelZoom(2, -0.5f);
  glPixelTransferf(GL_RED_SCALE, 3); glPixelTransferf(GL_DEPTH_BIAS, 0.125f);
  glPixelTransferi(GL_INDEX_OFFSET, -2);
  float f[4]; int iv[4];
  glGetFloatv(GL_ZOOM_X, f); glGetFloatv(GL_ZOOM_Y, f + 1);
  printf("zoom %g %g\n", f[0], f[1]);
  glGetFloatv(GL_RED_SCALE, f); glGetFloatv(GL_DEPTH_BIAS, f + 1); glGetIntegerv(GL_INDEX_OFFSET, iv);
  printf("transfer %g %g %d\n", f[0], f[1], iv[0]);
  glGetIntegerv(GL_PIXEL_MAP_R_TO_R_SIZE, iv); glGetIntegerv(GL_PIXEL_MAP_I_TO_G_SIZE, iv + 1);
  glGetIntegerv(GL_PIXEL_MAP_S_TO_S_SIZE, iv + 2); glGetIntegerv(GL_MAX_PIXEL_MAP_TABLE, iv + 3);
  printf("sizes %d %d %d %d\n", iv[0], iv[1], iv[2], iv[3]);
  float m[256]; unsigned mu[256]; unsigned short ms[256];
  glGetPixelMapfv(GL_PIXEL_MAP_R_TO_R, m);
  glGetPixelMapuiv(GL_PIXEL_MAP_R_TO_R, mu);
  glGetPixelMapusv(GL_PIXEL_MAP_I_TO_G, ms);
  printf("maps %g %g %u %u %u %u\n", m[0], m[7], mu[0], mu[3], ms[0], ms[3]);
  unsigned short us[3] = {0, 32768, 65535};
  glPixelMapusv(GL_PIXEL_MAP_A_TO_A, 3, us);
  glGetPixelMapfv(GL_PIXEL_MAP_A_TO_A, m);
  printf("usv %.6f %.6f %.6f err %x\n", m[0], m[1], m[2], glGetError());
  glPushAttrib(GL_PIXEL_MODE_BIT);
  glPixelZoom(1, 1);
  glPopAttrib();
  glGetFloatv(GL_ZOOM_X, f);
  printf("popped zoom %g\n", f[0]);
  /* Errors. */
  glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 3, m); printf("npot %x\n", glGetError());
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 0, m); printf("zero %x\n", glGetError());
  glPixelMapfv(0x1234, 2, m); printf("bad map %x\n", glGetError());
  glPixelTransferf(0x1234, 1); printf("bad transfer %x\n", glGetError());
  glDrawPixels(-1, 2, GL_RGBA, GL_UNSIGNED_BYTE, src); printf("negative %x\n", glGetError());
  glDrawPixels(1, 2, 0x1234, GL_UNSIGNED_BYTE, src); printf("bad format %x\n", glGetError());
  glDrawPixels(1, 2, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, src); printf("bad packed %x\n", glGetError());
  glDrawPixels(1, 2, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT_5_6_5, src); printf("depth packed %x\n", glGetError());
  glCopyPixels(0, 0, 2, 2, 0x1234); printf("bad copy %x\n", glGetError());
  glCopyPixels(0, 0, -2, 2, GL_COLOR); printf("negative copy %x\n", glGetError());
  OSMesaDestroyContext(ctx);
  /* A context without depth and stencil buffers. */
  ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
  CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
  glDrawPixels(2, 2, GL_DEPTH_COMPONENT, GL_FLOAT, fsrc); printf("no depth %x\n", glGetError());
  glDrawPixels(2, 2, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, src); printf("no stencil %x\n", glGetError());
  glCopyPixels(0, 0, 2, 2, GL_DEPTH); printf("no depth copy %x\n", glGetError());
  OSMesaDestroyContext(ctx);
  printf("done\n");
  return 0;
}
