/* GLU on OSMesa: gluPerspective, gluLookAt and the quadrics in every draw
 * style, flat colours, depth-tested; gluBuild2DMipmaps uploads its levels
 * (tests/c/textured.c draws with them). */
#include "common.h"
#include <GL/glu.h>

#define W 160
#define H 120

int main(int argc, char **argv) {
  start(argc, argv);
  static unsigned char buf[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 8, NULL); /* with accumulation bits, as some clients ask */
  CHECK(ctx);
  CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
  glClearColor(0.05f, 0.05f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, (double)W / H, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0, 2, 8, 0, 0, 0, 0, 1, 0);

  GLUquadric *q = gluNewQuadric();
  CHECK(q);
  glPushMatrix();
  glTranslatef(-2, 0, 0);
  glColor3f(1, 0, 0);
  gluSphere(q, 1.0, 24, 16);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(1.5f, -1, 0);
  glRotatef(-90, 1, 0, 0);
  glColor3f(0, 1, 0);
  gluCylinder(q, 0.8, 0.3, 2.0, 20, 4);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(0, 1.6f, -1);
  gluQuadricDrawStyle(q, GLU_LINE);
  glColor3f(0.3f, 0.5f, 1);
  gluDisk(q, 0.3, 1.2, 16, 3);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(0, -1.5f, 1);
  gluQuadricDrawStyle(q, GLU_POINT);
  glColor3f(1, 1, 0);
  gluPartialDisk(q, 0.2, 1.0, 12, 3, 30, 240);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(2.8f, 1.2f, 0);
  gluQuadricDrawStyle(q, GLU_SILHOUETTE);
  glColor3f(1, 0.5f, 0);
  gluDisk(q, 0.0, 0.7, 10, 1);
  glPopMatrix();
  gluDeleteQuadric(q);
  printf("error after quadrics 0x%x\n", glGetError());

  static unsigned char tex[8 * 8 * 3];
  for (int i = 0; i < (int)sizeof tex; i++) tex[i] = (unsigned char)(i * 7);
  GLint r = gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGB, 8, 8, GL_RGB, GL_UNSIGNED_BYTE, tex);
  printf("gluBuild2DMipmaps %d error 0x%x\n", r, glGetError());
  printf("then 0x%x\n", glGetError());
  glFinish();
  dump("glu.color", buf, sizeof buf);
  GLint dw, dh, bpv; void *db;
  CHECK(OSMesaGetDepthBuffer(ctx, &dw, &dh, &bpv, &db));
  dump("glu.depth", db, (size_t)dw * dh * bpv);
  OSMesaDestroyContext(ctx);
  printf("done\n");
  return 0;
}
