/* Stiff lighting cases compared with Mesa, four 128x128 scenes in one image:
 * 1. shininess 0 with an attenuated positional light (llvmpipe's LIT then
 *    raises N.L to the power N.L), two-sided;
 * 2. spot exponent 128 and GL_RESCALE_NORMAL under glScalef(2, 2, 2);
 * 3. normals of length 1e-20 (no GL_NORMALIZE) and 1e20 (GL_NORMALIZE);
 * 4. a rotated modelview (Mesa lights in object space), two infinite lights,
 *    per-vertex colours into the diffuse material, glScalef(1, 1, 1). */
#include "scenes.h"

static void strip(float scale) {
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i <= 16; i++) {
    float t = -1.5f + i * 0.1875f, a = t * 1.2f;
    glNormal3f(scale * sinf(a), 0, scale * cosf(a));
    glVertex3f(t, -1, 0);
    glNormal3f(scale * sinf(a), 0.3f * scale, scale * cosf(a));
    glVertex3f(t, 1, 0);
  }
  glEnd();
}

int main(int argc, char **argv) {
  GLUquadric *q = begin_scenes(argc, argv);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  GLfloat spec[4] = {1, 1, 1, 1};
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);

  /* 1 */
  view(0);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
  lightv(GL_LIGHT0, GL_POSITION, 0.5f, 1, 2, 1);
  glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 0.5f);
  glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0.1f);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 0);
  gluSphere(q, 1.2, 24, 16);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 0);
  printf("scene 1 error 0x%x\n", glGetError());

  /* 2 */
  view(1);
  lightv(GL_LIGHT0, GL_POSITION, 0, 0, 4, 1);
  lightv(GL_LIGHT0, GL_SPOT_DIRECTION, 0, 0, -1, 0);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 30);
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 128);
  glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 1);
  glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0);
  glMaterialf(GL_FRONT, GL_SHININESS, 128);
  glEnable(GL_RESCALE_NORMAL);
  glScalef(2, 2, 2);
  gluSphere(q, 0.6, 24, 16);
  glDisable(GL_RESCALE_NORMAL);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180);
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 0);
  printf("scene 2 error 0x%x\n", glGetError());

  /* 3 */
  view(2);
  lightv(GL_LIGHT0, GL_POSITION, 1, 1, 2, 0);
  glMaterialf(GL_FRONT, GL_SHININESS, 20);
  glPushMatrix();
  glTranslatef(0, 0.6f, 0);
  glScalef(1, 0.5f, 1);
  strip(1e-20f);
  glPopMatrix();
  glEnable(GL_NORMALIZE);
  glTranslatef(0, -0.6f, 0);
  glScalef(1, 0.5f, 1);
  strip(1e20f);
  glDisable(GL_NORMALIZE);
  printf("scene 3 error 0x%x\n", glGetError());

  /* 4 */
  view(3);
  glEnable(GL_LIGHT1);
  lightv(GL_LIGHT1, GL_POSITION, -1, 0.5f, 1, 0);
  lightv(GL_LIGHT1, GL_DIFFUSE, 0.3f, 0.3f, 0.6f, 1);
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT, GL_DIFFUSE);
  glRotatef(30, 0, 1, 0);
  glRotatef(20, 1, 0, 0);
  glScalef(1, 1, 1);
  glBegin(GL_QUADS);
  for (int i = 0; i < 8; i++) {
    float a0 = i * 0.785f, a1 = (i + 1) * 0.785f;
    glColor3f(0.5f + 0.5f * cosf(a0), 0.5f, 0.5f + 0.5f * sinf(a0));
    glNormal3f(cosf(a0), 0, sinf(a0));
    glVertex3f(cosf(a0), -1, sinf(a0));
    glColor3f(0.5f + 0.5f * cosf(a1), 0.5f, 0.5f + 0.5f * sinf(a1));
    glNormal3f(cosf(a1), 0, sinf(a1));
    glVertex3f(cosf(a1), -1, sinf(a1));
    glVertex3f(cosf(a1), 1, sinf(a1));
    glColor3f(0.5f + 0.5f * cosf(a0), 0.5f, 0.5f + 0.5f * sinf(a0));
    glNormal3f(cosf(a0), 0, sinf(a0));
    glVertex3f(cosf(a0), 1, sinf(a0));
  }
  glEnd();
  printf("scene 4 error 0x%x\n", glGetError());

  return end_scenes("lit_stiff.color", q);
}
