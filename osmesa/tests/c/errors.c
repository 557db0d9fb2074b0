/* GL errors from bad arguments, through glGetError (sticky: the first error
 * is kept until read), and OSMesa's refusals. Prints one line per check; the
 * test compares the lines of Mesa and softgl. */
#include "common.h"

#define E(call) do { call; printf("%-48s 0x%04x\n", #call, glGetError()); } while (0)
/* The error of `call` made between glBegin and glEnd (glGetError itself is
 * an error there). */
#define B(call) do { glBegin(GL_TRIANGLES); call; glEnd(); printf("in begin/end %-35s 0x%04x\n", #call, glGetError()); } while (0)

int main(int argc, char **argv) {
  start(argc, argv);
  static unsigned char buf[16 * 16 * 4];
  /* OSMesa refusals. */
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(ctx);
  printf("MakeCurrent null buffer %d\n", OSMesaMakeCurrent(ctx, NULL, GL_UNSIGNED_BYTE, 16, 16));
  printf("MakeCurrent zero width %d\n", OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 0, 16));
  printf("MakeCurrent negative height %d\n", OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 16, -3));
  printf("MakeCurrent RGBA with 5_6_5 %d\n", OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_SHORT_5_6_5, 16, 16));
  printf("MakeCurrent RGBA with GL_BYTE %d\n", OSMesaMakeCurrent(ctx, buf, GL_BYTE, 16, 16));
  printf("MakeCurrent null context %d\n", OSMesaMakeCurrent(NULL, buf, GL_UNSIGNED_BYTE, 16, 16));
  printf("current before any %d\n", OSMesaGetCurrentContext() == NULL);
  /* GL calls without a current context are ignored. */
  glClear(GL_COLOR_BUFFER_BIT);
  printf("glGetError without context 0x%x\n", glGetError());
  printf("glGetString without context %d\n", glGetString(GL_VENDOR) == NULL);
  printf("MakeCurrent ok %d\n", OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 16, 16));
  printf("current is ctx %d\n", OSMesaGetCurrentContext() == ctx);

  E(glBegin(0x20));
  E(glEnable(0x1234));
  E(glDisable(0x1234));
  E(glIsEnabled(0x1234));
  E(glClear(0x1));
  E(glViewport(0, 0, -1, 4));
  E(glScissor(0, 0, 4, -1));
  E(glMatrixMode(0x1234));
  E(glDepthFunc(0x1234));
  E(glAlphaFunc(0x1234, 0.5f));
  E(glStencilFunc(0x1234, 0, 0xff));
  E(glStencilOp(GL_KEEP, 0x1234, GL_KEEP));
  E(glBlendFunc(GL_ONE, 0x1234));
  E(glLogicOp(0x1234));
  E(glCullFace(0x1234));
  E(glFrontFace(0x1234));
  E(glPolygonMode(GL_FRONT_AND_BACK, 0x1234));
  E(glPolygonMode(0x1234, GL_LINE));
  E(glShadeModel(0x1234));
  E(glLineWidth(0));
  E(glPointSize(-1));
  E(glPopMatrix());
  for (int i = 0; i < 31; i++) glPushMatrix();
  E(glPushMatrix());
  for (int i = 0; i < 31; i++) glPopMatrix();
  E(glFrustum(-1, 1, -1, 1, 0, 10));
  E(glFrustum(-1, -1, -1, 1, 1, 10));
  E(glOrtho(0, 1, 0, 1, 2, 2));
  E(glEnd());
  glBegin(GL_TRIANGLES);
  E(glBegin(GL_TRIANGLES));
  glEnd();
  glBegin(GL_TRIANGLES);
  E(glClear(GL_COLOR_BUFFER_BIT));
  glEnd();
  /* Lighting: inside glBegin/glEnd every non-vertex command is
   * GL_INVALID_OPERATION before its arguments are looked at (Mesa's begin/end
   * dispatch); glMaterial is allowed there. */
  GLdouble plane[4];
  GLfloat lv[4];
  B(glLightModelf(0x1234, 1));
  B(glLightModeli(GL_LIGHT_MODEL_AMBIENT, 1));
  B(glLightModelfv(GL_LIGHT_MODEL_AMBIENT, NULL));
  B(glLightf(0x1234, GL_SPOT_EXPONENT, 1));
  B(glGetClipPlane(0, plane));
  B(glClipPlane(0, plane));
  B(glGetLightfv(0x1234, GL_AMBIENT, lv));
  B(glGetMaterialfv(0x1234, GL_AMBIENT, lv));
  B(glMaterialf(GL_FRONT, GL_AMBIENT, 0.5f));
  B(glMateriali(GL_FRONT, GL_SHININESS, 200));
  /* A vector parameter through the scalar call is no error in Mesa. */
  E(glMaterialf(GL_FRONT, GL_EMISSION, 0.5f));
  E(glMateriali(GL_BACK, GL_SPECULAR, 1));
  E(glMaterialf(GL_FRONT, 0x1234, 0.5f));
  E(glLightf(GL_LIGHT1, GL_POSITION, 2));
  glGetLightfv(GL_LIGHT1, GL_POSITION, lv); printf("light1 position %g %g %g %g\n", lv[0], lv[1], lv[2], lv[3]);
  E(glLighti(GL_LIGHT1, GL_SPOT_DIRECTION, 3));
  glGetLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, lv); printf("light1 spot direction %g %g %g\n", lv[0], lv[1], lv[2]);
  E(glLightModelf(GL_LIGHT_MODEL_AMBIENT, 0.25f));
  glGetFloatv(GL_LIGHT_MODEL_AMBIENT, lv); printf("model ambient %g %g %g %g\n", lv[0], lv[1], lv[2], lv[3]);
  E(glLightModeli(GL_LIGHT_MODEL_AMBIENT, 0x7fffffff));
  glGetFloatv(GL_LIGHT_MODEL_AMBIENT, lv); printf("model ambient %g %g %g %g\n", lv[0], lv[1], lv[2], lv[3]);
  E(glLightModelf(0x1234, 1));
  E(glDrawArrays(GL_TRIANGLES, 0, -1));
  E(glDrawArrays(0x20, 0, 3));
  E(glDrawElements(GL_TRIANGLES, 3, GL_FLOAT, NULL));
  E(glVertexPointer(5, GL_FLOAT, 0, NULL));
  E(glVertexPointer(3, GL_UNSIGNED_BYTE, 0, NULL));
  E(glColorPointer(3, GL_FLOAT, -4, NULL));
  E(glEnableClientState(0x1234));
  unsigned char px[64];
  E(glReadPixels(0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px));
  E(glReadPixels(0, 0, 1, 1, 0x1234, GL_UNSIGNED_BYTE, px));
  E(glReadPixels(0, 0, 1, 1, GL_RGBA, 0x1234, px));
  E(glPixelStorei(GL_PACK_ALIGNMENT, 3));
  E(glPixelStorei(GL_UNPACK_ROW_LENGTH, -1));
  E(glPixelStorei(0x1234, 1));
  E(glHint(GL_PERSPECTIVE_CORRECTION_HINT, 0x1234));
  E(glHint(0x1234, GL_NICEST));
  E(glGetString(0x1234));
  GLint iv[16];
  E(glGetIntegerv(0x1234, iv));
  /* Sticky: the first error stays until read, then GL_NO_ERROR. */
  glEnable(0x1234);
  glViewport(0, 0, -1, -1);
  printf("sticky first 0x%04x\n", glGetError());
  printf("sticky then 0x%04x\n", glGetError());
  /* Good calls leave no error, and the state reads back. */
  glViewport(1, 2, 3, 4);
  glGetIntegerv(GL_VIEWPORT, iv);
  printf("viewport %d %d %d %d\n", iv[0], iv[1], iv[2], iv[3]);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, iv);
  printf("max viewport %d %d\n", iv[0], iv[1]);
  glGetIntegerv(GL_MAX_MODELVIEW_STACK_DEPTH, iv);
  printf("max modelview depth %d\n", iv[0]);
  glGetIntegerv(GL_DEPTH_BITS, iv);
  printf("depth bits %d\n", iv[0]);
  glGetIntegerv(GL_STENCIL_BITS, iv);
  printf("stencil bits %d\n", iv[0]);
  glGetIntegerv(GL_RED_BITS, iv);
  printf("red bits %d\n", iv[0]);
  glDepthFunc(GL_GEQUAL);
  glGetIntegerv(GL_DEPTH_FUNC, iv);
  printf("depth func 0x%x\n", iv[0]);
  glEnable(GL_BLEND);
  printf("blend enabled %d\n", glIsEnabled(GL_BLEND));
  GLboolean bv[4];
  glColorMask(1, 0, 1, 0);
  glGetBooleanv(GL_COLOR_WRITEMASK, bv);
  printf("color mask %d %d %d %d\n", bv[0], bv[1], bv[2], bv[3]);
  GLfloat fv[16];
  glClearColor(0.25f, 0.5f, 0.75f, 1);
  glGetFloatv(GL_COLOR_CLEAR_VALUE, fv);
  printf("clear color %g %g %g %g\n", fv[0], fv[1], fv[2], fv[3]);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(1, 2, 3);
  glScalef(2, 2, 2);
  glGetFloatv(GL_MODELVIEW_MATRIX, fv);
  printf("modelview %g %g %g %g %g\n", fv[0], fv[5], fv[12], fv[13], fv[14]);
  GLdouble dv[4];
  glDepthRange(0.25, 0.75);
  glGetDoublev(GL_DEPTH_RANGE, dv);
  printf("depth range %g %g\n", dv[0], dv[1]);
  glPixelStorei(GL_PACK_ALIGNMENT, 2);
  glGetIntegerv(GL_PACK_ALIGNMENT, iv);
  printf("pack alignment %d\n", iv[0]);
  /* Attribute stacks: a pop restores the groups its push named. */
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  glGetIntegerv(GL_ATTRIB_STACK_DEPTH, iv);
  printf("attrib depth %d\n", iv[0]);
  glEnable(GL_DEPTH_TEST); glDepthFunc(GL_ALWAYS); glViewport(5, 6, 7, 8); glBlendFunc(GL_ONE, GL_ONE);
  glDisable(GL_BLEND); glColor4f(0.1f, 0.2f, 0.3f, 0.4f); glMatrixMode(GL_PROJECTION); glLineWidth(3);
  glPointSize(4); glShadeModel(GL_FLAT); glEnable(GL_SCISSOR_TEST); glScissor(1, 1, 2, 2);
  glStencilFunc(GL_EQUAL, 3, 0xf); glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_FASTEST); glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT); glColorMask(1, 1, 1, 1); glClearColor(0, 0, 0, 0); glPolygonMode(GL_FRONT, GL_LINE);
  glPopAttrib();
  printf("after pop: depth test %d blend %d scissor %d cull %d\n", glIsEnabled(GL_DEPTH_TEST), glIsEnabled(GL_BLEND),
         glIsEnabled(GL_SCISSOR_TEST), glIsEnabled(GL_CULL_FACE));
  GLint q[4];
  glGetIntegerv(GL_DEPTH_FUNC, q); printf("depth func 0x%x\n", q[0]);
  glGetIntegerv(GL_VIEWPORT, q); printf("viewport %d %d %d %d\n", q[0], q[1], q[2], q[3]);
  glGetIntegerv(GL_BLEND_SRC, q); glGetIntegerv(GL_BLEND_DST, q + 1); printf("blend 0x%x 0x%x\n", q[0], q[1]);
  glGetFloatv(GL_CURRENT_COLOR, fv); printf("current color %g %g %g %g\n", fv[0], fv[1], fv[2], fv[3]);
  glGetIntegerv(GL_MATRIX_MODE, q); printf("matrix mode 0x%x\n", q[0]);
  glGetFloatv(GL_LINE_WIDTH, fv); glGetFloatv(GL_POINT_SIZE, fv + 1); printf("line %g point %g\n", fv[0], fv[1]);
  glGetIntegerv(GL_SHADE_MODEL, q); printf("shade model 0x%x\n", q[0]);
  glGetIntegerv(GL_SCISSOR_BOX, q); printf("scissor %d %d %d %d\n", q[0], q[1], q[2], q[3]);
  glGetIntegerv(GL_STENCIL_FUNC, q); glGetIntegerv(GL_STENCIL_REF, q + 1); glGetIntegerv(GL_STENCIL_VALUE_MASK, q + 2);
  printf("stencil 0x%x %d 0x%x\n", q[0], q[1], q[2]);
  glGetIntegerv(GL_PERSPECTIVE_CORRECTION_HINT, q); printf("hint 0x%x\n", q[0]);
  glGetIntegerv(GL_CULL_FACE_MODE, q); printf("cull mode 0x%x\n", q[0]);
  glGetBooleanv(GL_COLOR_WRITEMASK, bv); printf("color mask %d %d %d %d\n", bv[0], bv[1], bv[2], bv[3]);
  glGetFloatv(GL_COLOR_CLEAR_VALUE, fv); printf("clear color %g %g %g %g\n", fv[0], fv[1], fv[2], fv[3]);
  glGetIntegerv(GL_POLYGON_MODE, q); printf("polygon mode 0x%x 0x%x\n", q[0], q[1]);
  glPushAttrib(GL_VIEWPORT_BIT);
  glViewport(9, 9, 9, 9);
  glDepthFunc(GL_GREATER);
  glPopAttrib();
  glGetIntegerv(GL_VIEWPORT, q); printf("viewport only: viewport %d %d %d %d\n", q[0], q[1], q[2], q[3]);
  glGetIntegerv(GL_DEPTH_FUNC, q); printf("viewport only: depth func 0x%x\n", q[0]);
  E(glPopAttrib());
  for (int i = 0; i < 16; i++) glPushAttrib(GL_CURRENT_BIT);
  printf("16 pushes 0x%04x\n", glGetError());
  E(glPushAttrib(GL_CURRENT_BIT));
  for (int i = 0; i < 16; i++) glPopAttrib();
  glGetIntegerv(GL_MAX_ATTRIB_STACK_DEPTH, q); printf("max attrib depth %d\n", q[0]);
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPopClientAttrib();
  glGetIntegerv(GL_PACK_ALIGNMENT, q); printf("client pop: pack alignment %d\n", q[0]);
  E(glPopClientAttrib());
  /* glRotatef's matrix, bit for bit: axes along x, y, z (Mesa's exact ones
   * and zeros), general axes, an axis too short to rotate about. */
  static const float angles[] = {30, 90, 123.4f, -17};
  static const float axes[][3] = {{1, 0, 0}, {0, -1, 0}, {0, 0, 2}, {1, 1, 0}, {0.3f, -0.5f, 0.8f}, {1e-5f, 0, 1e-5f}};
  glMatrixMode(GL_MODELVIEW);
  for (int a = 0; a < 4; a++)
    for (int x = 0; x < 6; x++) {
      GLfloat m[16];
      glLoadIdentity();
      glRotatef(angles[a], axes[x][0], axes[x][1], axes[x][2]);
      glGetFloatv(GL_MODELVIEW_MATRIX, m);
      printf("rotate %g axis %d:", angles[a], x);
      for (int i = 0; i < 16; i++) printf(" %a", m[i]);
      printf("\n");
    }
  printf("final error 0x%x\n", glGetError());
  OSMesaDestroyContext(ctx);
  printf("current after destroy %d\n", OSMesaGetCurrentContext() == NULL);
  printf("done\n");
  return 0;
}
