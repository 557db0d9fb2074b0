/* glMaterial as Mesa treats it, compared with Mesa: four 128x128 scenes in
 * one image, then the material state read back.
 * 1. glMaterial(GL_DIFFUSE) per vertex between glBegin and glEnd on a
 *    smooth-shaded strip (Mesa keeps materials as vertex attributes);
 * 2. the same in a display list, flat shaded, ambient, emission, specular and
 *    shininess per vertex, and a vertex that keeps the previous material;
 * 3. two-sided lighting with front materials per vertex (the back one
 *    constant: Mesa 22.3.6 computes a per-vertex back material's light
 *    products in red only, docs/llvmpipe-facts.md) on a strip seen from both
 *    sides;
 * 4. GL_COLOR_MATERIAL: a glMaterial of the tracked parameter is ignored
 *    (outside and inside glBegin/glEnd, directly and from a display list),
 *    the untracked ones still apply. */
#include "scenes.h"

static void print_material(const char *what, GLenum face, GLenum pname) {
  GLfloat v[4] = {-1, -1, -1, -1};
  glGetMaterialfv(face, pname, v);
  printf("%s %g %g %g %g\n", what, v[0], v[1], v[2], v[3]);
}

/* A strip of 2 * (n + 1) vertices from x = -1.4 to 1.4, material `i` given
 * by `mat(i)` before the pair of vertices i. */
static void strip(int n, void (*mat)(int)) {
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i <= n; i++) {
    float x = -1.4f + 2.8f * i / n, a = x * 0.8f;
    mat(i);
    glNormal3f(sinf(a), 0.2f, cosf(a));
    glVertex3f(x, -1, 0);
    glNormal3f(sinf(a), -0.2f, cosf(a));
    glVertex3f(x, 1, 0);
  }
  glEnd();
}

static void diffuse_ramp(int i) {
  materialv(GL_FRONT, GL_DIFFUSE, 0.1f * i, 0.9f - 0.1f * i, 0.5f, 1);
}

static void mixed(int i) {
  switch (i % 4) {
  case 0: materialv(GL_FRONT_AND_BACK, GL_AMBIENT, 0.6f, 0.1f * i, 0.2f, 1); break;
  case 1: materialv(GL_FRONT, GL_EMISSION, 0.05f * i, 0, 0.3f, 1); break;
  case 2: glMaterialf(GL_FRONT, GL_SHININESS, 8.0f * i); break;
  default: break; /* keeps the previous values */
  }
  if (i == 5) materialv(GL_FRONT, GL_SPECULAR, 0.2f, 0.9f, 0.2f, 1);
}

static void two_sided(int i) {
  materialv(GL_FRONT, GL_DIFFUSE, 0.9f, 0.1f * i, 0.1f, 1);
  materialv(GL_FRONT, GL_EMISSION, 0, 0.02f * i, 0.05f, 1);
}

static void tracked(int i) {
  glColor3f(0.2f + 0.1f * i, 0.5f, 0.3f);
  materialv(GL_FRONT, GL_DIFFUSE, 1, 0, 0, 1); /* tracked: ignored */
  materialv(GL_FRONT, GL_SPECULAR, 0.1f * i, 0.4f, 0.4f, 1);
}

int main(int argc, char **argv) {
  GLUquadric *q = begin_scenes(argc, argv);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  lightv(GL_LIGHT0, GL_POSITION, 1, 1, 2, 0);
  lightv(GL_LIGHT0, GL_SPECULAR, 1, 1, 1, 1);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 16);
  materialv(GL_FRONT_AND_BACK, GL_SPECULAR, 0.5f, 0.5f, 0.5f, 1);

  /* 1 */
  view(0);
  strip(12, diffuse_ramp);
  print_material("after strip, front diffuse", GL_FRONT, GL_DIFFUSE);
  printf("scene 1 error 0x%x\n", glGetError());

  /* 2 */
  view(1);
  glShadeModel(GL_FLAT);
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  strip(10, mixed);
  glEndList();
  materialv(GL_FRONT_AND_BACK, GL_AMBIENT, 0, 0, 0, 1);
  glCallList(list);
  glShadeModel(GL_SMOOTH);
  print_material("after list, front ambient", GL_FRONT, GL_AMBIENT);
  print_material("after list, front emission", GL_FRONT, GL_EMISSION);
  print_material("after list, front shininess", GL_FRONT, GL_SHININESS);
  materialv(GL_FRONT, GL_EMISSION, 0, 0, 0, 1);
  printf("scene 2 error 0x%x\n", glGetError());

  /* 3 */
  view(2);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
  materialv(GL_BACK, GL_DIFFUSE, 0.1f, 0.3f, 0.9f, 1);
  glRotatef(70, 0, 1, 0);
  glRotatef(40, 1, 0, 0);
  strip(8, two_sided);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 0);
  print_material("after two-sided, front diffuse", GL_FRONT, GL_DIFFUSE);
  materialv(GL_FRONT, GL_EMISSION, 0, 0, 0, 1);
  printf("scene 3 error 0x%x\n", glGetError());

  /* 4 */
  view(3);
  glColor3f(0.1f, 0.7f, 0.2f);
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT, GL_DIFFUSE);
  materialv(GL_FRONT, GL_DIFFUSE, 1, 0, 0, 1);
  print_material("tracked diffuse after glMaterial", GL_FRONT, GL_DIFFUSE);
  glNewList(list, GL_COMPILE);
  materialv(GL_FRONT, GL_DIFFUSE, 0, 0, 1, 1);
  materialv(GL_FRONT, GL_AMBIENT, 0.3f, 0.1f, 0.1f, 1);
  glEndList();
  glCallList(list);
  print_material("tracked diffuse after list", GL_FRONT, GL_DIFFUSE);
  print_material("untracked ambient after list", GL_FRONT, GL_AMBIENT);
  gluSphere(q, 0.5, 16, 12);
  glTranslatef(0, -0.6f, 0.5f);
  glScalef(1, 0.4f, 1);
  strip(6, tracked);
  print_material("tracked diffuse after strip", GL_FRONT, GL_DIFFUSE);
  print_material("untracked specular after strip", GL_FRONT, GL_SPECULAR);
  glDisable(GL_COLOR_MATERIAL);
  printf("scene 4 error 0x%x\n", glGetError());

  return end_scenes("materials.color", q);
}
