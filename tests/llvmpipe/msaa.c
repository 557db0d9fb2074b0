/* 4x multisampling against Mesa's llvmpipe (OSMesa): each scene is drawn
 * into a 4-sample framebuffer object (GL_RGBA8 and GL_DEPTH24_STENCIL8
 * renderbuffers, glRenderbufferStorageMultisample), resolved into a
 * single-sampled one with glBlitFramebuffer and read back. One scene per
 * line of msaa.txt, "name hex" (the RGBA bytes, bottom row first);
 * tests/multisample.rs makes the same calls through softgl's Rust API on a
 * 4-sample framebuffer (docs/llvmpipe-facts.md §29):
 *
 *   gcc -O1 -o /tmp/msaa tests/llvmpipe/msaa.c -lOSMesa
 *   (cd tests/llvmpipe && MESA_SHADER_CACHE_DISABLE=true /tmp/msaa > msaa.txt)
 */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <string.h>

#define N 40
static unsigned char window[N * N * 4];
static unsigned char out[N * N * 4];

/* Three triangles: x, y, z (eye z; glOrtho(0,N,0,N,-1,1)) per vertex. */
static const float T[3][3][3] = {
    {{2.3f, 3.1f, 0.3f}, {37.6f, 8.4f, 0.5f}, {12.2f, 35.7f, 0.4f}},
    {{30.4f, 2.2f, -0.5f}, {35.9f, 37.3f, -0.2f}, {4.7f, 20.6f, -0.3f}},
    {{1.4f, 38.8f, 0.8f}, {20.9f, 0.6f, 0.7f}, {38.2f, 30.1f, 0.9f}},
};
static const float C[3][4] = {{0.9f, 0.2f, 0.1f, 1.0f}, {0.1f, 0.8f, 0.3f, 0.5f}, {0.2f, 0.3f, 0.9f, 0.7f}};

static void tri(int t) {
  glColor4fv(C[t]);
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 3; i++) glVertex3fv(T[t][i]);
  glEnd();
}

static void scene(const char *name) {
  glViewport(0, 0, N, N);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, N, 0, N, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0.1f, 0.1f, 0.2f, 1.0f);
  glClearDepth(1.0);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  if (!strcmp(name, "depth")) {
    glEnable(GL_DEPTH_TEST);
    tri(0), tri(1), tri(2);
  } else if (!strcmp(name, "blend")) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    tri(0), tri(1), tri(2);
  } else if (!strcmp(name, "smooth")) {
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 3; i++) {
      glColor4fv(C[i]);
      glVertex3fv(T[0][i]);
    }
    glEnd();
  } else if (!strcmp(name, "intersect")) {
    /* The first two triangles' depths cross: the line where they do is
     * decided per sample. */
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_TRIANGLES);
    glColor4fv(C[0]);
    glVertex3f(2.3f, 3.1f, -0.9f), glVertex3f(37.6f, 8.4f, 0.9f), glVertex3f(12.2f, 35.7f, 0.1f);
    glColor4fv(C[1]);
    glVertex3f(30.4f, 2.2f, 0.6f), glVertex3f(35.9f, 37.3f, -0.7f), glVertex3f(4.7f, 20.6f, 0.2f);
    glEnd();
  } else if (!strcmp(name, "coverage")) {
    glEnable(GL_SAMPLE_COVERAGE);
    glSampleCoverage(0.5f, GL_FALSE);
    tri(0);
    glSampleCoverage(0.5f, GL_TRUE);
    tri(2);
  } else if (!strcmp(name, "nomultisample")) {
    glDisable(GL_MULTISAMPLE);
    tri(0), tri(1);
    glEnable(GL_MULTISAMPLE);
    tri(2);
  } else if (!strcmp(name, "lines")) {
    /* Multisampled lines are rectangles covered per sample. */
    static const float L[5][4] = {{3.2f, 4.7f, 36.1f, 9.3f},
                                  {5.6f, 33.4f, 30.2f, 2.9f},
                                  {20.3f, 1.8f, 22.9f, 38.1f},
                                  {2.5f, 20.5f, 37.5f, 20.5f},
                                  {8.0f, 8.0f, 31.0f, 31.0f}};
    static const float W[5] = {1.0f, 1.0f, 2.0f, 3.5f, 6.0f};
    for (int i = 0; i < 5; i++) {
      glLineWidth(W[i]);
      glColor4fv(C[i % 3]);
      glBegin(GL_LINES);
      glVertex2f(L[i][0], L[i][1]);
      glVertex2f(L[i][2], L[i][3]);
      glEnd();
    }
    glLineWidth(1.0f);
  } else if (!strcmp(name, "points")) {
    /* Multisampled points are squares covered per sample. */
    static const float P[6][3] = {{5.3f, 6.1f, 1.0f},   {12.7f, 30.2f, 2.5f}, {20.5f, 20.5f, 4.0f},
                                  {31.1f, 9.9f, 7.3f}, {33.0f, 33.0f, 3.0f},  {8.2f, 19.6f, 0.5f}};
    for (int i = 0; i < 6; i++) {
      glPointSize(P[i][2]);
      glColor4fv(C[i % 3]);
      glBegin(GL_POINTS);
      glVertex2f(P[i][0], P[i][1]);
      glEnd();
    }
    glPointSize(1.0f);
  } else if (!strcmp(name, "stencil")) {
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    tri(0);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilFunc(GL_EQUAL, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glColor4f(1.0f, 1.0f, 0.6f, 1.0f);
    glRectf(0.0f, 0.0f, N, N);
  }
}

static const char *NAMES[] = {"depth", "blend", "smooth", "intersect", "coverage", "nomultisample", "stencil", "lines", "points"};

int main(void) {
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, window, GL_UNSIGNED_BYTE, N, N)) return 1;
  GLint max_samples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  fprintf(stderr, "GL_MAX_SAMPLES %d\n", max_samples);
  for (unsigned k = 0; k < sizeof NAMES / sizeof *NAMES; k++) {
    GLuint fb[2], rb[3];
    glGenFramebuffers(2, fb);
    glGenRenderbuffers(3, rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_RGBA8, N, N);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_DEPTH24_STENCIL8, N, N);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[2]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, N, N);
    glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) return 2;
    GLint samples = 0, buffers = 0;
    glGetIntegerv(GL_SAMPLES, &samples);
    glGetIntegerv(GL_SAMPLE_BUFFERS, &buffers);
    if (samples != 4 || buffers != 1) return 3;
    glBindFramebuffer(GL_FRAMEBUFFER, fb[1]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[2]);
    glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
    scene(NAMES[k]);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[0]);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb[1]);
    glBlitFramebuffer(0, 0, N, N, 0, 0, N, N, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, fb[1]);
    glReadPixels(0, 0, N, N, GL_RGBA, GL_UNSIGNED_BYTE, out);
    if (glGetError() != GL_NO_ERROR) return 4;
    printf("%s ", NAMES[k]);
    for (int i = 0; i < N * N * 4; i++) printf("%02x", out[i]);
    printf("\n");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(2, fb);
    glDeleteRenderbuffers(3, rb);
    glDisable(GL_DEPTH_TEST), glDisable(GL_BLEND), glDisable(GL_STENCIL_TEST), glDisable(GL_SAMPLE_COVERAGE);
  }
  OSMesaDestroyContext(ctx);
  return 0;
}
