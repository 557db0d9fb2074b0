/* Every OSMesa format and type, with OSMESA_Y_UP both ways and a padded
 * OSMESA_ROW_LENGTH: the caller's buffer after a depth-tested, blended scene
 * and glFinish, the depth buffer from OSMesaGetDepthBuffer, and glReadPixels
 * in several formats. */
#include "common.h"

#define W 61
#define H 47
#define PAD 5 /* extra pixels per row with OSMESA_ROW_LENGTH */

static void scene(void) {
  glViewport(0, 0, W, H);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
  glClearDepth(1.0);
  glClearStencil(0x5a);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glBegin(GL_TRIANGLES);
  glColor4f(1, 0, 0, 1); glVertex3f(-0.9f, -0.9f, 0.5f);
  glColor4f(0, 1, 0, 0.5f); glVertex3f(0.8f, -0.7f, -0.2f);
  glColor4f(0, 0, 1, 0.25f); glVertex3f(-0.3f, 0.9f, 0.1f);
  glEnd();
  glBegin(GL_QUADS);
  glColor4f(1, 1, 0, 1);
  glVertex3f(-0.2f, -0.5f, 0.0f); glVertex3f(0.7f, -0.5f, 0.0f);
  glVertex3f(0.7f, 0.6f, 0.0f); glVertex3f(-0.2f, 0.6f, 0.0f);
  glEnd();
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDisable(GL_DEPTH_TEST);
  glBegin(GL_TRIANGLE_STRIP);
  glColor4f(0.2f, 0.9f, 0.9f, 0.6f); glVertex2f(-1, 0.2f);
  glColor4f(0.9f, 0.1f, 0.5f, 0.3f); glVertex2f(1, 0.1f);
  glColor4f(0.5f, 0.5f, 0.5f, 0.8f); glVertex2f(-1, 0.5f);
  glColor4f(0.0f, 0.0f, 0.0f, 0.1f); glVertex2f(1, 0.7f);
  glEnd();
  glDisable(GL_BLEND);
  glPointSize(3);
  glBegin(GL_POINTS); glColor3f(1, 1, 1); glVertex2f(0.5f, -0.8f); glEnd();
  glBegin(GL_LINES); glColor3f(0, 0, 0); glVertex2f(-0.95f, 0.95f); glVertex2f(0.95f, -0.2f); glEnd();
  glFinish();
}

struct fmt { GLenum format, type; int bpp; const char *name; };

int main(int argc, char **argv) {
  start(argc, argv);
  static const struct fmt fmts[] = {
    {OSMESA_RGBA, GL_UNSIGNED_BYTE, 4, "rgba_ubyte"},
    {OSMESA_BGRA, GL_UNSIGNED_BYTE, 4, "bgra_ubyte"},
    {OSMESA_ARGB, GL_UNSIGNED_BYTE, 4, "argb_ubyte"},
    {OSMESA_RGB, GL_UNSIGNED_BYTE, 3, "rgb_ubyte"},
    {OSMESA_RGB_565, GL_UNSIGNED_SHORT_5_6_5, 2, "rgb565"},
    {OSMESA_RGBA, GL_UNSIGNED_SHORT, 8, "rgba_ushort"},
    {OSMESA_BGRA, GL_UNSIGNED_SHORT, 8, "bgra_ushort"},
    {OSMESA_ARGB, GL_UNSIGNED_SHORT, 8, "argb_ushort"},
    {OSMESA_RGB, GL_UNSIGNED_SHORT, 6, "rgb_ushort"},
    {OSMESA_RGBA, GL_FLOAT, 16, "rgba_float"},
    {OSMESA_BGRA, GL_FLOAT, 16, "bgra_float"},
    {OSMESA_ARGB, GL_FLOAT, 16, "argb_float"},
    {OSMESA_RGB, GL_FLOAT, 12, "rgb_float"},
  };
  for (unsigned i = 0; i < sizeof fmts / sizeof fmts[0]; i++) {
    const struct fmt *f = &fmts[i];
    for (int layout = 0; layout < 3; layout++) { /* y-up, y-down, y-up with row length */
      int row = layout == 2 ? W + PAD : W;
      size_t size = (size_t)row * H * f->bpp;
      unsigned char *buf = malloc(size);
      memset(buf, 0xA5, size); /* a sentinel: padding must stay untouched */
      OSMesaContext ctx = OSMesaCreateContextExt(f->format, 24, 8, 0, NULL);
      CHECK(ctx);
      CHECK(OSMesaMakeCurrent(ctx, buf, f->type, W, H));
      if (layout == 1) OSMesaPixelStore(OSMESA_Y_UP, 0);
      if (layout == 2) OSMesaPixelStore(OSMESA_ROW_LENGTH, row);
      GLint v;
      OSMesaGetIntegerv(OSMESA_Y_UP, &v); CHECK(v == (layout != 1));
      OSMesaGetIntegerv(OSMESA_ROW_LENGTH, &v); CHECK(v == (layout == 2 ? row : 0));
      OSMesaGetIntegerv(OSMESA_WIDTH, &v); CHECK(v == W);
      OSMesaGetIntegerv(OSMESA_HEIGHT, &v); CHECK(v == H);
      OSMesaGetIntegerv(OSMESA_FORMAT, &v); CHECK(v == (GLint)f->format);
      OSMesaGetIntegerv(OSMESA_TYPE, &v); CHECK(v == (GLint)f->type);
      scene();
      char name[128];
      snprintf(name, sizeof name, "%s.%d.color", f->name, layout);
      dump(name, buf, size);
      GLint cw, ch, cf; void *cb;
      CHECK(OSMesaGetColorBuffer(ctx, &cw, &ch, &cf, &cb));
      CHECK(cw == W && ch == H && cf == (GLint)f->format && cb == buf);
      if (i == 0 && layout != 2) {
        GLint dw, dh, bpv; void *db;
        CHECK(OSMesaGetDepthBuffer(ctx, &dw, &dh, &bpv, &db));
        CHECK(dw == W && dh == H && bpv == 4);
        snprintf(name, sizeof name, "depth.%d", layout);
        dump(name, db, (size_t)dw * dh * bpv);
        /* glReadPixels: RGBA/RGB/BGRA bytes, RGBA float, depth float and uint, stencil */
        static unsigned char rb[W * H * 16];
        glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, rb); dump(layout ? "read_rgba.1" : "read_rgba.0", rb, W * H * 4);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, W, H, GL_RGB, GL_UNSIGNED_BYTE, rb); dump(layout ? "read_rgb.1" : "read_rgb.0", rb, W * H * 3);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glReadPixels(3, 5, 20, 11, GL_BGRA, GL_UNSIGNED_BYTE, rb); dump(layout ? "read_bgra_sub.1" : "read_bgra_sub.0", rb, 20 * 11 * 4);
        glReadPixels(0, 0, W, H, GL_RGBA, GL_FLOAT, rb); dump(layout ? "read_float.1" : "read_float.0", rb, W * H * 16);
        glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, rb); dump(layout ? "read_depth_uint.1" : "read_depth_uint.0", rb, W * H * 4);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, rb); dump(layout ? "read_stencil.1" : "read_stencil.0", rb, W * H);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        CHECK(glGetError() == GL_NO_ERROR);
      }
      OSMesaDestroyContext(ctx);
      free(buf);
    }
  }
  /* A context without stencil: the depth buffer is plain Z24 in 32 bits. */
  {
    static unsigned char buf[W * H * 4];
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    GLint bits; glGetIntegerv(GL_DEPTH_BITS, &bits); printf("depth bits for 16 without stencil: %d\n", bits);
    scene();
    GLint dw, dh, bpv; void *db;
    CHECK(OSMesaGetDepthBuffer(ctx, &dw, &dh, &bpv, &db));
    printf("depth16 bytes per value %d\n", bpv);
    CHECK(bpv == 2);
    dump("depth16", db, (size_t)dw * dh * bpv);
    OSMesaDestroyContext(ctx);
  }
  /* No depth buffer, with or without stencil: OSMesaGetDepthBuffer answers
   * GL_FALSE and writes zeros and NULL (read after the call: C evaluates
   * printf's arguments in no fixed order). */
  for (int stencil = 0; stencil <= 8; stencil += 8) {
    static unsigned char buf[W * H * 4];
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, stencil, 0, NULL);
    CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    GLint dw = 7, dh = 7, bpv = 7; void *db = buf;
    GLboolean r = OSMesaGetDepthBuffer(ctx, &dw, &dh, &bpv, &db);
    printf("no depth, stencil %d: %d %d %d %d %d\n", stencil, r, dw, dh, bpv, db == NULL);
    OSMesaDestroyContext(ctx);
  }
  printf("done\n");
  return 0;
}
