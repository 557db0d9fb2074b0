/* GL 1.3-1.4's small entry points, loaded through OSMesaGetProcAddress:
 * point parameters (size bounds, distance attenuation under a perspective
 * projection, in a display list, in glPushAttrib(GL_POINT_BIT)), the
 * transposed matrices, glSampleCoverage's state, their queries and errors.
 * The image and every printed line are compared with Mesa's (llvmpipe). */
#include "common.h"
#include <GL/glext.h>

#define W 128
#define H 96
#define E(call) do { call; printf("%-60s 0x%04x\n", #call, glGetError()); } while (0)

static PFNGLPOINTPARAMETERFPROC PointParameterf;
static PFNGLPOINTPARAMETERFVPROC PointParameterfv;
static PFNGLPOINTPARAMETERIPROC PointParameteri;
static PFNGLPOINTPARAMETERIVPROC PointParameteriv;
static PFNGLPOINTPARAMETERFVARBPROC PointParameterfvARB;
/* (gl.h declares GL 1.3's functions but not their pointer types.) */
static void (*LoadTransposeMatrixf)(const GLfloat *);
static void (*LoadTransposeMatrixd)(const GLdouble *);
static void (*MultTransposeMatrixf)(const GLfloat *);
static void (*MultTransposeMatrixd)(const GLdouble *);
static void (*SampleCoverage)(GLclampf, GLboolean);

#define LOAD(var, name) do { var = (void *)OSMesaGetProcAddress(name); CHECK(var); } while (0)

static void point_state(const char *what) {
  GLfloat min = -1, max = -1, fade = -1, att[3] = {-1, -1, -1};
  glGetFloatv(GL_POINT_SIZE_MIN, &min);
  glGetFloatv(GL_POINT_SIZE_MAX, &max);
  glGetFloatv(GL_POINT_FADE_THRESHOLD_SIZE, &fade);
  glGetFloatv(GL_POINT_DISTANCE_ATTENUATION, att);
  printf("%s: min %g max %g fade %g attenuation %g %g %g error 0x%x\n", what, min, max, fade, att[0], att[1],
         att[2], glGetError());
}

/* A row of points at depths from near to far, at height y. */
static void row(float y) {
  glBegin(GL_POINTS);
  for (int i = 0; i < 9; i++) {
    float z = -1.5f - i * 1.1f;
    /* x spread so the points land 13 pixels apart whatever their depth. */
    float x = (-0.8f + i * 0.2f) * -z;
    glColor3f(1, 1 - i / 9.0f, i / 9.0f);
    glVertex3f(x, y * -z, z);
  }
  glEnd();
}

int main(int argc, char **argv) {
  start(argc, argv);
  static unsigned char buf[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
  LOAD(PointParameterf, "glPointParameterf");
  LOAD(PointParameterfv, "glPointParameterfv");
  LOAD(PointParameteri, "glPointParameteri");
  LOAD(PointParameteriv, "glPointParameteriv");
  LOAD(PointParameterfvARB, "glPointParameterfvARB");
  LOAD(LoadTransposeMatrixf, "glLoadTransposeMatrixf");
  LOAD(LoadTransposeMatrixd, "glLoadTransposeMatrixd");
  LOAD(MultTransposeMatrixf, "glMultTransposeMatrixf");
  LOAD(MultTransposeMatrixd, "glMultTransposeMatrixd");
  LOAD(SampleCoverage, "glSampleCoverage");
  CHECK(OSMesaGetProcAddress("glPointParameterfEXT"));
  CHECK(OSMesaGetProcAddress("glSampleCoverageARB"));

  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  point_state("initial");

  /* A perspective projection given transposed (row major), then the same
   * frustum as glFrustum would make, compared. */
  const float n = 1, f = 20, r = 1, t = 0.75f;
  GLfloat rows[16] = {n / r, 0, 0, 0, 0, n / t, 0, 0, 0, 0, -(f + n) / (f - n), -2 * f * n / (f - n), 0, 0, -1, 0};
  glMatrixMode(GL_PROJECTION);
  E(LoadTransposeMatrixf(rows));
  GLfloat m[16];
  glGetFloatv(GL_PROJECTION_MATRIX, m);
  printf("projection column 2: %g %g %g %g, column 3: %g %g %g %g\n", m[8], m[9], m[10], m[11], m[12], m[13],
         m[14], m[15]);
  GLfloat tm[16];
  glGetFloatv(GL_TRANSPOSE_PROJECTION_MATRIX, tm);
  printf("transpose query row 3: %g %g %g %g error 0x%x\n", tm[12], tm[13], tm[14], tm[15], glGetError());
  glMatrixMode(GL_MODELVIEW);
  GLdouble shift[16] = {1, 0, 0, 0.05, 0, 1, 0, -0.02, 0, 0, 1, 0, 0, 0, 0, 1};
  E(LoadTransposeMatrixd(shift));
  GLfloat ident[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  E(MultTransposeMatrixf(ident));
  E(MultTransposeMatrixd(shift));
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  printf("modelview translation %g %g %g\n", m[12], m[13], m[14]);
  glLoadIdentity();

  /* Plain points of size 6, bounded to 2..4 by the parameters. */
  glPointSize(6);
  row(0.6f);
  E(PointParameterf(GL_POINT_SIZE_MIN, 2));
  E(PointParameterf(GL_POINT_SIZE_MAX, 4));
  row(0.4f);
  /* Attenuated: 1 / sqrt(a + b d + c d^2). */
  glPointSize(24);
  E(PointParameterf(GL_POINT_SIZE_MIN, 0));
  E(PointParameterf(GL_POINT_SIZE_MAX, 100));
  GLfloat att[3] = {0.25f, 0.1f, 0.05f};
  E(PointParameterfv(GL_POINT_DISTANCE_ATTENUATION, att));
  point_state("attenuated");
  row(0.15f);
  /* Attenuated and bounded. */
  E(PointParameteri(GL_POINT_SIZE_MIN, 5));
  GLint maxi = 9;
  E(PointParameteriv(GL_POINT_SIZE_MAX, &maxi));
  row(-0.15f);
  /* Attenuated points from a display list; the parameters are compiled. */
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  PointParameterf(GL_POINT_SIZE_MIN, 0);
  PointParameterf(GL_POINT_SIZE_MAX, 30);
  GLfloat quad[3] = {0, 0, 0.02f};
  PointParameterfvARB(GL_POINT_DISTANCE_ATTENUATION, quad);
  row(-0.4f);
  glEndList();
  point_state("after compile");
  /* The point bit keeps them. */
  E(glPushAttrib(GL_POINT_BIT));
  glCallList(list);
  point_state("after the list");
  E(glPopAttrib());
  point_state("popped");
  /* A point of fade threshold: state only. */
  E(PointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 3.5f));
  GLfloat one[3] = {1, 0, 0};
  E(PointParameterfv(GL_POINT_DISTANCE_ATTENUATION, one));
  glPointSize(3);
  row(-0.6f);
  point_state("end");

  /* Errors. */
  E(PointParameterf(GL_POINT_SIZE_MIN, -1));
  E(PointParameterf(GL_POINT_SIZE_MAX, -1));
  E(PointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, -1));
  E(PointParameterf(GL_TEXTURE_2D, 1));
  E(LoadTransposeMatrixf(NULL));
  glBegin(GL_POINTS);
  PointParameterf(GL_POINT_SIZE_MIN, 1);
  glEnd();
  printf("inside begin 0x%x\n", glGetError());

  /* Sample coverage: state and queries. */
  GLfloat cv = -1;
  GLboolean ci = 7;
  glGetFloatv(GL_SAMPLE_COVERAGE_VALUE, &cv);
  glGetBooleanv(GL_SAMPLE_COVERAGE_INVERT, &ci);
  printf("coverage %g invert %d\n", cv, ci);
  E(SampleCoverage(0.25f, GL_TRUE));
  glGetFloatv(GL_SAMPLE_COVERAGE_VALUE, &cv);
  glGetBooleanv(GL_SAMPLE_COVERAGE_INVERT, &ci);
  printf("coverage %g invert %d\n", cv, ci);
  E(SampleCoverage(3.0f, GL_FALSE));
  glGetFloatv(GL_SAMPLE_COVERAGE_VALUE, &cv);
  printf("coverage clamped %g\n", cv);

  /* Colour-index state of an RGBA context: kept, queried, without effect. */
  GLint iv = 7;
  GLfloat fv = 7;
  glGetFloatv(GL_INDEX_CLEAR_VALUE, &fv);
  glGetIntegerv(GL_INDEX_WRITEMASK, &iv);
  printf("index clear %g mask %d\n", fv, iv);
  E(glClearIndex(3.5f));
  E(glIndexMask(0x0f));
  E(glPushAttrib(GL_COLOR_BUFFER_BIT));
  glClearIndex(1);
  glIndexMask(0xff);
  E(glPopAttrib());
  glGetFloatv(GL_INDEX_CLEAR_VALUE, &fv);
  glGetIntegerv(GL_INDEX_WRITEMASK, &iv);
  printf("index clear %g mask %d after pop\n", fv, iv);
  static const GLshort idx[8] = {1, 2, 3, 4, 5, 6, 7, 8};
  E(glIndexPointer(GL_SHORT, 4, idx));
  E(glIndexPointer(GL_BYTE, 0, idx));
  E(glIndexPointer(GL_SHORT, -1, idx));
  E(glEnableClientState(GL_INDEX_ARRAY));
  GLint ty = 0;
  glGetIntegerv(GL_INDEX_ARRAY_TYPE, &ty);
  void *ip = NULL;
  glGetPointerv(GL_INDEX_ARRAY_POINTER, &ip);
  printf("index array on %d type 0x%x pointer same %d error 0x%x\n", glIsEnabled(GL_INDEX_ARRAY), ty,
         ip == (void *)idx, glGetError());
  static const GLfloat tri3[6] = {0.9f, 0.9f, 0.95f, 0.9f, 0.9f, 0.95f};
  glLoadIdentity();
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glVertexPointer(2, GL_FLOAT, 0, tri3);
  glEnableClientState(GL_VERTEX_ARRAY);
  E(glDrawArrays(GL_TRIANGLES, 0, 3));
  E(glDisableClientState(GL_INDEX_ARRAY));
  E(glEnableClientState(GL_EDGE_FLAG_ARRAY));
  printf("edge flag array on %d\n", glIsEnabled(GL_EDGE_FLAG_ARRAY));
  glDisableClientState(GL_EDGE_FLAG_ARRAY);

  glFinish();
  dump("gl14.color", buf, sizeof buf);
  OSMesaDestroyContext(ctx);
  printf("done\n");
  return 0;
}
