/* Four 128x128 scenes side by side in one 256x256 RGBA image, each in its own
 * viewport under the same perspective camera (the lighting and clip plane
 * clients; the test compares each quarter with Mesa's). */
#include "common.h"
#include <GL/glu.h>
#include <math.h>

#define W 256
#define H 256

static unsigned char scene_buf[W * H * 4];
static OSMesaContext scene_ctx;

static __attribute__((unused)) void lightv(GLenum l, GLenum p, float a, float b, float c, float d) {
  GLfloat v[4] = {a, b, c, d};
  glLightfv(l, p, v);
}

static __attribute__((unused)) void materialv(GLenum f, GLenum p, float a, float b, float c, float d) {
  GLfloat v[4] = {a, b, c, d};
  glMaterialfv(f, p, v);
}

/* Viewport quarter `i` (0 bottom left .. 3 top right), camera reset. */
static void view(int i) {
  glViewport((i % 2) * W / 2, (i / 2) * H / 2, W / 2, H / 2);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, 1.0, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0, 0.5, 5, 0, 0, 0, 0, 1, 0);
}

/* A context drawing into scene_buf, cleared, depth-tested; a quadric. */
static GLUquadric *begin_scenes(int argc, char **argv) {
  start(argc, argv);
  scene_ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(scene_ctx);
  CHECK(OSMesaMakeCurrent(scene_ctx, scene_buf, GL_UNSIGNED_BYTE, W, H));
  glClearColor(0.05f, 0.05f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  GLUquadric *q = gluNewQuadric();
  CHECK(q);
  return q;
}

/* Writes the image to `file` and ends the program's output. */
static int end_scenes(const char *file, GLUquadric *q) {
  glFinish();
  dump(file, scene_buf, sizeof scene_buf);
  gluDeleteQuadric(q);
  OSMesaDestroyContext(scene_ctx);
  printf("done\n");
  return 0;
}
