/* Occlusion queries (GL 1.5), functions loaded through OSMesaGetProcAddress:
 * exact GL_SAMPLES_PASSED counts for triangles, quads, strips, lines, wide
 * lines and points, with the scissor, alpha, stencil and depth tests
 * rejecting some fragments, a query over several draws, one over nothing
 * drawn and one over a clear only, begin/end compiled into a display list,
 * the query state and GL's errors. Every printed line and the image are
 * compared with Mesa's (llvmpipe). */
#include "common.h"
#include <GL/glext.h>

#define W 96
#define H 80
#define E(call) do { call; printf("%-60s 0x%04x\n", #call, glGetError()); } while (0)

static PFNGLGENQUERIESPROC GenQueries;
static PFNGLDELETEQUERIESPROC DeleteQueries;
static PFNGLISQUERYPROC IsQuery;
static PFNGLBEGINQUERYPROC BeginQuery;
static PFNGLENDQUERYPROC EndQuery;
static PFNGLGETQUERYIVPROC GetQueryiv;
static PFNGLGETQUERYOBJECTIVPROC GetQueryObjectiv;
static PFNGLGETQUERYOBJECTUIVPROC GetQueryObjectuiv;
static PFNGLBEGINQUERYARBPROC BeginQueryARB;

#define LOAD(var, name) do { var = (void *)OSMesaGetProcAddress(name); CHECK(var); } while (0)

static GLuint q[4];

/* Runs `draw` inside query q[0] and prints its count. */
static void count(const char *what, void (*draw)(void)) {
  BeginQuery(GL_SAMPLES_PASSED, q[0]);
  draw();
  EndQuery(GL_SAMPLES_PASSED);
  GLuint n = 12345, avail = 7;
  GetQueryObjectuiv(q[0], GL_QUERY_RESULT_AVAILABLE, &avail);
  GetQueryObjectuiv(q[0], GL_QUERY_RESULT, &n);
  printf("%-28s %6u available %u error 0x%x\n", what, n, avail, glGetError());
}

static void tri(float x, float y, float s, float z) {
  glBegin(GL_TRIANGLES);
  glVertex3f(x, y, z);
  glVertex3f(x + s, y + 0.3f * s, z);
  glVertex3f(x + 0.2f * s, y + s, z);
  glEnd();
}

static void triangles(void) {
  glColor3f(1, 0, 0);
  tri(2.3f, 3.1f, 30, 0);
  tri(40.5f, 10.7f, 21.3f, 0);
}
static void quads(void) {
  glColor3f(0, 1, 0);
  glBegin(GL_QUADS);
  glVertex2f(60.2f, 2.6f); glVertex2f(90.1f, 5.3f); glVertex2f(88.4f, 30.9f); glVertex2f(58.7f, 28.2f);
  glEnd();
}
static void strip(void) {
  glColor3f(0, 0, 1);
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i < 8; i++) glVertex2f(4.5f + i * 5.7f, 40.25f + (i & 1) * 9.5f);
  glEnd();
}
static void lines(void) {
  glColor3f(1, 1, 0);
  glBegin(GL_LINES);
  glVertex2f(3.5f, 60.5f); glVertex2f(50.5f, 70.2f);
  glVertex2f(10.2f, 75.3f); glVertex2f(10.7f, 52.5f);
  glEnd();
  glLineWidth(3);
  glBegin(GL_LINE_STRIP);
  glVertex2f(55.5f, 52.5f); glVertex2f(90.5f, 58.2f); glVertex2f(70.2f, 77.5f);
  glEnd();
  glLineWidth(1);
}
static void points(void) {
  glColor3f(0, 1, 1);
  glBegin(GL_POINTS);
  for (int i = 0; i < 10; i++) glVertex2f(2.5f + i * 9.1f, 36.5f);
  glEnd();
  glPointSize(4);
  glBegin(GL_POINTS);
  glVertex2f(20.5f, 33.5f); glVertex2f(47.2f, 34.9f);
  glEnd();
  glPointSize(1);
}
/* Everything again, so that depth (GL_LESS) rejects it all. */
static void everything(void) {
  triangles(); quads(); strip(); lines(); points();
}
static void nothing(void) {}
static void clear_only(void) { glClear(GL_COLOR_BUFFER_BIT); }
static void offscreen(void) { tri(200, 200, 30, 0); tri(-50, 10, 20, 0); }
static void nearer(void) {
  /* At depth -0.5 (nearer than 0): passes GL_LESS where drawn before. */
  glColor3f(1, 1, 1);
  tri(10.5f, 5.5f, 60, -0.5f);
}
static void alpha_tested(void) {
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.5f);
  glBegin(GL_TRIANGLES);
  glColor4f(1, 1, 1, 0); glVertex3f(5, 5, -0.7f);
  glColor4f(1, 1, 1, 1); glVertex3f(90, 10, -0.7f);
  glColor4f(1, 1, 1, 1); glVertex3f(30, 75, -0.7f);
  glEnd();
  glDisable(GL_ALPHA_TEST);
}
static void scissored(void) {
  glEnable(GL_SCISSOR_TEST);
  glScissor(20, 15, 33, 21);
  tri(0.5f, 0.5f, 90, -0.8f);
  glDisable(GL_SCISSOR_TEST);
}
static void stenciled(void) {
  /* Stencil is 1 where the strip was drawn (set below); only there passes. */
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  tri(0.5f, 30.5f, 60, -0.9f);
  glDisable(GL_STENCIL_TEST);
}
static void masked(void) {
  /* Nothing written (colour and depth masks off): still counted. */
  glColorMask(0, 0, 0, 0);
  glDepthMask(0);
  tri(50.5f, 40.5f, 40, -0.95f);
  glColorMask(1, 1, 1, 1);
  glDepthMask(1);
}

int main(int argc, char **argv) {
  start(argc, argv);
  static unsigned char buf[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
  LOAD(GenQueries, "glGenQueries");
  LOAD(DeleteQueries, "glDeleteQueries");
  LOAD(IsQuery, "glIsQuery");
  LOAD(BeginQuery, "glBeginQuery");
  LOAD(EndQuery, "glEndQuery");
  LOAD(GetQueryiv, "glGetQueryiv");
  LOAD(GetQueryObjectiv, "glGetQueryObjectiv");
  LOAD(GetQueryObjectuiv, "glGetQueryObjectuiv");
  LOAD(BeginQueryARB, "glBeginQueryARB");

  glClearColor(0, 0, 0, 1);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, W, 0, H, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);

  GLint v = -1;
  GetQueryiv(GL_SAMPLES_PASSED, GL_QUERY_COUNTER_BITS, &v);
  printf("counter bits %d\n", v);
  GetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &v);
  printf("current %d\n", v);
  GenQueries(4, q);
  printf("gen %u %u %u %u is %d\n", q[0], q[1], q[2], q[3], IsQuery(q[0]));

  count("nothing", nothing);
  printf("is after use %d\n", IsQuery(q[0]));
  count("clear only", clear_only);
  count("triangles", triangles);
  count("quads", quads);
  /* The strip sets stencil 1 where it draws. */
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  count("strip", strip);
  glDisable(GL_STENCIL_TEST);
  count("lines", lines);
  count("points", points);
  count("all again, depth rejects", everything);
  count("off screen", offscreen);
  count("nearer", nearer);
  count("alpha test", alpha_tested);
  count("scissor", scissored);
  count("stencil", stenciled);
  count("masks off", masked);

  /* A query over several draws and a state change, with another query's
   * result asked for in between (the draws of q[1] are still counted). */
  BeginQuery(GL_SAMPLES_PASSED, q[1]);
  glDepthFunc(GL_ALWAYS);
  triangles();
  GetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &v);
  printf("current during %d\n", v);
  GLuint n = 0;
  GetQueryObjectuiv(q[0], GL_QUERY_RESULT, &n);
  printf("q0 during q1 %u error 0x%x\n", n, glGetError());
  quads();
  glDisable(GL_DEPTH_TEST);
  strip();
  points();
  EndQuery(GL_SAMPLES_PASSED);
  GLint ni = -1;
  GetQueryObjectiv(q[1], GL_QUERY_RESULT, &ni);
  printf("several draws %d error 0x%x\n", ni, glGetError());

  /* Begin and end compiled into a list, run twice (the count restarts). */
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  BeginQuery(GL_SAMPLES_PASSED, q[2]);
  quads();
  EndQuery(GL_SAMPLES_PASSED);
  glEndList();
  printf("compiled: is %d error 0x%x\n", IsQuery(q[2]), glGetError());
  glCallList(list);
  glCallList(list);
  GetQueryObjectuiv(q[2], GL_QUERY_RESULT, &n);
  printf("from a list %u error 0x%x\n", n, glGetError());

  /* Errors. */
  E(BeginQuery(GL_TEXTURE_2D, q[3]));
  E(BeginQuery(GL_SAMPLES_PASSED, 0));
  E(EndQuery(GL_SAMPLES_PASSED));
  E(EndQuery(GL_TEXTURE_2D));
  E(BeginQueryARB(GL_SAMPLES_PASSED, q[3]));
  E(BeginQuery(GL_SAMPLES_PASSED, q[3]));
  E(BeginQuery(GL_SAMPLES_PASSED, q[2]));
  E(GetQueryObjectuiv(q[3], GL_QUERY_RESULT, &n));
  E(GetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &v));
  printf("current %d\n", v);
  E(EndQuery(GL_SAMPLES_PASSED));
  E(GetQueryObjectuiv(q[3], GL_QUERY_RESULT, &n));
  printf("empty %u\n", n);
  E(GetQueryObjectuiv(q[3], GL_TEXTURE_2D, &n));
  E(GetQueryObjectuiv(0, GL_QUERY_RESULT, &n));
  E(GetQueryObjectuiv(1000, GL_QUERY_RESULT, &n));
  GLuint fresh;
  GenQueries(1, &fresh);
  E(GetQueryObjectuiv(fresh, GL_QUERY_RESULT, &n));
  E(GetQueryiv(GL_TEXTURE_2D, GL_CURRENT_QUERY, &v));
  E(GetQueryiv(GL_SAMPLES_PASSED, GL_TEXTURE_2D, &v));
  E(GenQueries(-1, q));
  E(DeleteQueries(-1, q));
  E(BeginQuery(GL_SAMPLES_PASSED, 500));
  printf("begun unnamed is %d\n", IsQuery(500));
  E(DeleteQueries(1, (GLuint[]){500}));
  E(GetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &v));
  printf("current after deleting the active one %d is %d\n", v, IsQuery(500));
  glBegin(GL_TRIANGLES);
  BeginQuery(GL_SAMPLES_PASSED, q[3]);
  glEnd();
  printf("begin inside glBegin 0x%x\n", glGetError());
  E(DeleteQueries(4, q));
  printf("is after delete %d\n", IsQuery(q[0]));

  glFinish();
  dump("queries.color", buf, sizeof buf);
  OSMesaDestroyContext(ctx);
  printf("done\n");
  return 0;
}
