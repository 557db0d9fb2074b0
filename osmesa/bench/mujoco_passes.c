/* MuJoCo's floor passes through the OSMesa C ABI, without the framebuffer
 * objects softgl lacks so far (not a test; run by osmesa/bench/mujoco.sh).
 * The state and matrices are those of docs/mujoco-trace.txt (the `full`
 * scene's camera and lights, MuJoCo without GL_ARB_clip_control): the
 * infinite checker plane is MuJoCo's display list of 200x200 GL_QUADS
 * (glTexCoord2d + glVertex3d), drawn
 *   plane-WxH     once, lit by 3 lights, textured (256² checker, trilinear), reverse Z;
 *   floor-WxH     as a frame with two shadow lights draws it into the colour
 *                 buffer: stencil mask, base pass, two additive one-light passes;
 *   shadow-4096   as one shadow map pass draws it: a 4096² depth-only pass
 *                 (colour mask off, flat, polygon offset, the light's ortho),
 *                 into a 4096² OSMesa buffer instead of a depth texture.
 * Prints `ROW MEDIAN_MS` per row (FRAMES frames after one warm-up).
 *   cc -O2 osmesa/bench/mujoco_passes.c -o /tmp/mjp -lOSMesa -lGLU -lm
 *   /tmp/mjp [FRAMES] [SIZES]        e.g. 5 320x240,640x480 */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glu.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench.h"
#include "bench_checker.h"

static void lights(int only) {
  static const GLfloat head[4] = {0, 0, 1, 0}, sun[4] = {-0.3f, -0.2f, 1, 0}, spot[4] = {1.2f, -1, 2, 1};
  static const GLfloat dif0[4] = {0.4f, 0.4f, 0.4f, 1}, dif1[4] = {0.6f, 0.6f, 0.6f, 1}, dif2[4] = {0.5f, 0.5f, 0.4f, 1};
  static const GLfloat amb[4] = {0.1f, 0.1f, 0.1f, 1}, spec[4] = {0.3f, 0.3f, 0.3f, 1}, sdir[3] = {-0.5f, 0.4f, -1};
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, head);
  glPopMatrix();
  glLightfv(GL_LIGHT0, GL_DIFFUSE, dif0);
  glLightfv(GL_LIGHT0, GL_AMBIENT, amb);
  glLightfv(GL_LIGHT0, GL_SPECULAR, spec);
  glLightfv(GL_LIGHT1, GL_POSITION, sun);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, dif1);
  glLightfv(GL_LIGHT1, GL_SPECULAR, spec);
  glLightfv(GL_LIGHT2, GL_POSITION, spot);
  glLightfv(GL_LIGHT2, GL_DIFFUSE, dif2);
  glLightfv(GL_LIGHT2, GL_SPECULAR, spec);
  glLightfv(GL_LIGHT2, GL_SPOT_DIRECTION, sdir);
  glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, 35);
  glLightf(GL_LIGHT2, GL_SPOT_EXPONENT, 10);
  for (int i = 0; i < 3; i++) {
    if (only < 0 || only == i) glEnable(GL_LIGHT0 + i);
    else glDisable(GL_LIGHT0 + i);
  }
}

static void scene_state(void) {
  glEnable(GL_LIGHTING);
  glEnable(GL_NORMALIZE);
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GEQUAL);
  glClearDepth(0);
  glEnable(GL_CULL_FACE);
  glEnable(GL_TEXTURE_2D);
  static const GLfloat white_spec[4] = {0.5f, 0.5f, 0.5f, 1};
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, white_spec);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 64);
  glColor4f(1, 1, 1, 1);
}

static void plane(GLuint l) {
  lights(-1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glCallList(l);
}

/* The floor's share of a frame with reflection and two shadow lights (docs/mujoco.md). */
static void floor_passes(GLuint l) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glDisable(GL_DEPTH_TEST);
  glColorMask(0, 0, 0, 0);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 255);
  glStencilOp(GL_REPLACE, GL_REPLACE, GL_REPLACE);
  glCallList(l);
  glColorMask(1, 1, 1, 1);
  glDisable(GL_STENCIL_TEST);
  glEnable(GL_DEPTH_TEST);
  lights(0);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColor4f(1, 1, 1, 0.7f);
  glCallList(l);
  glBlendFunc(GL_ONE, GL_ONE);
  glColor4f(1, 1, 1, 1);
  for (int i = 1; i < 3; i++) {
    lights(i);
    glCallList(l);
  }
  glDisable(GL_BLEND);
}

static void shadow(GLuint l) {
  glClear(GL_DEPTH_BUFFER_BIT);
  glCallList(l);
}

static void time_row(const char *row, int frames, void (*f)(GLuint), GLuint l) {
  double t[64];
  if (frames > 64) frames = 64;
  for (int i = 0; i <= frames; i++) {
    double t0 = now();
    f(l);
    glFinish();
    if (i) t[i - 1] = 1000 * (now() - t0);
  }
  qsort(t, frames, sizeof t[0], cmp);
  printf("%s %.3f\n", row, t[frames / 2]);
  fflush(stdout);
}

int main(int argc, char **argv) {
  int frames = argc > 1 ? atoi(argv[1]) : 5;
  const char *sizes = argc > 2 ? argv[2] : "320x240,640x480";
  char buf[64];
  strncpy(buf, sizes, sizeof buf - 1);
  buf[sizeof buf - 1] = 0;
  for (char *s = strtok(buf, ","); s; s = strtok(NULL, ",")) {
    int w, h;
    if (sscanf(s, "%dx%d", &w, &h) != 2) return 2;
    unsigned char *px = malloc((size_t)w * h * 4);
    OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    if (!c || !OSMesaMakeCurrent(c, px, GL_UNSIGNED_BYTE, w, h)) return 1;
    checker_texture(GL_RGB);
    GLuint l = plane_list(200, 1);
    camera();
    scene_state();
    char row[64];
    snprintf(row, sizeof row, "plane-%dx%d", w, h);
    time_row(row, frames, plane, l);
    snprintf(row, sizeof row, "floor-%dx%d", w, h);
    time_row(row, frames, floor_passes, l);
    OSMesaDestroyContext(c);
    free(px);
  }
  /* A shadow map pass: the light's ortho and view (the sun of the full scene), 4096². */
  int n = 4096;
  unsigned char *px = malloc((size_t)n * n * 4);
  OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  if (!c || !OSMesaMakeCurrent(c, px, GL_UNSIGNED_BYTE, n, n)) return 1;
  GLuint l = plane_list(200, 1);
  glViewport(1, 1, n - 2, n - 2);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glScalef(1, 1, -1);
  glOrtho(-2.44245553, 2.44245553, -2.44245553, 2.44245553, 0.0244245548, 122.12278);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(-1.2, -0.8, 4, 0, 0, 0, 0, 0, 1);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GEQUAL);
  glClearDepth(0);
  glShadeModel(GL_FLAT);
  glColorMask(0, 0, 0, 0);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-16, -512);
  time_row("shadow-4096", frames, shadow, l);
  OSMesaDestroyContext(c);
  free(px);
  return 0;
}
