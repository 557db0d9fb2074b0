/* The accumulation buffer: motion-blur accumulation of several frames,
 * LOAD/ACCUM/MULT/ADD/RETURN with values beyond [0, 1] (shorts that wrap),
 * scissored operations and clears, the colour mask on GL_RETURN, display
 * lists, glPushAttrib(GL_ACCUM_BUFFER_BIT), the queries and the errors.
 * Writes one colour image per step (<format>.<step>.color) and prints one
 * line per query; the test compares both with Mesa's, byte for byte. */
#include "common.h"

#define W 64
#define H 48

#define E(call) do { call; printf("%-56s 0x%04x\n", #call, glGetError()); } while (0)

static void tri(float dx, float dy) {
  glBegin(GL_TRIANGLES);
  glColor4f(1.0f, 0.2f, 0.1f, 0.9f);
  glVertex2f(-0.8f + dx, -0.7f + dy);
  glColor4f(0.1f, 0.9f, 0.3f, 0.4f);
  glVertex2f(0.6f + dx, -0.5f + dy);
  glColor4f(0.2f, 0.4f, 1.0f, 0.7f);
  glVertex2f(-0.1f + dx, 0.8f + dy);
  glEnd();
}

static void print_state(const char *what) {
  GLint bits[4];
  GLfloat clear[4];
  glGetIntegerv(GL_ACCUM_RED_BITS, &bits[0]);
  glGetIntegerv(GL_ACCUM_GREEN_BITS, &bits[1]);
  glGetIntegerv(GL_ACCUM_BLUE_BITS, &bits[2]);
  glGetIntegerv(GL_ACCUM_ALPHA_BITS, &bits[3]);
  glGetFloatv(GL_ACCUM_CLEAR_VALUE, clear);
  printf("%s: bits %d %d %d %d clear %.6f %.6f %.6f %.6f error 0x%04x\n", what, bits[0], bits[1], bits[2],
         bits[3], clear[0], clear[1], clear[2], clear[3], glGetError());
}

/* Each step is read back with glReadPixels (<name>.<step>.read) and the
 * caller's buffer is written too (<name>.<step>.color). Mesa's OSMesa copies
 * its colour buffer into the caller's at glFinish only when a draw or a clear
 * marked it since the last copy (st_manager_flush_frontbuffer's `defined`),
 * so after a glAccum(GL_RETURN) alone Mesa's .color is stale: the test
 * compares the .read files with Mesa's, and softgl's .color with its .read. */
static void steps(const char *name, void *buf, int bpp) {
  char file[64];
  int step = 0;
  static unsigned char read[W * H * 4];
#define SAVE() do { \
    glFinish(); \
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, read); \
    snprintf(file, sizeof file, "%s.%d.read", name, step); dump(file, read, sizeof read); \
    snprintf(file, sizeof file, "%s.%d.color", name, step++); dump(file, buf, (size_t)W * H * bpp); \
  } while (0)
  glViewport(0, 0, W, H);
  glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
  glClearAccum(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_ACCUM_BUFFER_BIT);

  /* Motion blur: four frames, each a quarter. */
  for (int f = 0; f < 4; f++) {
    glClear(GL_COLOR_BUFFER_BIT);
    tri(0.07f * f, 0.03f * f);
    glAccum(f == 0 ? GL_LOAD : GL_ACCUM, 0.25f);
  }
  glAccum(GL_RETURN, 1.0f);
  SAVE();
  /* Returned brighter, beyond 1 (clamped by the colour buffer). */
  glAccum(GL_RETURN, 1.7f);
  SAVE();
  /* MULT and ADD, negative and past 1. */
  glAccum(GL_MULT, 1.9f);
  glAccum(GL_ADD, -0.15f);
  glAccum(GL_RETURN, 1.0f);
  SAVE();
  glAccum(GL_RETURN, -0.5f);
  SAVE();
  /* Overflow: the shorts wrap. */
  glAccum(GL_ACCUM, 0.9f);
  glAccum(GL_ACCUM, 0.9f);
  glAccum(GL_RETURN, 0.6f);
  SAVE();
  glAccum(GL_MULT, 3.3f);
  glAccum(GL_RETURN, 1.0f);
  SAVE();
  glAccum(GL_ADD, 0.8f);
  glAccum(GL_ADD, 0.8f);
  glAccum(GL_RETURN, 1.0f);
  SAVE();
  /* Clear values beyond [-1, 1] are clamped; odd ones round as Mesa's FLOAT_TO_SHORT. */
  glClearAccum(-0.5f, 0.3f, 1.5f, 0.7f);
  glClear(GL_ACCUM_BUFFER_BIT);
  glAccum(GL_RETURN, 1.0f);
  SAVE();
  glAccum(GL_RETURN, -1.0f);
  SAVE();
  glClearAccum(0.123f, 0.456f, 0.789f, 0.333f);
  glClear(GL_ACCUM_BUFFER_BIT);
  glAccum(GL_RETURN, 1.0f);
  SAVE();
  /* Scissored: clear, load, mult and return inside a box only. */
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  tri(0.0f, 0.0f);
  glAccum(GL_LOAD, 1.0f);
  glEnable(GL_SCISSOR_TEST);
  glScissor(10, 7, 30, 25);
  glClearAccum(0.25f, 0.5f, 0.75f, 1.0f);
  glClear(GL_ACCUM_BUFFER_BIT);
  glScissor(20, 12, 40, 30);
  glAccum(GL_MULT, 0.5f);
  glAccum(GL_ACCUM, 0.3f);
  glScissor(5, 3, 50, 40);
  glAccum(GL_RETURN, 1.0f);
  SAVE();
  glDisable(GL_SCISSOR_TEST);
  /* The colour mask on GL_RETURN. */
  glClearColor(0.5f, 0.5f, 0.5f, 0.5f);
  glClear(GL_COLOR_BUFFER_BIT);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
  glAccum(GL_RETURN, 1.0f);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  SAVE();
  /* Blending, depth test and alpha test do not apply to GL_RETURN. */
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_NEVER, 0.0f);
  glAccum(GL_RETURN, 0.8f);
  glDisable(GL_BLEND);
  glDisable(GL_ALPHA_TEST);
  SAVE();
  /* In a display list. */
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glClearAccum(0.6f, 0.1f, 0.2f, 0.9f);
  glClear(GL_ACCUM_BUFFER_BIT);
  glAccum(GL_ACCUM, 0.5f);
  glAccum(GL_RETURN, 0.9f);
  glEndList();
  print_state("after compiling");
  glClear(GL_COLOR_BUFFER_BIT);
  tri(-0.1f, 0.05f);
  glCallList(list);
  SAVE();
  print_state("after the list");
  /* The attribute stack. */
  glPushAttrib(GL_ACCUM_BUFFER_BIT);
  glClearAccum(-0.25f, 0.75f, -2.0f, 0.5f);
  print_state("pushed and changed");
  glPopAttrib();
  print_state("popped");
  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glClearAccum(-0.25f, 0.75f, -2.0f, 0.5f);
  glPopAttrib();
  print_state("colour bit popped");
  /* Errors. */
  E(glAccum(0x0105, 1.0f));
  E(glAccum(GL_ADD + 0x100, 1.0f));
  glBegin(GL_TRIANGLES);
  glAccum(GL_LOAD, 1.0f);
  glEnd();
  printf("in begin/end 0x%04x\n", glGetError());
  E(glAccum(GL_RETURN, 1.0f));
  glDeleteLists(list, 1);
#undef SAVE
}

int main(int argc, char **argv) {
  start(argc, argv);
  static unsigned char rgba[W * H * 4], bgra[W * H * 4], rgb565[W * H * 2], plain[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, NULL);
  CHECK(ctx);
  CHECK(OSMesaMakeCurrent(ctx, rgba, GL_UNSIGNED_BYTE, W, H));
  print_state("rgba");
  steps("rgba", rgba, 4);
  OSMesaDestroyContext(ctx);

  const int attribs[] = {OSMESA_FORMAT, OSMESA_BGRA, OSMESA_ACCUM_BITS, 8, 0};
  ctx = OSMesaCreateContextAttribs(attribs, NULL);
  CHECK(ctx);
  CHECK(OSMesaMakeCurrent(ctx, bgra, GL_UNSIGNED_BYTE, W, H));
  print_state("bgra");
  steps("bgra", bgra, 4);
  OSMesaDestroyContext(ctx);

  ctx = OSMesaCreateContextExt(OSMESA_RGB_565, 0, 0, 32, NULL);
  CHECK(ctx);
  CHECK(OSMesaMakeCurrent(ctx, rgb565, GL_UNSIGNED_SHORT_5_6_5, W, H));
  print_state("rgb565");
  steps("rgb565", rgb565, 2);
  OSMesaDestroyContext(ctx);

  /* Without an accumulation buffer. */
  ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(ctx);
  CHECK(OSMesaMakeCurrent(ctx, plain, GL_UNSIGNED_BYTE, W, H));
  print_state("none");
  E(glAccum(GL_LOAD, 1.0f));
  E(glAccum(0x0105, 1.0f));
  E(glClear(GL_ACCUM_BUFFER_BIT));
  E(glClearAccum(0.5f, 0.5f, 0.5f, 0.5f));
  print_state("none after ClearAccum");
  OSMesaDestroyContext(ctx);
  printf("done\n");
  return 0;
}
