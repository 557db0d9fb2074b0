/* A lit frame through the OSMesa C ABI, for Mesa and softgl (not a test): a
 * GLU sphere asked for with 1000x800 slices and stacks (GLU clamps both to 239:
 * 114,242 triangles, not 1.6 M; see fill.c's `lit`), one infinite
 * light with specular, smooth, depth-tested, at 1024x1024; and the same
 * sphere unlit, to show what lighting adds.
 *   cc -O2 osmesa/bench/lit.c -o /tmp/lit -lOSMesa -lGLU
 *   LP_NUM_THREADS=1 /tmp/lit                                     # Mesa llvmpipe
 *   LD_LIBRARY_PATH=$PWD/target/release/osmesa /tmp/lit           # softgl */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glu.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
static double now(void) { struct timespec t; clock_gettime(CLOCK_MONOTONIC, &t); return t.tv_sec + t.tv_nsec * 1e-9; }
static double frame(GLUquadric *q, int frames) {
  double t0 = now();
  for (int f = 0; f < frames; f++) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gluSphere(q, 1.5, 1000, 800);
    glFinish();
  }
  return (now() - t0) * 1000 / frames;
}
int main(void) {
  int W = 1024, H = 1024;
  unsigned char *buf = malloc(W * H * 4);
  OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  OSMesaMakeCurrent(c, buf, GL_UNSIGNED_BYTE, W, H);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION); gluPerspective(40, 1, 1, 20);
  glMatrixMode(GL_MODELVIEW); gluLookAt(0, 2, 8, 0, 0, 0, 0, 1, 0);
  GLUquadric *q = gluNewQuadric();
  glColor3f(1, 0.5f, 0.2f);
  frame(q, 1);
  printf("unlit sphere 114k tris 1024x1024: %.1f ms/frame\n", frame(q, 3));
  glEnable(GL_LIGHTING); glEnable(GL_LIGHT0);
  GLfloat pos[4] = {1, 1, 1, 0}, spec[4] = {1, 1, 1, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT, GL_SHININESS, 32);
  frame(q, 1);
  printf("lit sphere 114k tris 1024x1024, 1 infinite light: %.1f ms/frame\n", frame(q, 3));
  return 0;
}
