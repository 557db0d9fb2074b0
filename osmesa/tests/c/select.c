/* Selection and feedback (GL 1.5 5.2, 5.3): hit records and feedback
 * buffers for points, lines, strips, polygons (clipped by the view volume,
 * culled, drawn as lines or points), the name stack, overflow (-1), every
 * feedback type, pass-through tokens, display lists, the errors and the
 * state read back. Prints one line per value; the test compares Mesa's
 * lines with softgl's. */
#include "common.h"

#define E(call) do { call; printf("%-48s 0x%04x\n", #call, glGetError()); } while (0)

static GLuint sel[256];
static GLfloat fb[1024];

static void print_hits(const char *what, GLint hits) {
  printf("%s: hits %d\n", what, hits);
  GLint n = hits < 0 ? 8 : 0;
  if (hits > 0) {
    GLuint *p = sel;
    for (int h = 0; h < hits; h++) { GLuint names = p[0]; p += 3 + names; }
    n = (GLint)(p - sel);
  }
  for (int i = 0; i < n; i++) printf("  %u\n", sel[i]);
}

static void print_feedback(const char *what, GLint count) {
  printf("%s: values %d\n", what, count);
  GLint n = count < 0 ? 4 : count;
  for (int i = 0; i < n; i++) printf("  %.9g\n", fb[i]);
}

static void tri(float x, float y, float z, float s) {
  glBegin(GL_TRIANGLES);
  glColor4f(1, 0, 0, 1); glTexCoord4f(0.25f, 0.5f, 0, 1); glVertex3f(x, y, z);
  glColor4f(0, 1, 0, 0.5f); glTexCoord2f(1, 0); glVertex3f(x + s, y, z + 0.25f);
  glColor4f(0, 0, 1, 1); glTexCoord2f(0, 1); glVertex3f(x, y + s, z - 0.25f);
  glEnd();
}

/* Every kind of primitive, some clipped, one culled. */
static void scene(void) {
  tri(-0.5f, -0.5f, 0, 0.5f);
  glBegin(GL_POINTS);
  glVertex3f(0.1f, 0.2f, 0.3f);
  glVertex3f(2, 0, 0);                /* outside: nothing */
  glVertex3f(-0.9f, 0.9f, -0.9f);
  glEnd();
  glBegin(GL_LINES);
  glVertex3f(-0.5f, 0, 0.5f); glVertex3f(0.5f, 0.25f, -0.5f);
  glVertex3f(0, 0, 0); glVertex3f(3, 0.5f, 0.9f);   /* clipped at x = 1 */
  glEnd();
  glBegin(GL_LINE_STRIP);
  glVertex3f(-0.75f, -0.75f, 0); glVertex3f(0, 0.5f, 0.25f); glVertex3f(0.75f, -0.75f, 0.5f);
  glEnd();
  glBegin(GL_LINE_LOOP);
  glVertex3f(-0.25f, -0.25f, 0); glVertex3f(0.25f, -0.25f, 0); glVertex3f(0, 0.25f, 0);
  glEnd();
  /* A quad crossing the far plane and the right edge: clipped into a polygon. */
  glBegin(GL_QUADS);
  glColor3f(1, 1, 0);
  glVertex3f(0.5f, -0.5f, 0); glVertex3f(1.5f, -0.5f, 0.5f); glVertex3f(1.5f, 0.5f, 1.5f); glVertex3f(0.5f, 0.5f, 0.2f);
  glEnd();
  /* Clockwise: culled when GL_CULL_FACE is on. */
  glBegin(GL_TRIANGLES);
  glVertex3f(0, 0, 0.1f); glVertex3f(0, 0.5f, 0.1f); glVertex3f(0.5f, 0, 0.1f);
  glEnd();
}

int main(int argc, char **argv) {
  start(argc, argv);
  static unsigned char buf[64 * 64 * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(ctx);
  CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 64, 64));
  GLint v[4];
  void *ptr;

  /* Defaults. */
  glGetIntegerv(GL_RENDER_MODE, v); printf("render mode 0x%x\n", v[0]);
  glGetIntegerv(GL_NAME_STACK_DEPTH, v); printf("name stack depth %d\n", v[0]);
  glGetIntegerv(GL_MAX_NAME_STACK_DEPTH, v); printf("max name stack depth %d\n", v[0]);
  glGetIntegerv(GL_SELECTION_BUFFER_SIZE, v); printf("selection size %d\n", v[0]);
  glGetIntegerv(GL_FEEDBACK_BUFFER_SIZE, v); printf("feedback size %d\n", v[0]);
  glGetIntegerv(GL_FEEDBACK_BUFFER_TYPE, v); printf("feedback type 0x%x\n", v[0]);
  glGetPointerv(GL_SELECTION_BUFFER_POINTER, &ptr); printf("selection pointer null %d\n", ptr == NULL);
  glGetPointerv(GL_FEEDBACK_BUFFER_POINTER, &ptr); printf("feedback pointer null %d\n", ptr == NULL);
  printf("error 0x%x\n", glGetError());

  /* Errors, and name calls outside select mode (ignored). */
  E(glPushName(1));
  E(glPopName());
  E(glLoadName(1));
  E(glInitNames());
  E(glPassThrough(1));
  E(glSelectBuffer(-1, sel));
  E(glFeedbackBuffer(-1, GL_2D, fb));
  E(glFeedbackBuffer(4, 0x1234, fb));
  E(glFeedbackBuffer(4, GL_2D, NULL));
  E(glRenderMode(0x1234));
  E(glRenderMode(GL_SELECT));          /* no buffer yet */
  E(printf("leave %d\n", glRenderMode(GL_RENDER)));
  E(glBegin(GL_POINTS); glRenderMode(GL_SELECT); glEnd());

  /* Selection. */
  E(glSelectBuffer(256, sel));
  glGetPointerv(GL_SELECTION_BUFFER_POINTER, &ptr); printf("selection pointer ok %d\n", ptr == (void *)sel);
  glGetIntegerv(GL_SELECTION_BUFFER_SIZE, v); printf("selection size %d\n", v[0]);
  E(printf("enter %d\n", glRenderMode(GL_SELECT)));
  glGetIntegerv(GL_RENDER_MODE, v); printf("render mode 0x%x\n", v[0]);
  E(glSelectBuffer(16, sel));
  E(glLoadName(7));                     /* empty stack */
  E(glPopName());
  glInitNames();
  glPushName(1);
  tri(-0.5f, -0.5f, 0, 0.5f);
  glLoadName(2);
  glBegin(GL_LINES); glVertex3f(0, 0, 0); glVertex3f(3, 0.5f, 0.9f); glEnd();
  glPushName(3);
  glBegin(GL_POINTS); glVertex3f(0.1f, 0.2f, 0.3f); glVertex3f(2, 0, 0); glEnd();
  glGetIntegerv(GL_NAME_STACK_DEPTH, v); printf("name stack depth %d\n", v[0]);
  glPopName();
  glLoadName(4);
  glBegin(GL_POINTS); glVertex3f(2, 0, 0); glEnd(); /* outside: no hit */
  glLoadName(5);
  glBegin(GL_QUADS);
  glVertex3f(0.5f, -0.5f, 0); glVertex3f(1.5f, -0.5f, 0.5f); glVertex3f(1.5f, 0.5f, 1.5f); glVertex3f(0.5f, 0.5f, 0.2f);
  glEnd();
  glLoadName(6);
  glEnable(GL_CULL_FACE);
  glBegin(GL_TRIANGLES); glVertex3f(0, 0, 0.1f); glVertex3f(0, 0.5f, 0.1f); glVertex3f(0.5f, 0, 0.1f); glEnd();
  glDisable(GL_CULL_FACE);
  glLoadName(8);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  tri(-0.25f, -0.25f, -1, 0.5f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glInitNames();
  glBegin(GL_POINTS); glVertex3f(0, 0, 1); glEnd();   /* z = 1 (far), empty stack */
  glPushName(9);
  glBegin(GL_POINTS); glVertex3f(0, 0, -1); glEnd();  /* z = 0 (near) */
  for (int i = 0; i < 70; i++) glPushName(100 + i);
  printf("push past the top 0x%04x\n", glGetError());
  glGetIntegerv(GL_NAME_STACK_DEPTH, v); printf("name stack depth %d\n", v[0]);
  print_hits("select", glRenderMode(GL_RENDER));
  glGetIntegerv(GL_NAME_STACK_DEPTH, v); printf("name stack depth after %d\n", v[0]);

  /* Names compiled into a list. */
  glNewList(1, GL_COMPILE);
  glInitNames(); glPushName(11); glPushName(12); glLoadName(13);
  glBegin(GL_POINTS); glVertex3f(0.5f, 0.5f, 0.5f); glEnd();
  glPopName();
  glBegin(GL_POINTS); glVertex3f(-0.5f, 0.5f, -0.5f); glEnd();
  glPassThrough(42);
  glEndList();
  glRenderMode(GL_SELECT);
  glCallList(1);
  print_hits("select list", glRenderMode(GL_RENDER));

  /* Overflow: 5 values of room. */
  for (int i = 0; i < 16; i++) sel[i] = 0xdeadbeef;
  glSelectBuffer(5, sel);
  glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(1);
  glBegin(GL_POINTS); glVertex3f(0.5f, 0.5f, 0.5f); glEnd();
  glLoadName(2);
  glBegin(GL_POINTS); glVertex3f(0.5f, 0.5f, 0.5f); glEnd();
  print_hits("select overflow", glRenderMode(GL_RENDER));

  /* Feedback, every type. */
  static const GLenum types[] = {GL_2D, GL_3D, GL_3D_COLOR, GL_3D_COLOR_TEXTURE, GL_4D_COLOR_TEXTURE};
  static const char *names[] = {"2d", "3d", "3d color", "3d color texture", "4d color texture"};
  for (int t = 0; t < 5; t++) {
    E(glFeedbackBuffer(1024, types[t], fb));
    glGetIntegerv(GL_FEEDBACK_BUFFER_TYPE, v); printf("feedback type 0x%x\n", v[0]);
    glRenderMode(GL_FEEDBACK);
    E(glFeedbackBuffer(1024, types[t], fb));
    glPassThrough(1.5f);
    scene();
    glPassThrough(2);
    print_feedback(names[t], glRenderMode(GL_RENDER));
  }
  glGetPointerv(GL_FEEDBACK_BUFFER_POINTER, &ptr); printf("feedback pointer ok %d\n", ptr == (void *)fb);

  /* Culling, polygon modes, flat shading, a perspective projection. */
  glFeedbackBuffer(1024, GL_4D_COLOR_TEXTURE, fb);
  glRenderMode(GL_FEEDBACK);
  glEnable(GL_CULL_FACE);
  scene();
  glDisable(GL_CULL_FACE);
  glPolygonMode(GL_FRONT, GL_LINE);
  glPolygonMode(GL_BACK, GL_POINT);
  scene();
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glShadeModel(GL_FLAT);
  tri(-0.5f, -0.5f, 0, 0.5f);
  glShadeModel(GL_SMOOTH);
  glMatrixMode(GL_PROJECTION);
  glFrustum(-1, 1, -1, 1, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glTranslatef(0, 0, -3);
  tri(-0.5f, -0.5f, 0, 1);
  tri(-2, -2, 2.5f, 4);                 /* crosses the near plane */
  glLoadIdentity();
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glCallList(1);                        /* the pass-through in the list */
  print_feedback("cull, modes, flat, perspective", glRenderMode(GL_RENDER));

  /* An empty scissor box and viewport do not stop feedback. */
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 0, 0);
  glFeedbackBuffer(1024, GL_3D, fb);
  glRenderMode(GL_FEEDBACK);
  glBegin(GL_POINTS); glVertex3f(0.5f, 0.5f, 0.5f); glEnd();
  glViewport(0, 0, 0, 0);
  glBegin(GL_POINTS); glVertex3f(0.5f, 0.5f, 0.5f); glEnd();
  glViewport(0, 0, 64, 64);
  glDisable(GL_SCISSOR_TEST);
  print_feedback("scissor and viewport empty", glRenderMode(GL_RENDER));

  /* Feedback overflow: 4 values of room. */
  for (int i = 0; i < 8; i++) fb[i] = -7;
  glFeedbackBuffer(4, GL_3D, fb);
  glRenderMode(GL_FEEDBACK);
  tri(-0.5f, -0.5f, 0, 0.5f);
  print_feedback("feedback overflow", glRenderMode(GL_RENDER));
  printf("error 0x%x\n", glGetError());

  /* Nothing was drawn. */
  int drawn = 0;
  for (int i = 0; i < 64 * 64 * 4; i++) drawn |= buf[i];
  printf("drawn %d\n", drawn);
  OSMesaDestroyContext(ctx);
  printf("done\n");
  return 0;
}
