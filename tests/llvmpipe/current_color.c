/* The current colour under perspective against Mesa's llvmpipe (OSMesa):
 * whether a colour is read as a constant (the current value, a uniform of
 * Mesa's fixed-function fragment shader) or interpolated from the vertices
 * (docs/llvmpipe-facts.md §20). One 32x32 scene per line of
 * current_color.txt, "name hex" (the RGBA bytes of the colour buffer, bottom
 * row first); tests/current_color.rs makes the same calls through softgl:
 *
 *   gcc -O1 -o /tmp/current_color tests/llvmpipe/current_color.c -lOSMesa
 *   (cd tests/llvmpipe && MESA_SHADER_CACHE_DISABLE=true /tmp/current_color > current_color.txt)
 *
 * Every scene draws untextured floor quads in perspective (glFrustum), left
 * half x in [-4, 0], right half x in [0, 4], from z = -1.5 to z = -30. */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <string.h>

#define N 32
static unsigned char buf[N * N * 4];

static const float A[4] = {0.3f, 0.55f, 0.7f, 0.9f};
static const float B[4] = {0.15f, 0.45f, 0.85f, 0.35f};

/* The floor quad of half `h` (0 left, 1 right); `c` per vertex when given. */
static void quad(int h, const float *c) {
  float x0 = h ? 0.0f : -4.0f, x1 = x0 + 4.0f;
  float v[4][2] = {{x0, -1.5f}, {x1, -1.5f}, {x1, -30.0f}, {x0, -30.0f}};
  glBegin(GL_QUADS);
  for (int i = 0; i < 4; i++) {
    if (c) glColor4fv(c);
    glVertex3f(v[i][0], -1.0f, v[i][1]);
  }
  glEnd();
}

static void arrays(const float *c) {
  float pos[4][3] = {{-4, -1, -1.5f}, {4, -1, -1.5f}, {4, -1, -30}, {-4, -1, -30}};
  float col[16];
  for (int i = 0; i < 16; i++) col[i] = A[i % 4];
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, pos);
  if (c) {
    glEnableClientState(GL_COLOR_ARRAY);
    glColorPointer(4, GL_FLOAT, 0, col);
  }
  glDrawArrays(GL_QUADS, 0, 4);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

static void scene(const char *name) {
  glViewport(0, 0, N, N);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1, 1, -1, 1, 1, 40);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glShadeModel(GL_SMOOTH);
  glDisable(GL_COLOR_SUM);
  glSecondaryColor3f(0, 0, 0);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  /* The left quad (colour A) shows the difference: interpolated, 142 of its
     pixels are an ulp off the constant; colour B interpolates exactly here. */
  if (!strcmp(name, "outside")) {
    /* glColor before glBegin: constant. */
    glColor4fv(A);
    quad(0, NULL);
    glColor4fv(B);
    quad(1, NULL);
  } else if (!strcmp(name, "inside")) {
    /* The same colours given per vertex: interpolated. */
    quad(0, A);
    quad(1, B);
  } else if (!strcmp(name, "again")) {
    /* No state call between: A, set outside, enters Mesa's vertex format
       after the first quad's vertices, so the left quad interpolates it. */
    glColor4fv(B);
    quad(1, NULL);
    glColor4fv(A);
    quad(0, NULL);
  } else if (!strcmp(name, "flushed")) {
    /* A state call between (glLoadIdentity flushes): constant again. */
    glColor4fv(B);
    quad(1, NULL);
    glLoadIdentity();
    glColor4fv(A);
    quad(0, NULL);
  } else if (!strcmp(name, "finished")) {
    /* glFinish flushes as well: constant. */
    glColor4fv(B);
    quad(1, NULL);
    glFinish();
    glColor4fv(A);
    quad(0, NULL);
  } else if (!strcmp(name, "many")) {
    /* More than 8 vertices buffered: the new colour empties the format. */
    glColor4fv(B);
    quad(1, NULL);
    quad(1, NULL);
    quad(1, NULL);
    glColor4fv(A);
    quad(0, NULL);
  } else if (!strcmp(name, "flat")) {
    glShadeModel(GL_FLAT);
    glColor4fv(A);
    quad(0, NULL);
    quad(1, B);
  } else if (!strcmp(name, "color_sum")) {
    /* Both colours current: constants. */
    glEnable(GL_COLOR_SUM);
    glSecondaryColor3f(0.2f, 0.1f, 0.05f);
    glColor4fv(A);
    quad(0, NULL);
  } else if (!strcmp(name, "color_sum_mixed")) {
    /* A per-vertex colour with the current secondary colour. */
    glEnable(GL_COLOR_SUM);
    glSecondaryColor3f(0.2f, 0.1f, 0.05f);
    quad(0, A);
  } else if (!strcmp(name, "arrays_current")) {
    glColor4fv(A);
    arrays(NULL);
  } else if (!strcmp(name, "arrays_color")) {
    arrays(A);
  }
  glFinish();
  printf("%s ", name);
  for (int i = 0; i < N * N * 4; i++) printf("%02x", buf[i]);
  printf("\n");
}

int main(void) {
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, N, N)) return 1;
  const char *names[] = {"outside", "inside",         "again",          "flushed",     "finished", "many",
                         "flat",    "color_sum",      "color_sum_mixed", "arrays_current", "arrays_color"};
  for (unsigned i = 0; i < sizeof names / sizeof *names; i++) scene(names[i]);
  OSMesaDestroyContext(ctx);
  return 0;
}
