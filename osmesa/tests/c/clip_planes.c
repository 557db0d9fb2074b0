/* User clip planes (and normal arrays) compared with Mesa, four 128x128
 * scenes in one image:
 * 1. two planes cutting a lit sphere drawn with glPolygonMode(GL_LINE);
 * 2. a lit sphere of points (GLU_POINT) under a plane;
 * 3. glDrawElements with a GL_SHORT normal array, lit, under a plane given
 *    with a rotated modelview;
 * 4. lines crossing a plane and the near plane. */
#include "scenes.h"

int main(int argc, char **argv) {
  GLUquadric *q = begin_scenes(argc, argv);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  GLfloat pos[4] = {1, 1, 2, 0};

  /* 1 */
  view(0);
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  GLdouble p0[4] = {1, 0, 0, 0.4}, p1[4] = {0, -1, 0.3, 0.5};
  glClipPlane(GL_CLIP_PLANE0, p0);
  glClipPlane(GL_CLIP_PLANE3, p1);
  glEnable(GL_CLIP_PLANE0);
  glEnable(GL_CLIP_PLANE3);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  gluSphere(q, 1.3, 24, 16);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glDisable(GL_CLIP_PLANE0);
  glDisable(GL_CLIP_PLANE3);
  printf("scene 1 error 0x%x\n", glGetError());

  /* 2 */
  view(1);
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  GLdouble p2[4] = {-1, 1, 0, 0.2};
  glClipPlane(GL_CLIP_PLANE2, p2);
  glEnable(GL_CLIP_PLANE2);
  gluQuadricDrawStyle(q, GLU_POINT);
  glPointSize(2);
  gluSphere(q, 1.3, 32, 24);
  gluQuadricDrawStyle(q, GLU_FILL);
  glDisable(GL_CLIP_PLANE2);
  printf("scene 2 error 0x%x\n", glGetError());

  /* 3 */
  view(2);
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  static GLfloat v[17 * 17 * 3];
  static GLshort n[17 * 17 * 3];
  static GLushort idx[16 * 16 * 6];
  for (int j = 0; j <= 16; j++)
    for (int i = 0; i <= 16; i++) {
      int k = (j * 17 + i) * 3;
      float x = -1.5f + i * 0.1875f, y = -1.5f + j * 0.1875f;
      v[k] = x; v[k + 1] = y; v[k + 2] = 0.3f * sinf(2 * x) * cosf(2 * y);
      float nx = -0.6f * cosf(2 * x) * cosf(2 * y), ny = 0.6f * sinf(2 * x) * sinf(2 * y);
      float l = sqrtf(nx * nx + ny * ny + 1);
      n[k] = (GLshort)(32767 * nx / l); n[k + 1] = (GLshort)(32767 * ny / l); n[k + 2] = (GLshort)(32767 / l);
    }
  int m = 0;
  for (int j = 0; j < 16; j++)
    for (int i = 0; i < 16; i++) {
      int a = j * 17 + i;
      idx[m++] = a; idx[m++] = a + 1; idx[m++] = a + 18;
      idx[m++] = a; idx[m++] = a + 18; idx[m++] = a + 17;
    }
  glPushMatrix();
  glRotatef(25, 0, 0, 1);
  GLdouble p3[4] = {1, 1, 0, 0.5};
  glClipPlane(GL_CLIP_PLANE1, p3);
  glPopMatrix();
  glEnable(GL_CLIP_PLANE1);
  glVertexPointer(3, GL_FLOAT, 0, v);
  glNormalPointer(GL_SHORT, 0, n);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glRotatef(-30, 1, 0, 0);
  glDrawElements(GL_TRIANGLES, m, GL_UNSIGNED_SHORT, idx);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisable(GL_CLIP_PLANE1);
  printf("scene 3 error 0x%x\n", glGetError());

  /* 4 */
  view(3);
  glDisable(GL_LIGHTING);
  GLdouble p4[4] = {0, 1, 0, 0.2};
  glClipPlane(GL_CLIP_PLANE5, p4);
  glEnable(GL_CLIP_PLANE5);
  glBegin(GL_LINES);
  for (int i = 0; i < 24; i++) {
    float a = i * 0.2618f;
    glColor3f(0.5f + 0.5f * cosf(a), 0.5f + 0.5f * sinf(a), 0.3f);
    glVertex3f(0, 0, 0);
    glColor3f(1, 1, 1);
    glVertex3f(1.8f * cosf(a), 1.8f * sinf(a), 6.0f * (i % 3 == 0));
  }
  glEnd();
  glDisable(GL_CLIP_PLANE5);
  printf("scene 4 error 0x%x\n", glGetError());

  return end_scenes("clip_planes.color", q);
}
