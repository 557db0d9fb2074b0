/* Line and polygon stipple: 128x128 scenes written to stipple.<k> (see
 * scene()), then the stipple state as glGet reads it, glGetPolygonStipple
 * under several pack states (stipple.get), glPushAttrib/glPopAttrib and
 * display lists, each result printed. */
#include "common.h"

#define W 128
#define H 128
static unsigned char buf[W * H * 4];
static unsigned rnd = 4242;
static float fr(void) { rnd = rnd * 1103515245u + 12345u; return (rnd >> 8) / 16777216.0f; }
static unsigned char pat[4 * 32], pat2[64 * 40];

static void rand_pattern(unsigned char *p, int n) {
  for (int i = 0; i < n; i++) p[i] = (unsigned char)(fr() * 256.0f);
}

static void vtx(float spread) {
  glColor4f(fr(), fr(), fr(), fr());
  glVertex2f(fr() * W * spread - W * (spread - 1) / 2, fr() * H * spread - H * (spread - 1) / 2);
}

static void lines(GLenum mode, int n, float spread) {
  glBegin(mode);
  for (int i = 0; i < n; i++) vtx(spread);
  glEnd();
}

static void tris(GLenum mode, int n) {
  glBegin(mode);
  for (int i = 0; i < n; i++) {
    glColor4f(fr(), fr(), fr(), fr());
    glVertex3f(fr() * W * 1.2f - 10, fr() * H * 1.2f - 10, fr() * 2 - 1);
  }
  glEnd();
}

static void scene(int k) {
  glClearColor(0.1f, 0.2f, 0.3f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION); glLoadIdentity(); glOrtho(0, W, 0, H, -1, 1);
  glMatrixMode(GL_MODELVIEW); glLoadIdentity();
  glDisable(GL_DEPTH_TEST); glDisable(GL_BLEND);
  glDisable(GL_LINE_STIPPLE); glDisable(GL_POLYGON_STIPPLE);
  glLineWidth(1);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glShadeModel(GL_SMOOTH);
  switch (k) {
  case 0: /* separate lines: the counter starts again at each */
    glEnable(GL_LINE_STIPPLE); glLineStipple(1, 0xF0F0); lines(GL_LINES, 60, 1); break;
  case 1: /* strips running past the window (clipped), factor 3 */
    glEnable(GL_LINE_STIPPLE); glLineStipple(3, 0x1C47);
    for (int i = 0; i < 6; i++) lines(GL_LINE_STRIP, 8, 1.5f);
    break;
  case 2: /* loops, factor 2; flat shading */
    glShadeModel(GL_FLAT);
    glEnable(GL_LINE_STIPPLE); glLineStipple(2, 0x00FF);
    for (int i = 0; i < 5; i++) lines(GL_LINE_LOOP, 5, 1);
    break;
  case 3: /* wide lines, strips and separate */
    glEnable(GL_LINE_STIPPLE); glLineStipple(1, 0x3333); glLineWidth(3);
    lines(GL_LINE_STRIP, 10, 1); glLineWidth(5); glLineStipple(4, 0x0F0F); lines(GL_LINES, 10, 1);
    break;
  case 4: /* triangles and a quad as lines: polygon stipple does not apply to them */
    glEnable(GL_LINE_STIPPLE); glLineStipple(2, 0xE4E4); glEnable(GL_POLYGON_STIPPLE);
    glPolygonStipple(pat);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    tris(GL_TRIANGLES, 30);
    break;
  case 5: /* perspective strips (attributes along a dash) and an all-ones pattern */
    glMatrixMode(GL_PROJECTION); glLoadIdentity(); glFrustum(-0.5, 0.5, -0.5, 0.5, 1, 12);
    glEnable(GL_LINE_STIPPLE); glLineStipple(1, 0x5F5F);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i < 20; i++) { glColor3f(fr(), fr(), fr()); glVertex3f(fr() * 4 - 2, fr() * 4 - 2, -(fr() * 9 + 1)); }
    glEnd();
    glLineStipple(1, 0xFFFF);
    glBegin(GL_LINES);
    for (int i = 0; i < 20; i++) { glColor3f(fr(), fr(), fr()); glVertex3f(fr() * 4 - 2, fr() * 4 - 2, -(fr() * 9 + 1)); }
    glEnd();
    break;
  case 6: /* stippled triangles and quads, depth test and blending */
    glEnable(GL_POLYGON_STIPPLE); glPolygonStipple(pat);
    glEnable(GL_DEPTH_TEST); glEnable(GL_BLEND); glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    tris(GL_TRIANGLES, 60); tris(GL_QUADS, 24);
    glDisable(GL_POLYGON_STIPPLE); tris(GL_TRIANGLES, 6);
    break;
  case 7: /* unpack state: LSB first, alignment 1, row length 40 bits, skips */
    glPixelStorei(GL_UNPACK_LSB_FIRST, 1); glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 40); glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
    glPolygonStipple(pat2);
    glPixelStorei(GL_UNPACK_LSB_FIRST, 0); glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0); glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glEnable(GL_POLYGON_STIPPLE);
    glRectf(3, 5, 125, 120);
    tris(GL_TRIANGLE_STRIP, 12);
    break;
  case 8: { /* display lists copy the pattern; points and lines ignore polygon stipple */
    GLuint l = glGenLists(1);
    glNewList(l, GL_COMPILE);
    glPolygonStipple(pat2);
    glLineStipple(5, 0x0FF0);
    glEndList();
    glPolygonStipple(pat);
    rand_pattern(pat2, sizeof pat2); /* the list holds the old bytes */
    glCallList(l);
    glEnable(GL_POLYGON_STIPPLE);
    tris(GL_TRIANGLES, 30);
    glEnable(GL_LINE_STIPPLE);
    lines(GL_LINE_STRIP, 12, 1);
    glPointSize(4);
    glBegin(GL_POINTS); for (int i = 0; i < 50; i++) vtx(1); glEnd();
    glDeleteLists(l, 1);
    break;
  }
  case 9: /* one long horizontal and vertical strip each: exact dash positions */
    glEnable(GL_LINE_STIPPLE); glLineStipple(1, 0x8CE7);
    glBegin(GL_LINE_STRIP); glColor3f(1, 1, 1);
    glVertex2f(0.5f, 10.5f); glVertex2f(120.5f, 10.5f); glVertex2f(120.5f, 120.5f); glVertex2f(3.3f, 60.7f);
    glEnd();
    glLineStipple(7, 0xA5A5);
    glBegin(GL_LINES); glVertex2f(2.2f, 100.1f); glVertex2f(125.7f, 90.3f); glEnd();
    break;
  }
  glFinish();
  char name[32];
  snprintf(name, sizeof name, "stipple.%d", k);
  dump(name, buf, sizeof buf);
  printf("scene %d error 0x%x\n", k, glGetError());
}

static void print_state(const char *at) {
  GLint p = -1, r = -1;
  glGetIntegerv(GL_LINE_STIPPLE_PATTERN, &p);
  glGetIntegerv(GL_LINE_STIPPLE_REPEAT, &r);
  printf("%s: pattern 0x%x repeat %d line %d polygon %d error 0x%x\n", at, p, r,
         glIsEnabled(GL_LINE_STIPPLE), glIsEnabled(GL_POLYGON_STIPPLE), glGetError());
}

int main(int argc, char **argv) {
  start(argc, argv);
  OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(c && OSMesaMakeCurrent(c, buf, GL_UNSIGNED_BYTE, W, H));
  print_state("default");
  unsigned char got[64 * 40];
  memset(got, 0x5A, sizeof got);
  glGetPolygonStipple(got);
  printf("default stipple %02x %02x %02x error 0x%x\n", got[0], got[64], got[127], glGetError());
  rand_pattern(pat, sizeof pat);
  rand_pattern(pat2, sizeof pat2);
  for (int k = 0; k < 10; k++) scene(k);

  /* Factors clamp to [1, 256]. */
  glLineStipple(0, 0x1234); print_state("factor 0");
  glLineStipple(300, 0xABCD); print_state("factor 300");
  glLineStipple(-5, 0xFFFF); print_state("factor -5");

  /* glGetPolygonStipple under pack states. */
  glPolygonStipple(pat);
  unsigned char out[4][64 * 40];
  memset(out, 0x5A, sizeof out);
  glGetPolygonStipple(out[0]);
  glPixelStorei(GL_PACK_LSB_FIRST, 1); glGetPolygonStipple(out[1]);
  glPixelStorei(GL_PACK_ALIGNMENT, 8); glPixelStorei(GL_PACK_ROW_LENGTH, 45);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 5); glPixelStorei(GL_PACK_SKIP_ROWS, 3);
  glGetPolygonStipple(out[2]);
  glPixelStorei(GL_PACK_LSB_FIRST, 0); glGetPolygonStipple(out[3]);
  glPixelStorei(GL_PACK_ALIGNMENT, 4); glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 0); glPixelStorei(GL_PACK_SKIP_ROWS, 0);
  printf("round trip %d error 0x%x\n", memcmp(out[0], pat, sizeof pat) == 0, glGetError());
  dump("stipple.get", out, sizeof out);

  /* The attribute stack. */
  glLineStipple(3, 0x1111); glEnable(GL_LINE_STIPPLE); glEnable(GL_POLYGON_STIPPLE);
  glPushAttrib(GL_LINE_BIT);
  glLineStipple(4, 0x2222); glDisable(GL_LINE_STIPPLE); glDisable(GL_POLYGON_STIPPLE);
  print_state("pushed line");
  glPopAttrib(); print_state("popped line");
  glPushAttrib(GL_ENABLE_BIT);
  glLineStipple(5, 0x3333); glDisable(GL_LINE_STIPPLE); glDisable(GL_POLYGON_STIPPLE);
  glPopAttrib(); print_state("popped enable");
  glPushAttrib(GL_POLYGON_BIT); glDisable(GL_POLYGON_STIPPLE); glPopAttrib(); print_state("popped polygon");
  glPushAttrib(GL_POLYGON_STIPPLE_BIT);
  glPolygonStipple(pat2);
  glPopAttrib();
  memset(got, 0, sizeof got); glGetPolygonStipple(got);
  printf("popped polygon stipple %d error 0x%x\n", memcmp(got, pat, sizeof pat) == 0, glGetError());

  /* Inside glBegin/glEnd. */
  glBegin(GL_POINTS); glLineStipple(1, 1); glEnd(); printf("line stipple in begin 0x%x\n", glGetError());
  glBegin(GL_POINTS); glPolygonStipple(pat); glEnd(); printf("polygon stipple in begin 0x%x\n", glGetError());
  glBegin(GL_POINTS); glGetPolygonStipple(got); glEnd(); printf("get in begin 0x%x\n", glGetError());
  print_state("end");
  OSMesaDestroyContext(c);
  printf("done\n");
  return 0;
}
