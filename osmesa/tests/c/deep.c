/* Deep colour buffers, as mesa-demos' ostest1 tries them: the same scene
 * rendered into OSMesa buffers of GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT and
 * GL_FLOAT, each checked for its GL_RED_BITS.. and written out
 * (<type>.<pass>.color: the caller's buffer; <type>.<pass>.read: glReadPixels
 * GL_RGBA/GL_FLOAT). Pass 0 is the default GL_FIXED_ONLY clamping, pass 1
 * after OSMesaColorClamp(GL_TRUE). The scene: smooth and lit geometry with
 * depth, blending (over and additive past 1), alpha test, fog, a scissored
 * clear, a colour mask and, in unorm buffers, logic op; the accumulation
 * buffer at the end. */
#define GL_GLEXT_PROTOTYPES
#include "common.h"
#include <GL/glext.h>
#include <GL/glu.h>

#define W 80
#define H 60

static void scene(void) {
  glViewport(0, 0, W, H);
  glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.5, 1.5, -1.1, 1.1, -5, 5);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_DEPTH_TEST);

  /* Smooth triangle with colours past 1 (clamped per vertex). */
  glBegin(GL_TRIANGLES);
  glColor4f(1.7f, 0.1f, 0.2f, 1.0f);
  glVertex3f(-1.4f, -1.0f, 0.2f);
  glColor4f(0.0f, 0.9f, 0.3f, 0.6f);
  glVertex3f(0.3f, -0.9f, -0.4f);
  glColor4f(0.3f, 0.2f, 1.0f, 0.8f);
  glVertex3f(-0.5f, 0.9f, 0.1f);
  glEnd();

  /* A lit sphere. */
  GLfloat pos[] = {1.0f, 1.0f, 2.0f, 0.0f};
  GLfloat diffuse[] = {0.9f, 0.7f, 0.4f, 1.0f};
  GLfloat specular[] = {1.0f, 1.0f, 1.0f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT, GL_SHININESS, 20.0f);
  glPushMatrix();
  glTranslatef(0.7f, 0.3f, 0.0f);
  GLUquadric *q = gluNewQuadric();
  gluSphere(q, 0.55, 20, 14);
  gluDeleteQuadric(q);
  glPopMatrix();
  glDisable(GL_LIGHTING);

  /* Blended over, then additive past 1 (a float buffer keeps the sum). */
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glBegin(GL_QUADS);
  glColor4f(0.9f, 0.9f, 0.1f, 0.37f);
  glVertex2f(-1.2f, 0.2f);
  glVertex2f(0.2f, 0.2f);
  glColor4f(0.1f, 0.8f, 0.9f, 0.71f);
  glVertex2f(0.2f, 0.8f);
  glVertex2f(-1.2f, 0.8f);
  glEnd();
  glBlendFunc(GL_ONE, GL_ONE);
  glBegin(GL_TRIANGLES);
  glColor4f(0.8f, 0.7f, 0.6f, 0.9f);
  glVertex2f(-0.3f, -0.8f);
  glVertex2f(1.4f, -0.6f);
  glVertex2f(0.9f, 0.6f);
  glEnd();
  glBlendFunc(GL_DST_COLOR, GL_ZERO);
  glBegin(GL_TRIANGLES);
  glColor4f(0.5f, 0.25f, 0.75f, 1.0f);
  glVertex2f(0.5f, -1.0f);
  glVertex2f(1.5f, -1.0f);
  glVertex2f(1.0f, 0.0f);
  glEnd();
  glDisable(GL_BLEND);

  /* Alpha test and fog. */
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.45f);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, -1.0f);
  glFogf(GL_FOG_END, 1.5f);
  GLfloat fogc[] = {0.6f, 0.1f, 0.5f, 1.0f};
  glFogfv(GL_FOG_COLOR, fogc);
  glBegin(GL_TRIANGLES);
  glColor4f(0.2f, 1.0f, 0.4f, 0.0f);
  glVertex3f(-1.5f, -0.2f, 1.0f);
  glColor4f(0.9f, 0.3f, 0.1f, 1.0f);
  glVertex3f(-0.2f, -1.1f, -1.0f);
  glColor4f(0.4f, 0.4f, 0.9f, 0.8f);
  glVertex3f(-0.6f, 0.4f, 0.0f);
  glEnd();
  glDisable(GL_FOG);
  glDisable(GL_ALPHA_TEST);

  /* The colour sum past 1 (a float buffer keeps it unclamped). */
  glEnable(GL_COLOR_SUM);
  glBegin(GL_TRIANGLES);
  glColor4f(0.8f, 0.6f, 0.2f, 1.0f);
  glSecondaryColor3f(0.7f, 0.9f, 0.1f);
  glVertex2f(0.9f, 1.1f);
  glColor4f(0.4f, 0.9f, 0.9f, 1.0f);
  glSecondaryColor3f(0.9f, 0.3f, 0.6f);
  glVertex2f(1.5f, 1.1f);
  glVertex2f(1.5f, 0.2f);
  glEnd();
  glDisable(GL_COLOR_SUM);

  /* A scissored clear through a colour mask. */
  glEnable(GL_SCISSOR_TEST);
  glScissor(5, 40, 20, 12);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
  glClearColor(0.77f, 0.5f, 0.123f, 0.9f);
  glClear(GL_COLOR_BUFFER_BIT);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_SCISSOR_TEST);
}

static void logic_op(void) {
  glEnable(GL_COLOR_LOGIC_OP);
  glLogicOp(GL_XOR);
  glBegin(GL_TRIANGLES);
  glColor4f(0.3f, 0.6f, 0.9f, 0.5f);
  glVertex2f(-1.5f, 1.1f);
  glVertex2f(-0.5f, 1.1f);
  glVertex2f(-1.0f, 0.3f);
  glEnd();
  glDisable(GL_COLOR_LOGIC_OP);
}

static void accum(void) {
  glEnable(GL_SCISSOR_TEST);
  glScissor(50, 2, 28, 20);
  glAccum(GL_LOAD, 0.5f);
  glBegin(GL_TRIANGLES);
  glColor4f(0.9f, 0.2f, 0.6f, 1.0f);
  glVertex2f(0.0f, -1.1f);
  glVertex2f(1.5f, 1.1f);
  glVertex2f(-0.5f, 1.1f);
  glEnd();
  glAccum(GL_ACCUM, 0.5f);
  glAccum(GL_RETURN, 1.0f);
  glDisable(GL_SCISSOR_TEST);
  /* A draw, so that Mesa copies its buffer to the caller's at glFinish. */
  glBegin(GL_POINTS);
  glColor4f(1, 1, 1, 1);
  glVertex2f(-1.49f, -1.09f);
  glEnd();
}

int main(int argc, char **argv) {
  start(argc, argv);
  const GLenum types[] = {GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_FLOAT};
  const char *names[] = {"ubyte", "ushort", "float"};
  const int sizes[] = {1, 2, 4};
  static float read[W * H * 4];
  for (int t = 0; t < 3; t++) {
    for (int pass = 0; pass < 2; pass++) {
      void *buf = calloc((size_t)W * H * 4, sizes[t]);
      OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, NULL);
      CHECK(ctx && buf);
      CHECK(OSMesaMakeCurrent(ctx, buf, types[t], W, H));
      if (pass == 1) OSMesaColorClamp(GL_TRUE);
      GLint bits[4];
      glGetIntegerv(GL_RED_BITS, &bits[0]);
      glGetIntegerv(GL_GREEN_BITS, &bits[1]);
      glGetIntegerv(GL_BLUE_BITS, &bits[2]);
      glGetIntegerv(GL_ALPHA_BITS, &bits[3]);
      GLint type = 0;
      OSMesaGetIntegerv(OSMESA_TYPE, &type);
      printf("%s pass %d: bits %d %d %d %d type 0x%x\n", names[t], pass, bits[0], bits[1], bits[2], bits[3], type);
      scene();
      if (t < 2) logic_op();
      accum();
      glFinish();
      printf("%s pass %d: error 0x%x\n", names[t], pass, glGetError());
      char file[64];
      snprintf(file, sizeof file, "%s.%d.color", names[t], pass);
      dump(file, buf, (size_t)W * H * 4 * sizes[t]);
      glReadPixels(0, 0, W, H, GL_RGBA, GL_FLOAT, read);
      snprintf(file, sizeof file, "%s.%d.read", names[t], pass);
      dump(file, read, sizeof read);
      static unsigned char bytes[W * H * 4];
      static unsigned short shorts[W * H * 4];
      glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, bytes);
      snprintf(file, sizeof file, "%s.%d.read_ubyte", names[t], pass);
      dump(file, bytes, sizeof bytes);
      glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_SHORT, shorts);
      snprintf(file, sizeof file, "%s.%d.read_ushort", names[t], pass);
      dump(file, shorts, sizeof shorts);
      OSMesaDestroyContext(ctx);
      free(buf);
    }
  }
  printf("done\n");
  return 0;
}
