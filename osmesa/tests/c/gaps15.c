/* What piglit's GL 1.x tests found missing (issue 15): glMultiDrawArrays
 * and glMultiDrawElements refuse a negative count before drawing anything
 * (gl-1.4-multidrawarrays-errors); glTexSubImage with a null image still
 * reports its errors (teximage-errors); colour-index texture images go
 * through the I_TO_* pixel maps, also from a display list
 * (gl-1.1-read-pixels-after-display-list); zero-area triangles in feedback
 * through GL_EXT_vertex_array (gl-1.0-rendermode-feedback); packed
 * glReadPixels types (triangle-rasterization); GL_EXT_shadow_funcs
 * (depth-tex-compare). Prints each error, pixel and value. */
#include "common.h"
#include <GL/glext.h>

#define W 8
#define H 8
static unsigned char buf[W * H * 4];

static void pixel(const char *what, int x, int y) {
  GLubyte p[4];
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  printf("%s: %d %d %d %d\n", what, p[0], p[1], p[2], p[3]);
}

int main(int argc, char **argv) {
  start(argc, argv);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(ctx && OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
  PFNGLMULTIDRAWARRAYSPROC multi_arrays = (PFNGLMULTIDRAWARRAYSPROC)OSMesaGetProcAddress("glMultiDrawArrays");
  PFNGLMULTIDRAWELEMENTSPROC multi_elements = (PFNGLMULTIDRAWELEMENTSPROC)OSMesaGetProcAddress("glMultiDrawElements");
  CHECK(multi_arrays && multi_elements);

  /* Negative counts: nothing drawn, not even the valid first primitive. */
  static const float quad[] = {-1, -1, 1, -1, 1, 1, -1, 1};
  static const GLubyte idx[] = {0, 1, 2, 3};
  const GLvoid *idxs[2] = {idx, idx};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, quad);
  GLint first[2] = {0, 0};
  GLsizei count[2] = {4, -1};
  glClear(GL_COLOR_BUFFER_BIT);
  multi_arrays(GL_TRIANGLE_FAN, first, count, 2);
  printf("multi arrays, count -1: 0x%x\n", glGetError());
  pixel("after", 4, 4);
  multi_arrays(GL_TRIANGLE_FAN, first, count, -1);
  printf("multi arrays, primcount -1: 0x%x\n", glGetError());
  multi_arrays(0x77, first, count, 2);
  printf("multi arrays, bad mode and count: 0x%x\n", glGetError());
  multi_elements(GL_TRIANGLE_FAN, count, GL_UNSIGNED_BYTE, idxs, 2);
  printf("multi elements, count -1: 0x%x\n", glGetError());
  multi_elements(GL_TRIANGLE_FAN, count, GL_FLOAT, idxs, 2);
  printf("multi elements, bad type and count: 0x%x\n", glGetError());
  pixel("after", 4, 4);
  count[1] = 3;
  multi_arrays(GL_TRIANGLE_FAN, first, count, 2);
  printf("multi arrays, good: 0x%x\n", glGetError());
  pixel("drawn", 4, 4);
  glDisableClientState(GL_VERTEX_ARRAY);

  /* glTexSubImage with no image. */
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_FLOAT, NULL);
  printf("teximage null: 0x%x\n", glGetError());
  glTexSubImage2D(GL_TEXTURE_2D, 0, 6, 6, 100, 100, GL_RGBA, GL_FLOAT, NULL);
  printf("subimage null, too big: 0x%x\n", glGetError());
  glTexSubImage2D(GL_TEXTURE_2D, 0, -6, -6, 10, 10, GL_RGBA, GL_FLOAT, NULL);
  printf("subimage null, negative offset: 0x%x\n", glGetError());
  glTexSubImage2D(GL_TEXTURE_2D, 1, 0, 0, 8, 8, GL_RGBA, GL_FLOAT, NULL);
  printf("subimage null, no level 1: 0x%x\n", glGetError());
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 8, 8, GL_RGBA, GL_FLOAT, NULL);
  printf("subimage null, fine: 0x%x\n", glGetError());
  glTexSubImage1D(GL_TEXTURE_1D, 0, 0, 8, GL_RGBA, GL_FLOAT, NULL);
  printf("subimage 1D null, no image: 0x%x\n", glGetError());

  /* Colour indices through the I_TO_* maps (shift and offset too). */
  static const GLfloat r_map[] = {0, 1, 0.5f, 0.2f}, g_map[] = {0, 0, 1, 0.7f}, b_map[] = {1, 0, 0.25f, 0.1f},
                       a_map[] = {1, 1, 0.6f, 0.3f};
  glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 4, r_map);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 4, g_map);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 4, b_map);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 4, a_map);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, W, 0, H, -1, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  static const GLubyte bits[] = {0x8f, 0x7f, 0x70, 0xff};
  for (int k = 0; k < 4; k++) {
    glClear(GL_COLOR_BUFFER_BIT);
    glNewList(1, GL_COMPILE_AND_EXECUTE);
    glEnable(GL_TEXTURE_2D);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_COLOR_INDEX, GL_BITMAP, &bits[k]);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(0, 0);
    glTexCoord2f(1, 0); glVertex2f(W, 0);
    glTexCoord2f(1, 1); glVertex2f(W, H);
    glTexCoord2f(0, 1); glVertex2f(0, H);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glEndList();
    printf("bitmap 0x%02x: 0x%x\n", bits[k], glGetError());
    pixel("  executed", 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glCallList(1);
    pixel("  called", 1, 1);
  }
  /* A 4x2 image of byte indices (with shift 1, offset 1: 2i+1 masked by 3). */
  static const GLubyte indices[] = {0, 1, 2, 3, 3, 2, 1, 0};
  static const GLshort shorts[] = {0, 1, 2, 3, 3, 2, 1, 0};
  for (int pass = 0; pass < 3; pass++) {
    if (pass == 1) {
      glPixelTransferi(GL_INDEX_SHIFT, 1);
      glPixelTransferi(GL_INDEX_OFFSET, 1);
    }
    if (pass < 2)
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 2, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, indices);
    else
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 2, 0, GL_COLOR_INDEX, GL_SHORT, shorts);
    printf("indices pass %d: 0x%x\n", pass, glGetError());
    GLubyte tex[4 * 2 * 4];
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
    for (int i = 0; i < 8; i++) printf(" %d,%d,%d,%d", tex[4 * i], tex[4 * i + 1], tex[4 * i + 2], tex[4 * i + 3]);
    printf("\n");
  }

  /* Feedback of a zero-area triangle through GL_EXT_vertex_array's pointers
   * (rendermode-feedback): recorded as a back face. */
  typedef void (*PointerEXT)(GLint, GLenum, GLsizei, GLsizei, const GLvoid *);
  PointerEXT vertex_ext = (PointerEXT)OSMesaGetProcAddress("glVertexPointerEXT");
  PointerEXT color_ext = (PointerEXT)OSMesaGetProcAddress("glColorPointerEXT");
  CHECK(vertex_ext && color_ext);
  static const float line3[] = {1, 2, 0.4f, 1, 3, 4, 0.6f, 1, 5, 6, 0.8f, 1};
  static const float colors[] = {0.01f, 0.02f, 0.03f, 0.04f, 0.05f, 0.06f, 0.07f, 0.08f, 0.09f, 0.1f, 0.11f, 0.12f};
  vertex_ext(4, GL_FLOAT, 0, 3, line3);
  color_ext(4, GL_FLOAT, 0, 3, colors);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  static const GLenum culls[] = {0, GL_BACK, GL_FRONT};
  for (int c = 0; c < 3; c++) {
    if (culls[c]) {
      glEnable(GL_CULL_FACE);
      glCullFace(culls[c]);
    }
    GLfloat fb[64];
    glFeedbackBuffer(64, GL_3D_COLOR, fb);
    glRenderMode(GL_FEEDBACK);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    int n = glRenderMode(GL_RENDER);
    printf("feedback, cull 0x%x: %d values:", culls[c], n);
    for (int i = 0; i < n; i++) printf(" %.3f", fb[i]);
    printf(" err 0x%x\n", glGetError());
    glDisable(GL_CULL_FACE);
  }
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);

  /* glReadPixels into packed types (triangle-rasterization reads
   * GL_UNSIGNED_INT_8_8_8_8): a smooth quad, every packed type with each
   * format it takes, and one with GL_PACK_SWAP_BYTES. */
  glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_QUADS);
  glColor4f(1, 0, 0.3f, 0.1f); glVertex2f(1, 1);
  glColor4f(0, 1, 0.7f, 0.5f); glVertex2f(7, 1);
  glColor4f(0.4f, 0.2f, 1, 0.9f); glVertex2f(7, 7);
  glColor4f(0.9f, 0.6f, 0, 1); glVertex2f(1, 7);
  glEnd();
  static const struct { GLenum type; GLenum formats[2]; int bytes; } packed[] = {
    {GL_UNSIGNED_BYTE_3_3_2, {GL_RGB, GL_RGB}, 1}, {GL_UNSIGNED_BYTE_2_3_3_REV, {GL_RGB, GL_RGB}, 1},
    {GL_UNSIGNED_SHORT_5_6_5, {GL_RGB, GL_RGB}, 2}, {GL_UNSIGNED_SHORT_5_6_5_REV, {GL_RGB, GL_RGB}, 2},
    {GL_UNSIGNED_SHORT_4_4_4_4, {GL_RGBA, GL_BGRA}, 2}, {GL_UNSIGNED_SHORT_4_4_4_4_REV, {GL_RGBA, GL_BGRA}, 2},
    {GL_UNSIGNED_SHORT_5_5_5_1, {GL_RGBA, GL_BGRA}, 2}, {GL_UNSIGNED_SHORT_1_5_5_5_REV, {GL_RGBA, GL_BGRA}, 2},
    {GL_UNSIGNED_INT_8_8_8_8, {GL_RGBA, GL_BGRA}, 4}, {GL_UNSIGNED_INT_8_8_8_8_REV, {GL_RGBA, GL_BGRA}, 4},
    {GL_UNSIGNED_INT_10_10_10_2, {GL_RGBA, GL_BGRA}, 4}, {GL_UNSIGNED_INT_2_10_10_10_REV, {GL_RGBA, GL_BGRA}, 4},
  };
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  for (unsigned t = 0; t < sizeof packed / sizeof packed[0]; t++) {
    for (int f = 0; f < 2; f++) {
      if (f == 1 && packed[t].formats[1] == packed[t].formats[0]) continue;
      unsigned char out[W * H * 4];
      memset(out, 0xAB, sizeof out);
      glReadPixels(0, 0, W, H, packed[t].formats[f], packed[t].type, out);
      printf("packed 0x%x/0x%x err 0x%x:", packed[t].type, packed[t].formats[f], glGetError());
      for (int i = 0; i < W * H * packed[t].bytes; i++) printf("%02x", out[i]);
      printf("\n");
    }
  }
  unsigned char swapped[W * H * 2];
  glPixelStorei(GL_PACK_SWAP_BYTES, 1);
  glReadPixels(0, 0, W, H, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, swapped);
  glPixelStorei(GL_PACK_SWAP_BYTES, 0);
  printf("swapped 565 err 0x%x:", glGetError());
  for (int i = 0; i < W * H * 2; i++) printf("%02x", swapped[i]);
  printf("\n");
  unsigned char bad[64];
  glReadPixels(0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, bad);
  printf("565 with RGBA: 0x%x\n", glGetError());
  glReadPixels(0, 0, 2, 2, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_8_8_8_8, bad);
  printf("8888 with depth: 0x%x\n", glGetError());

  /* GL_EXT_shadow_funcs: every compare function on a depth texture
   * (depth-tex-compare): texels 0.25 (left) and 0.75 (right) against r = 0.5,
   * the red of a pixel on each side printed per function. */
  {
    static const GLfloat depths[2] = {0.25f, 0.75f};
    static const GLenum funcs[8] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 2, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depths);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    for (int f = 0; f < 8; f++) {
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, funcs[f]);
      GLint back = 0;
      glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, &back);
      glClear(GL_COLOR_BUFFER_BIT);
      glBegin(GL_QUADS);
      glTexCoord3f(0, 0, 0.5f); glVertex2f(0, 0);
      glTexCoord3f(1, 0, 0.5f); glVertex2f(W, 0);
      glTexCoord3f(1, 1, 0.5f); glVertex2f(W, H);
      glTexCoord3f(0, 1, 0.5f); glVertex2f(0, H);
      glEnd();
      GLubyte px[2][4];
      glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px[0]);
      glReadPixels(W - 2, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px[1]);
      printf("compare 0x%x (read 0x%x): %d %d err 0x%x\n", funcs[f], back, px[0][0], px[1][0], glGetError());
    }
    glDisable(GL_TEXTURE_2D);
    glDeleteTextures(1, &tex);
  }

  OSMesaDestroyContext(ctx);
  printf("done\n");
  return 0;
}
