/* Display lists: GL_COMPILE and GL_COMPILE_AND_EXECUTE, glCallList under
 * other transforms, nested lists, glCallLists with glListBase, a GLU sphere
 * compiled into a list, client-array draws compiled (the arrays are read at
 * compile time), list management and its errors. */
#include "common.h"
#include <GL/glu.h>

#define W 96
#define H 64
#define E(call) do { call; printf("%-40s 0x%04x\n", #call, glGetError()); } while (0)

int main(int argc, char **argv) {
  start(argc, argv);
  static unsigned char buf[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, W, 0, H, -10, 10);
  glMatrixMode(GL_MODELVIEW);

  GLuint base = glGenLists(4);
  printf("genlists %u islist %d %d\n", base, glIsList(base), glIsList(base + 4));
  /* A smooth triangle with its own colour and a state change. */
  glNewList(base, GL_COMPILE);
  glShadeModel(GL_SMOOTH);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0); glVertex2f(0, 0);
  glColor3f(0, 1, 0); glVertex2f(20, 0);
  glColor3f(0, 0, 1); glVertex2f(0, 20);
  glEnd();
  glEndList();
  GLint v; glGetIntegerv(GL_LIST_INDEX, &v); printf("list index after end %d\n", v);
  /* Nothing drawn while compiling. */
  unsigned char px[4]; glReadPixels(2, 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  printf("after compile %d %d %d\n", px[0], px[1], px[2]);
  /* A list calling another under a translation. */
  glNewList(base + 1, GL_COMPILE);
  glPushMatrix();
  glTranslatef(30, 5, 0);
  glCallList(base);
  glPopMatrix();
  glEndList();
  /* Compile and execute: drawn now and later. */
  glNewList(base + 2, GL_COMPILE_AND_EXECUTE);
  glGetIntegerv(GL_LIST_MODE, &v); printf("list mode 0x%x\n", v);
  glColor3f(1, 1, 0);
  glRectf(60, 40, 70, 50);
  glEndList();
  glCallList(base);
  glCallList(base + 1);
  glPushMatrix(); glTranslatef(0, 30, 0); glCallList(base + 1); glPopMatrix();
  /* glCallLists with a base: offsets 0 and 2 from base. */
  GLubyte offs[2] = {0, 2};
  glListBase(base);
  glPushMatrix(); glTranslatef(60, 0, 0); glCallLists(2, GL_UNSIGNED_BYTE, offs); glPopMatrix();
  glListBase(0);
  /* A GLU sphere in a list, drawn twice. */
  GLUquadric *q = gluNewQuadric();
  glNewList(base + 3, GL_COMPILE);
  glColor3f(0.5f, 0.25f, 1);
  gluSphere(q, 6, 12, 8);
  glEndList();
  gluDeleteQuadric(q);
  glEnable(GL_DEPTH_TEST);
  glPushMatrix(); glTranslatef(80, 20, 0); glCallList(base + 3); glPopMatrix();
  glPushMatrix(); glTranslatef(45, 50, 0); glCallList(base + 3); glPopMatrix();
  glDisable(GL_DEPTH_TEST);
  /* Client arrays are read when the list is compiled. */
  GLfloat verts[6] = {40, 30, 55, 30, 40, 45};
  GLubyte cols[12] = {255, 255, 255, 255, 0, 255, 255, 255, 255, 0, 255, 255};
  glVertexPointer(2, GL_FLOAT, 0, verts);
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, cols);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  GLuint arr = glGenLists(1);
  glNewList(arr, GL_COMPILE);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEndList();
  verts[0] = verts[2] = verts[4] = -100; /* too late to matter */
  glCallList(arr);
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  printf("error after drawing 0x%x\n", glGetError());
  /* Management and errors. */
  E(glNewList(0, GL_COMPILE));
  E(glNewList(base, 0x1234));
  E(glEndList());
  glNewList(base + 10, GL_COMPILE);
  E(glNewList(base + 11, GL_COMPILE));
  glEndList();
  printf("islist new %d\n", glIsList(base + 10));
  E(glDeleteLists(base, -1));
  glDeleteLists(base + 10, 1);
  printf("islist deleted %d\n", glIsList(base + 10));
  E(glCallList(12345));
  E(glGenLists(-1));
  glGetIntegerv(GL_MAX_LIST_NESTING, &v); printf("max nesting %d\n", v);
  glFinish();
  dump("lists.color", buf, sizeof buf);
  OSMesaDestroyContext(ctx);
  printf("done\n");
  return 0;
}
