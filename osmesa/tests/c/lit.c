/* Lighting through the C ABI, compared with Mesa: four scenes side by side
 * in one 256x256 image, each in its own viewport (GLU spheres and strips):
 * 1. one infinite light, specular (shininess 32), smooth;
 * 2. 8 lights (spot, attenuation, positional), a local viewer, linear fog
 *    (its eye distance is the lighting's eye position);
 * 3. two-sided lighting with separate specular on a twisted strip;
 * 4. colour material (ambient and diffuse) with GL_NORMALIZE on a scaled
 *    sphere, flat shaded, cut by a user clip plane. */
#include "scenes.h"

int main(int argc, char **argv) {
  GLUquadric *q = begin_scenes(argc, argv);

  /* 1: one infinite light, white specular. */
  view(0);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  lightv(GL_LIGHT0, GL_POSITION, 1, 1, 1, 0);
  materialv(GL_FRONT, GL_DIFFUSE, 0.8f, 0.2f, 0.1f, 1);
  materialv(GL_FRONT, GL_SPECULAR, 1, 1, 1, 1);
  glMaterialf(GL_FRONT, GL_SHININESS, 32);
  gluSphere(q, 1.2, 32, 24);
  printf("scene 1 error 0x%x\n", glGetError());

  /* 2: 8 lights, spot + attenuation, local viewer. */
  view(1);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
  for (int i = 0; i < 8; i++) {
    GLenum l = GL_LIGHT0 + i;
    glEnable(l);
    float a = i * 0.785f;
    lightv(l, GL_POSITION, 2 * cosf(a), 2 * sinf(a), 2, i % 3 == 2 ? 0 : 1);
    lightv(l, GL_DIFFUSE, 0.3f + 0.1f * (i % 3), 0.2f + 0.1f * (i % 4), 0.4f, 1);
    lightv(l, GL_SPECULAR, 0.5f, 0.5f, 0.5f, 1);
    lightv(l, GL_AMBIENT, 0.02f * i, 0.01f, 0.02f, 1);
    lightv(l, GL_SPOT_DIRECTION, -cosf(a), -sinf(a), -2, 0);
    glLightf(l, GL_SPOT_CUTOFF, i % 2 ? 25.0f + 5 * i : 180.0f);
    glLightf(l, GL_SPOT_EXPONENT, 4.0f * i);
    glLightf(l, GL_LINEAR_ATTENUATION, 0.1f * i);
    glLightf(l, GL_QUADRATIC_ATTENUATION, 0.02f * i);
  }
  materialv(GL_FRONT, GL_DIFFUSE, 0.9f, 0.9f, 0.9f, 1);
  glMaterialf(GL_FRONT, GL_SHININESS, 60);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 3.5f);
  glFogf(GL_FOG_END, 6.5f);
  GLfloat fog[4] = {0.3f, 0.3f, 0.5f, 1};
  glFogfv(GL_FOG_COLOR, fog);
  gluSphere(q, 1.2, 32, 24);
  glDisable(GL_FOG);
  printf("scene 2 error 0x%x\n", glGetError());
  for (int i = 1; i < 8; i++) glDisable(GL_LIGHT0 + i);
  lightv(GL_LIGHT0, GL_DIFFUSE, 1, 1, 1, 1);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180);
  glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0);
  glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 0);

  /* 3: two-sided, separate specular, a twisted strip. */
  view(2);
  lightv(GL_LIGHT0, GL_POSITION, 0.5f, 1, 2, 0);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
  materialv(GL_FRONT, GL_DIFFUSE, 0.2f, 0.7f, 0.2f, 1);
  materialv(GL_BACK, GL_DIFFUSE, 0.7f, 0.2f, 0.6f, 1);
  materialv(GL_BACK, GL_SPECULAR, 0.8f, 0.8f, 0.2f, 1);
  glMaterialf(GL_BACK, GL_SHININESS, 10);
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i <= 24; i++) {
    float t = -1.5f + i * 0.125f, a = t * 1.6f;
    glNormal3f(0, -sinf(a), cosf(a));
    glVertex3f(t, -0.5f * cosf(a), -0.5f * sinf(a));
    glVertex3f(t, 0.5f * cosf(a), 0.5f * sinf(a));
  }
  glEnd();
  printf("scene 3 error 0x%x\n", glGetError());
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 0);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);

  /* 4: colour material, NORMALIZE on a scaled sphere, flat, clip plane. */
  view(3);
  glShadeModel(GL_FLAT);
  glEnable(GL_NORMALIZE);
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
  GLdouble plane[4] = {1, 1, 0, 0.3};
  glClipPlane(GL_CLIP_PLANE0, plane);
  glEnable(GL_CLIP_PLANE0);
  glColor3f(0.2f, 0.5f, 0.9f);
  glScalef(1.5f, 0.8f, 1.0f);
  gluSphere(q, 1.0, 20, 14);
  printf("scene 4 error 0x%x\n", glGetError());

  return end_scenes("lit.color", q);
}
