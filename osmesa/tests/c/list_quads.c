/* GL_QUADS from a display list: Mesa compiles a list's glBegin/glEnd into
 * indexed vertices (vbo/vbo_save_api.c, compile_vertex_list), so llvmpipe
 * draws them on its glDrawElements path and splits each quad (v0,v1,v3),
 * (v1,v2,v3), where the same quads drawn at once split (v0,v1,v2),(v0,v2,v3)
 * (docs/llvmpipe-facts.md §12, §37). Smooth quads whose colour differs along
 * the two diagonals show the split: per-vertex colours, and lit quads with a
 * local viewer and a spot light (MuJoCo's sphere caps). Drawn at once,
 * from a list, and compiled with GL_COMPILE_AND_EXECUTE (at once, then
 * from the list). */
#include "common.h"
#include <math.h>

#define W 96
#define H 96

static void colour_quads(void) {
  glBegin(GL_QUADS);
  glColor3f(1, 0, 0); glVertex2f(0, 0);
  glColor3f(0, 0, 0); glVertex2f(20, 0);
  glColor3f(1, 0, 0); glVertex2f(20, 20);
  glColor3f(0, 0, 0); glVertex2f(0, 20);
  glColor3f(0, 1, 0); glVertex2f(0, 24);
  glColor3f(0, 0, 1); glVertex2f(20, 24);
  glColor3f(1, 1, 1); glVertex2f(20, 40);
  glColor3f(0, 0, 1); glVertex2f(0, 40);
  glEnd();
}

/* A band of a sphere of radius 10 as quads, normals from the centre. */
static void lit_quads(void) {
  glBegin(GL_QUADS);
  for (int i = 0; i < 8; i++) {
    for (int j = 0; j < 4; j++) {
      float a[2] = {i * 0.785398f, (i + 1) * 0.785398f}, b[2] = {j * 0.35f - 0.7f, (j + 1) * 0.35f - 0.7f};
      int order[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      for (int k = 0; k < 4; k++) {
        float u = a[order[k][0]], v = b[order[k][1]];
        float n[3] = {cosf(v) * cosf(u), cosf(v) * sinf(u), sinf(v)};
        glNormal3fv(n);
        glVertex3f(10 * n[0], 10 * n[1], 10 * n[2]);
      }
    }
  }
  glEnd();
}

static void light_state(void) {
  float amb[4] = {0.1f, 0.1f, 0.1f, 1}, dif[4] = {0.4f, 0.4f, 0.4f, 1}, spe[4] = {0.5f, 0.5f, 0.5f, 1};
  float dif1[4] = {0.7f, 0.7f, 0.7f, 1}, spe1[4] = {0.3f, 0.3f, 0.3f, 1};
  float pos0[4] = {0.3f, 0.5f, 1, 0}, pos1[4] = {20, 10, 40, 1}, dir1[4] = {-0.4f, -0.2f, -0.9f, 0};
  float mspe[4] = {0.5f, 0.5f, 0.5f, 1};
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
  glLightfv(GL_LIGHT0, GL_AMBIENT, amb);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, dif);
  glLightfv(GL_LIGHT0, GL_SPECULAR, spe);
  glLightfv(GL_LIGHT0, GL_POSITION, pos0);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, dif1);
  glLightfv(GL_LIGHT1, GL_SPECULAR, spe1);
  glLightfv(GL_LIGHT1, GL_POSITION, pos1);
  glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, dir1);
  glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 10);
  glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 45);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHT1);
  glEnable(GL_NORMALIZE);
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, mspe);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 64);
}

int main(int argc, char **argv) {
  start(argc, argv);
  static unsigned char buf[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, W, 0, H, -50, 50);
  glMatrixMode(GL_MODELVIEW);
  glShadeModel(GL_SMOOTH);

  /* Per-vertex colours: at once, from a list, compile-and-execute then the list. */
  GLuint l = glGenLists(4);
  glPushMatrix(); glTranslatef(2, 2, 0); colour_quads(); glPopMatrix();
  glNewList(l, GL_COMPILE); colour_quads(); glEndList();
  glPushMatrix(); glTranslatef(26, 2, 0); glCallList(l); glPopMatrix();
  glPushMatrix(); glTranslatef(50, 2, 0);
  glNewList(l + 1, GL_COMPILE_AND_EXECUTE); colour_quads(); glEndList();
  glPopMatrix();
  glPushMatrix(); glTranslatef(74, 2, 0); glCallList(l + 1); glPopMatrix();

  /* Lit quads above them: at once and from a list (a perspective view, a local
   * viewer; scaled, so GL_NORMALIZE matters). */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1, 1, -0.5, 0.5, 2, 200);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, 7, -60);
  glScalef(0.5f, 0.5f, 0.5f);
  glEnable(GL_LIGHTING);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  light_state();
  glColor3f(0.2f, 0.7f, 0.3f);
  glPushMatrix(); glTranslatef(-14, 0, 0); glRotatef(-60, 1, 0, 0); lit_quads(); glPopMatrix();
  glNewList(l + 2, GL_COMPILE); lit_quads(); glEndList();
  glPushMatrix(); glTranslatef(14, 0, 0); glRotatef(-60, 1, 0, 0); glCallList(l + 2); glPopMatrix();
  printf("error 0x%x\n", glGetError());
  glFinish();
  dump("list_quads.color", buf, sizeof buf);
  OSMesaDestroyContext(ctx);
  printf("done\n");
  return 0;
}
