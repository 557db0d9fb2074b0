/* glRasterPos, glWindowPos and glBitmap: 96x80 scenes written to bitmaps.<k>.
 * 0: a random 8x13 font compiled into display lists (GL_UNPACK_ALIGNMENT 1 at
 *    compile time, 4 when called), text placed with glRasterPos2i and
 *    glWindowPos2i, glCallLists with a list base, colours latched per line;
 * 1: bitmaps at raster depths against a depth-tested triangle;
 * 2: blended bitmaps (the raster colour's alpha), alpha test, logic op, colour mask;
 * 3: linear and exp fog at raster positions in a perspective projection;
 * 4: a raster position far off-screen (invalid: nothing drawn, no move), one
 *    just inside the view volume, bitmaps partly off the window, moves past it;
 * 5: lit raster positions (the lit colour is latched), user clip planes;
 * 6: unpack state: LSB first, row length, skipped rows and pixels;
 * 7: scissor and stencil on bitmaps.
 * Then the raster state as glGet reads it, around glPushAttrib(GL_CURRENT_BIT). */
#include "common.h"
#include <GL/glext.h>
#include <math.h>

#define W 96
#define H 80
static unsigned char buf[W * H * 4];
static unsigned rnd = 777;
static unsigned ri(void) { rnd = rnd * 1103515245u + 12345u; return rnd >> 8; }
static unsigned char font[128][13];

typedef void (*WP2I)(int, int);
typedef void (*WP3F)(float, float, float);
static WP2I wp2i;
static WP3F wp3f;

static void pr(const char *what) {
  float v[4]; GLboolean valid; float d;
  glGetFloatv(GL_CURRENT_RASTER_POSITION, v);
  glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
  glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &d);
  printf("%s pos %.4f %.4f %.6f %.4f valid %d dist %.5f", what, v[0], v[1], v[2], v[3], valid, d);
  glGetFloatv(GL_CURRENT_RASTER_COLOR, v);
  printf(" color %.4f %.4f %.4f %.4f", v[0], v[1], v[2], v[3]);
  glGetFloatv(GL_CURRENT_RASTER_SECONDARY_COLOR, v);
  printf(" sec %.4f %.4f %.4f", v[0], v[1], v[2]);
  glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, v);
  printf(" tex %.4f %.4f %.4f %.4f err %x\n", v[0], v[1], v[2], v[3], glGetError());
}

static void ortho(void) {
  glMatrixMode(GL_PROJECTION); glLoadIdentity(); glOrtho(0, W, 0, H, -1, 1);
  glMatrixMode(GL_MODELVIEW); glLoadIdentity();
}

static void glyph(int c) { glBitmap(8, 13, 0, 2, 9, 0, font[c]); }

static void scene(int k) {
  glClearColor(0.1f, 0.2f, 0.3f, 0.5f);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  ortho();
  switch (k) {
  case 0: {
    GLuint base = glGenLists(128);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int c = 32; c < 128; c++) { glNewList(base + c, GL_COMPILE); glyph(c); glEndList(); }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glListBase(base);
    const char *lines[] = {"Hello, MuJoCo!", "fps 60.0 t=1.25", "{[(<>)]}|~`@#$", "softgl 0123456"};
    for (int i = 0; i < 4; i++) {
      glColor3f(0.2f * i + 0.3f, 1.0f - 0.2f * i, 0.5f);
      glRasterPos2i(2, H - 14 - 15 * i);
      glColor3f(0, 0, 0); /* the colour was latched at glRasterPos */
      glCallLists((GLsizei)strlen(lines[i]), GL_UNSIGNED_BYTE, lines[i]);
    }
    glColor4f(1, 1, 0, 1);
    wp2i(50, 3);
    glCallLists(5, GL_UNSIGNED_BYTE, "xyzzy");
    /* A list with a raster position and text inside. */
    GLuint l = glGenLists(1);
    glNewList(l, GL_COMPILE);
    glColor3f(1, 0.5f, 0);
    glRasterPos2f(3.7f, 4.2f);
    glCallLists(3, GL_UNSIGNED_BYTE, "abc");
    glEndList();
    glCallList(l);
    pr("text");
    break;
  }
  case 1:
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_TRIANGLES);
    glColor3f(0.8f, 0.2f, 0.2f);
    glVertex3f(0, 0, -1); glVertex3f(W, 0, 1); glVertex3f(0, H, 1);
    glEnd();
    for (int i = 0; i < 12; i++) {
      glColor3f(0.1f * i, 1, 1 - 0.05f * i);
      glRasterPos3f(4 + 7 * i, 10 + 5 * i, -1 + i * 0.18f);
      glBitmap(8, 13, 0, 0, 0, 0, font[65 + i]);
      glDepthFunc(i & 1 ? GL_LEQUAL : GL_LESS);
      glBitmap(8, 13, -8, 0, 0, 0, font[97 + i]);
    }
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    break;
  case 2:
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for (int i = 0; i < 16; i++) {
      glColor4f(1, 0.3f + 0.04f * i, 0.1f, 0.0625f * i);
      glRasterPos2i(5 * i, 3 * i);
      for (int j = 0; j < 4; j++) glBitmap(8, 13, 0, 0, 3, 2, font[40 + i + j]);
    }
    /* Mesa's bitmap cache is drawn with the state current when it is
     * emptied (a draw, clear, flush, read or scissor change): glFlush before
     * each state change, so that each bitmap runs with its own state, as GL
     * says (softgl does not copy that quirk, docs/llvmpipe-facts.md). */
    glFlush();
    glDisable(GL_BLEND);
    glEnable(GL_ALPHA_TEST); glAlphaFunc(GL_GREATER, 0.5f);
    for (int i = 0; i < 8; i++) {
      glColor4f(0, 1, 0, 0.125f * i + 0.01f);
      glRasterPos2i(60, 5 + 9 * i);
      glBitmap(8, 13, 0, 0, 0, 0, font[50 + i]);
    }
    glFlush();
    glDisable(GL_ALPHA_TEST);
    glEnable(GL_COLOR_LOGIC_OP); glLogicOp(GL_XOR);
    glColor3f(1, 1, 1);
    glRasterPos2i(70, 20);
    for (int j = 0; j < 6; j++) glBitmap(8, 13, 0, 0, 2, 3, font[60 + j]);
    glFlush();
    glDisable(GL_COLOR_LOGIC_OP);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glColor3f(1, 1, 1);
    glRasterPos2i(80, 60);
    glBitmap(8, 13, 0, 0, 0, 0, font[70]);
    glFlush();
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    break;
  case 3: {
    glMatrixMode(GL_PROJECTION); glLoadIdentity(); glFrustum(-1, 1, -1, 1, 1, 20);
    glMatrixMode(GL_MODELVIEW); glLoadIdentity();
    float fc[4] = {0.9f, 0.8f, 0.1f, 1};
    glFogfv(GL_FOG_COLOR, fc);
    glEnable(GL_FOG);
    for (int i = 0; i < 20; i++) {
      if (i < 10) { glFogi(GL_FOG_MODE, GL_LINEAR); glFogf(GL_FOG_START, 1); glFogf(GL_FOG_END, 15); }
      else { glFogi(GL_FOG_MODE, GL_EXP); glFogf(GL_FOG_DENSITY, 0.15f); }
      glColor3f(0.2f, 0.3f, 1);
      float z = -(1.5f + 0.9f * (i % 10));
      glRasterPos3f((-0.8f + 0.08f * (i % 10)) * -z, (i < 10 ? -0.6f : 0.3f) * -z, z);
      glBitmap(8, 13, 0, 0, 0, 0, font[33 + i]);
    }
    pr("fog");
    glDisable(GL_FOG);
    break;
  }
  case 4:
    glColor3f(1, 1, 1);
    glRasterPos2i(10, 10);
    glRasterPos2f(-1000, 40);
    pr("offscreen");
    glBitmap(8, 13, 0, 0, 50, 0, font[66]);
    pr("after invalid bitmap");
    glRasterPos2f(W, H);  /* on the boundary: valid */
    pr("corner");
    glBitmap(8, 13, 4, 4, 0, 0, font[67]);
    glBitmap(8, 13, 9, 9, 0, 0, font[68]);
    glRasterPos2f(0, 0);
    glBitmap(8, 13, 3, 5, 0, 0, font[69]);
    glRasterPos2f(90, 30);
    for (int j = 0; j < 4; j++) glBitmap(8, 13, 0, 0, 9, 0, font[70 + j]); /* moves past the window */
    pr("moved past");
    glRasterPos2f(W + 0.001f, 10);
    pr("just outside");
    glRasterPos4f(40, 40, 0, 0); /* w = 0 */
    pr("w0");
    glRasterPos4f(20, 20, 0, -1);
    pr("negative w");
    break;
  case 5: {
    glEnable(GL_LIGHTING); glEnable(GL_LIGHT0);
    float amb[4] = {0.2f, 0.1f, 0.1f, 1}, dif[4] = {0.3f, 0.9f, 0.4f, 1}, pos[4] = {1, 1, 1, 0};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, amb);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, dif);
    for (int i = 0; i < 8; i++) {
      glNormal3f(cosf(i * 0.4f), sinf(i * 0.4f), 0.5f);
      glRasterPos2i(4 + 11 * i, 30);
      glBitmap(8, 13, 0, 0, 0, 0, font[80 + i]);
    }
    pr("lit");
    glDisable(GL_LIGHTING);
    double plane[4] = {-1, 0, 0, 50};
    glClipPlane(GL_CLIP_PLANE0, plane);
    glEnable(GL_CLIP_PLANE0);
    glColor3f(1, 0, 1);
    for (int i = 0; i < 8; i++) {
      glRasterPos2i(4 + 11 * i, 50);
      glBitmap(8, 13, 0, 0, 0, 0, font[90 + i]);
    }
    pr("clipped");
    glDisable(GL_CLIP_PLANE0);
    break;
  }
  case 6: {
    static unsigned char big[64 * 40];
    for (int i = 0; i < (int)sizeof big; i++) big[i] = (unsigned char)ri();
    glColor3f(0.9f, 0.9f, 0.2f);
    glPixelStorei(GL_UNPACK_LSB_FIRST, 1);
    glRasterPos2i(2, 2);
    glBitmap(30, 20, 0, 0, 0, 0, big);
    glPixelStorei(GL_UNPACK_LSB_FIRST, 0);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 70);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 3);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 5);
    glColor3f(0.2f, 0.9f, 0.9f);
    glRasterPos2i(40, 2);
    glBitmap(37, 25, 0, 0, 0, 0, big);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 11);
    glColor3f(1, 0.4f, 0.7f);
    glRasterPos2i(10, 40);
    glBitmap(70, 30, 0, 0, 0, 0, big);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    break;
  }
  case 7:
    glEnable(GL_SCISSOR_TEST); glScissor(10, 10, 50, 40);
    glColor3f(1, 1, 1);
    glRasterPos2i(5, 5);
    for (int j = 0; j < 8; j++) glBitmap(8, 13, 0, 0, 7, 5, font[100 + j]);
    glDisable(GL_SCISSOR_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xff); glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    glColor3f(0.3f, 0.3f, 1);
    glRasterPos2i(50, 50);
    for (int j = 0; j < 3; j++) glBitmap(8, 13, 0, 0, 2, 1, font[110 + j]);
    glStencilFunc(GL_EQUAL, 1, 0xff); glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glBegin(GL_QUADS); glColor3f(1, 0.5f, 0);
    glVertex2i(40, 40); glVertex2i(80, 40); glVertex2i(80, 80); glVertex2i(40, 80); glEnd();
    glDisable(GL_STENCIL_TEST);
    break;
  }
  glFinish();
  char name[32];
  snprintf(name, sizeof name, "bitmaps.%d", k);
  dump(name, buf, sizeof buf);
}

int main(int argc, char **argv) {
  start(argc, argv);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(ctx);
  CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
  wp2i = (WP2I)OSMesaGetProcAddress("glWindowPos2i");
  wp3f = (WP3F)OSMesaGetProcAddress("glWindowPos3f");
  CHECK(wp2i && wp3f);
  for (int c = 0; c < 128; c++)
    for (int r = 0; r < 13; r++) font[c][r] = (unsigned char)ri();
  pr("initial");
  for (int k = 0; k < 8; k++) scene(k);
  /* Queries, the attribute stack, window positions, texture coordinates. */
  ortho();
  glColor4f(0.25f, 0.5f, 0.75f, 1);
  glTexCoord4f(1, 2, 3, 4);
  glRasterPos3f(10.5f, 20.25f, 0.5f);
  pr("plain");
  glPushAttrib(GL_CURRENT_BIT);
  wp3f(3.5f, -7.25f, 2.0f);
  pr("window pos");
  glPopAttrib();
  pr("popped");
  glMatrixMode(GL_TEXTURE); glLoadIdentity(); glScalef(2, 3, 4); glMatrixMode(GL_MODELVIEW);
  glRasterPos2i(1, 2);
  pr("texture matrix");
  glMatrixMode(GL_TEXTURE); glLoadIdentity(); glMatrixMode(GL_MODELVIEW);
  glDepthRange(0.25, 0.75);
  wp3f(1, 2, 0.5f);
  pr("window depth range");
  glRasterPos3f(1, 2, 0.5f);
  pr("depth range");
  glBegin(GL_POINTS); glRasterPos2i(1, 1); glEnd();
  printf("inside begin err %x\n", glGetError());
  glBitmap(-1, 2, 0, 0, 0, 0, font[0]);
  printf("negative err %x\n", glGetError());
  OSMesaDestroyContext(ctx);
  printf("done\n");
  return 0;
}
