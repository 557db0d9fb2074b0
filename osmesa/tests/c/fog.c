/* Fog and the colour sum: 128x128 scenes of random perspective, depth-tested
 * triangles, each written to fog.<k>: LINEAR, EXP, EXP2, glFogCoord with EXP,
 * the colour sum alone, LINEAR + colour sum, flat-shaded EXP2 + colour sum,
 * end == start, EXP with SRC_ALPHA blending, points and wide lines with LINEAR
 * fog, density 1e6 then 0. Then the fog state as glGet reads it. */
#include "common.h"
#include <GL/glext.h>

#define W 128
#define H 128
static unsigned char buf[W * H * 4];
static unsigned rnd = 12345;
static float fr(void) { rnd = rnd * 1103515245u + 12345u; return (rnd >> 8) / 16777216.0f; }
typedef void (*SC3F)(float, float, float);
typedef void (*FC1F)(float);
static SC3F sc3f;
static FC1F fc1f;

static void tris(int n, int fogc, int sec) {
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < n * 3; i++) {
    glColor4f(fr(), fr(), fr(), fr());
    if (sec) sc3f(fr(), fr(), fr());
    if (fogc) fc1f(fr() * 12.0f - 1.0f);
    glVertex3f(fr() * 2.4f - 1.2f, fr() * 2.4f - 1.2f, -(fr() * 9.0f + 1.0f));
  }
  glEnd();
}

static void scene(int k) {
  glClearColor(0.1f, 0.2f, 0.3f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION); glLoadIdentity(); glFrustum(-0.5, 0.5, -0.5, 0.5, 1, 12);
  glMatrixMode(GL_MODELVIEW); glLoadIdentity();
  glEnable(GL_DEPTH_TEST);
  float fc[4] = {0.7f, 0.5f, 0.9f, 0.3f};
  glFogfv(GL_FOG_COLOR, fc);
  glEnable(GL_FOG);
  glDisable(GL_COLOR_SUM);
  glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
  glShadeModel(GL_SMOOTH);
  switch (k) {
  case 0: glFogi(GL_FOG_MODE, GL_LINEAR); glFogf(GL_FOG_START, 2); glFogf(GL_FOG_END, 9); tris(60, 0, 0); break;
  case 1: glFogi(GL_FOG_MODE, GL_EXP); glFogf(GL_FOG_DENSITY, 0.25f); tris(60, 0, 0); break;
  case 2: glFogi(GL_FOG_MODE, GL_EXP2); glFogf(GL_FOG_DENSITY, 0.2f); tris(60, 0, 0); break;
  case 3: glFogi(GL_FOG_MODE, GL_EXP); glFogf(GL_FOG_DENSITY, 0.3f); glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD); tris(60, 1, 0); break;
  case 4: glDisable(GL_FOG); glEnable(GL_COLOR_SUM); tris(60, 0, 1); break;
  case 5: glFogi(GL_FOG_MODE, GL_LINEAR); glFogf(GL_FOG_START, 1); glFogf(GL_FOG_END, 11); glEnable(GL_COLOR_SUM); tris(60, 0, 1); break;
  case 6: glFogi(GL_FOG_MODE, GL_EXP2); glFogf(GL_FOG_DENSITY, 0.15f); glShadeModel(GL_FLAT); glEnable(GL_COLOR_SUM); tris(60, 0, 1); break;
  case 7: glFogi(GL_FOG_MODE, GL_LINEAR); glFogf(GL_FOG_START, 5); glFogf(GL_FOG_END, 5); tris(60, 0, 0); break;
  case 8: glFogi(GL_FOG_MODE, GL_EXP); glFogf(GL_FOG_DENSITY, 0.2f); glEnable(GL_BLEND);
          glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA); tris(60, 0, 0); glDisable(GL_BLEND); break;
  case 9:
    glFogi(GL_FOG_MODE, GL_LINEAR); glFogf(GL_FOG_START, 0); glFogf(GL_FOG_END, 10);
    glPointSize(5);
    glBegin(GL_POINTS);
    for (int i = 0; i < 200; i++) { glColor3f(fr(), fr(), fr()); glVertex3f(fr() * 2 - 1, fr() * 2 - 1, -(fr() * 9 + 1)); }
    glEnd();
    glLineWidth(2);
    glBegin(GL_LINES);
    for (int i = 0; i < 100; i++) { glColor3f(fr(), fr(), fr()); glVertex3f(fr() * 2 - 1, fr() * 2 - 1, -(fr() * 9 + 1)); }
    glEnd();
    break;
  case 10: glFogi(GL_FOG_MODE, GL_EXP); glFogf(GL_FOG_DENSITY, 1e6f); tris(30, 0, 0);
           glFogf(GL_FOG_DENSITY, 0); tris(30, 0, 0); break;
  }
  glFinish();
  char name[32];
  snprintf(name, sizeof name, "fog.%d", k);
  dump(name, buf, sizeof buf);
}

int main(int argc, char **argv) {
  start(argc, argv);
  OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(c && OSMesaMakeCurrent(c, buf, GL_UNSIGNED_BYTE, W, H));
  sc3f = (SC3F)OSMesaGetProcAddress("glSecondaryColor3f");
  fc1f = (FC1F)OSMesaGetProcAddress("glFogCoordf");
  CHECK(sc3f && fc1f);
  for (int k = 0; k < 11; k++) scene(k);
  GLfloat f[4];
  GLint i;
  glGetIntegerv(GL_FOG_MODE, &i); printf("mode 0x%x\n", i);
  glGetFloatv(GL_FOG_DENSITY, f); printf("density %g\n", f[0]);
  glGetFloatv(GL_FOG_START, f); printf("start %g\n", f[0]);
  glGetFloatv(GL_FOG_END, f); printf("end %g\n", f[0]);
  glGetFloatv(GL_FOG_COLOR, f); printf("color %g %g %g %g\n", f[0], f[1], f[2], f[3]);
  glGetIntegerv(GL_FOG_COORD_SRC, &i); printf("coord src 0x%x\n", i);
  printf("fog %d colour sum %d\n", glIsEnabled(GL_FOG), glIsEnabled(GL_COLOR_SUM));
  glFogf(GL_FOG_DENSITY, -1); printf("negative density 0x%x\n", glGetError());
  glFogi(GL_FOG_MODE, GL_LINE); printf("bad mode 0x%x\n", glGetError());
  printf("error 0x%x\n", glGetError());
  OSMesaDestroyContext(c);
  printf("done\n");
  return 0;
}
