/* The fixed cost of a draw through the C ABI: N glBegin/glEnd quads placed
 * outside the view volume (every one culled, nothing rasterized), then
 * glFinish. Count instructions, not time (not a test):
 *   cc -O2 osmesa/bench/quads.c -o /tmp/quads -lOSMesa
 *   LD_LIBRARY_PATH=$PWD/target/release/osmesa valgrind --tool=callgrind --callgrind-out-file=/dev/null /tmp/quads 10000
 *   (the same with 20000; the difference / 10000 is the instructions a quad) */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdlib.h>
int main(int argc, char **argv){
  int n = argc > 1 ? atoi(argv[1]) : 20000;
  unsigned char *buf = malloc(64*64*4);
  OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  if (!c || !OSMesaMakeCurrent(c, buf, GL_UNSIGNED_BYTE, 64, 64)) return 1;
  for (int i = 0; i < n; i++) {
    glBegin(GL_QUADS);
    glVertex3f(0, 0, 5); glVertex3f(1, 0, 5); glVertex3f(1, 1, 5); glVertex3f(0, 1, 5);
    glEnd();
  }
  glFinish();
  return glGetError() != GL_NO_ERROR;
}
