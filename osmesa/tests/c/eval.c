/* Evaluators (GL 1.5 section 5.1): a Bezier curve with a colour map
 * (glEvalMesh1 GL_LINE and GL_POINT), a lit bicubic patch with
 * GL_AUTO_NORMAL (glEvalMesh2 GL_FILL; rational GL_MAP2_VERTEX_4 too), a
 * texture-coordinate map and a colour map (GL_FILL, GL_LINE), glEvalCoord
 * and glEvalPoint inside glBegin/glEnd (current values unchanged), a list
 * holding glMap (its points copied at compile time), glPushAttrib
 * (GL_EVAL_BIT), glGetMap's results and the errors. */
#include "common.h"

#define W 128
#define H 96
#define E(call) do { call; printf("%-60s 0x%04x\n", #call, glGetError()); } while (0)

static void print_fv(const char *what, const GLfloat *v, int n) {
  printf("%s", what);
  for (int i = 0; i < n; i++) printf(" %.9g", v[i]);
  printf("\n");
}

int main(int argc, char **argv) {
  start(argc, argv);
  static unsigned char buf[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, W, 0, H, -100, 100);
  glMatrixMode(GL_MODELVIEW);

  GLint iv[4]; GLfloat fv[64]; GLdouble dv[8];
  glGetIntegerv(GL_MAX_EVAL_ORDER, iv); printf("max eval order %d\n", iv[0]);
  glGetFloatv(GL_MAP1_GRID_DOMAIN, fv); print_fv("grid1 domain", fv, 2);
  glGetIntegerv(GL_MAP2_GRID_SEGMENTS, iv); printf("grid2 segments %d %d\n", iv[0], iv[1]);
  glGetMapfv(GL_MAP1_COLOR_4, GL_COEFF, fv); print_fv("default color4", fv, 4);
  glGetMapfv(GL_MAP2_NORMAL, GL_COEFF, fv); print_fv("default normal", fv, 3);
  glGetMapiv(GL_MAP2_VERTEX_4, GL_ORDER, iv); printf("default order %d %d\n", iv[0], iv[1]);
  printf("enabled %d %d\n", glIsEnabled(GL_MAP1_VERTEX_3), glIsEnabled(GL_AUTO_NORMAL));

  /* 1. A cubic Bezier curve, colour from red to blue, as a line strip. */
  GLfloat curve[4][3] = {{4, 4, 0}, {14, 60, 0}, {40, -20, 0}, {50, 40, 0}};
  GLfloat ccol[2][4] = {{1, 0, 0, 1}, {0, 0.5f, 1, 1}};
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 4, &curve[0][0]);
  glMap1f(GL_MAP1_COLOR_4, 0, 1, 4, 2, &ccol[0][0]);
  glEnable(GL_MAP1_VERTEX_3);
  glEnable(GL_MAP1_COLOR_4);
  glMapGrid1f(25, 0, 1);
  glColor3f(0.25f, 0.5f, 0.75f);
  glEvalMesh1(GL_LINE, 0, 25);
  /* The same curve as points, shifted, on part of the grid. */
  glPushMatrix(); glTranslatef(0, 30, 0);
  glEvalMesh1(GL_POINT, 3, 20);
  glPopMatrix();
  glGetFloatv(GL_CURRENT_COLOR, fv); print_fv("current colour after mesh1", fv, 4);
  /* glEvalCoord1 and glEvalPoint1 inside glBegin/glEnd, mixed with glVertex. */
  glPushMatrix(); glTranslatef(60, 0, 0);
  glBegin(GL_LINE_STRIP);
  for (int i = 0; i <= 10; i++) glEvalCoord1f(i / 10.0f);
  glColor3f(1, 1, 1); /* Mesa's current alpha is 0 after evaluation */
  glVertex2f(55, 5);
  glEnd();
  glBegin(GL_POINTS);
  for (int i = 0; i <= 25; i += 5) glEvalPoint1(i);
  glEvalCoord1d(0.33);
  GLdouble u = 0.66; glEvalCoord1dv(&u);
  glEnd();
  glPopMatrix();
  glGetFloatv(GL_CURRENT_COLOR, fv); print_fv("current colour after evalcoord", fv, 4);
  glDisable(GL_MAP1_COLOR_4);

  /* 2. A lit bicubic patch with GL_AUTO_NORMAL. */
  GLfloat patch[4][4][3];
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 4; j++) {
      patch[i][j][0] = 4 + i * 10.0f;
      patch[i][j][1] = 50 + j * 12.0f;
      patch[i][j][2] = ((i == 1 || i == 2) && (j == 1 || j == 2)) ? 20.0f : -5.0f + i * 2.0f;
    }
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  GLfloat lpos[4] = {0.3f, 0.5f, 1, 0};
  glLightfv(GL_LIGHT0, GL_POSITION, lpos);
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 4, 0, 1, 12, 4, &patch[0][0][0]);
  glEnable(GL_MAP2_VERTEX_3);
  glEnable(GL_AUTO_NORMAL);
  glMapGrid2f(10, 0, 1, 8, 0, 1);
  glEvalMesh2(GL_FILL, 0, 10, 0, 8);
  /* The same patch, rational (w = 1 but the middle points weighted 2). */
  GLfloat rpatch[4][4][4];
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 4; j++) {
      GLfloat w = (i == 1 && j == 2) ? 2.0f : 1.0f;
      rpatch[i][j][0] = (patch[i][j][0] + 40) * w;
      rpatch[i][j][1] = patch[i][j][1] * w;
      rpatch[i][j][2] = patch[i][j][2] * w;
      rpatch[i][j][3] = w;
    }
  glMap2f(GL_MAP2_VERTEX_4, 0, 1, 4, 4, 0, 1, 16, 4, &rpatch[0][0][0]);
  glEnable(GL_MAP2_VERTEX_4);
  glEvalMesh2(GL_FILL, 0, 10, 0, 8);
  glGetFloatv(GL_CURRENT_NORMAL, fv); print_fv("current normal after autonormal", fv, 3);
  glDisable(GL_MAP2_VERTEX_4);
  glDisable(GL_LIGHTING);
  glDisable(GL_AUTO_NORMAL);

  /* 3. A texture-coordinate map over a quadratic patch, with a checker. */
  static unsigned char tex[8 * 8 * 4];
  for (int i = 0; i < 64; i++) {
    int on = ((i % 8) / 2 + (i / 8) / 2) % 2;
    tex[i * 4 + 0] = on ? 255 : 30; tex[i * 4 + 1] = on ? 200 : 60;
    tex[i * 4 + 2] = on ? 40 : 220; tex[i * 4 + 3] = 255;
  }
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  GLfloat quad[3][3][3];
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) {
      quad[i][j][0] = 90 + i * 16.0f + (j == 1 ? 6 : 0);
      quad[i][j][1] = 50 + j * 20.0f;
      quad[i][j][2] = 0;
    }
  GLfloat tc[2][2][2] = {{{0, 0}, {0, 2}}, {{2, 0}, {2, 2}}};
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 3, 0, 1, 9, 3, &quad[0][0][0]);
  glMap2f(GL_MAP2_TEXTURE_COORD_2, 0, 1, 2, 2, 0, 1, 4, 2, &tc[0][0][0]);
  glEnable(GL_MAP2_TEXTURE_COORD_2);
  glMapGrid2d(6, 0.0, 1.0, 6, 0.0, 1.0);
  glEvalMesh2(GL_FILL, 0, 6, 0, 6);
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_MAP2_TEXTURE_COORD_2);
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, fv); print_fv("current texcoord", fv, 4);

  /* 4. A colour map over a bilinear patch: lines, then points, then
   * glEvalCoord2/glEvalPoint2 in a triangle strip. */
  GLfloat flat[2][2][3] = {{{70, 4, 0}, {70, 40, 0}}, {{120, 4, 0}, {124, 44, 0}}};
  GLfloat col2[2][2][4] = {{{1, 0, 0, 1}, {0, 1, 0, 1}}, {{0, 0, 1, 1}, {1, 1, 1, 1}}};
  glDisable(GL_DEPTH_TEST);
  glMap2f(GL_MAP2_VERTEX_3, 0, 4, 3, 2, 0, 2, 6, 2, &flat[0][0][0]);
  glMap2f(GL_MAP2_COLOR_4, 0, 4, 4, 2, 0, 2, 8, 2, &col2[0][0][0]);
  glEnable(GL_MAP2_COLOR_4);
  glMapGrid2f(8, 0, 4, 6, 0, 2);
  /* Flat lines: the evaluated colours themselves, not llvmpipe's line
   * interpolation (which differs from softgl's by up to 3 levels on long
   * smooth lines). */
  glShadeModel(GL_FLAT);
  glEvalMesh2(GL_LINE, 0, 8, 0, 6);
  glShadeModel(GL_SMOOTH);
  glPushMatrix(); glTranslatef(0, 0, 1);
  glEvalMesh2(GL_POINT, 1, 7, 1, 5);
  glPopMatrix();
  glPushMatrix(); glTranslatef(-64, 44, 0); glScalef(0.5f, 0.5f, 1);
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i <= 4; i++) {
    glEvalPoint2(i, 0);
    GLfloat uv[2] = {i * 0.5f, 1.0f};
    glEvalCoord2fv(uv);
  }
  glEnd();
  glPopMatrix();
  glGetFloatv(GL_CURRENT_COLOR, fv); print_fv("current colour after mesh2", fv, 4);
  glDisable(GL_MAP2_COLOR_4);
  glDisable(GL_MAP2_VERTEX_3);

  /* 5. A list holding glMap1: the points are copied when compiled. */
  GLfloat line[2][3] = {{2, 90, 0}, {60, 70, 0}};
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, &line[0][0]);
  glMapGrid1f(4, 0, 1);
  glEvalMesh1(GL_LINE, 0, 4);
  glEndList();
  line[1][1] = 10;
  glColor3f(1, 1, 0);
  glCallList(list);
  glGetMapfv(GL_MAP1_VERTEX_3, GL_COEFF, fv); print_fv("list map coeff", fv, 6);

  /* 6. GL_EVAL_BIT. */
  glPushAttrib(GL_EVAL_BIT);
  glMapGrid1f(7, 2, 3);
  glDisable(GL_MAP1_VERTEX_3);
  glEnable(GL_AUTO_NORMAL);
  glPopAttrib();
  glGetFloatv(GL_MAP1_GRID_DOMAIN, fv); print_fv("grid1 domain after pop", fv, 2);
  glGetIntegerv(GL_MAP1_GRID_SEGMENTS, iv); printf("grid1 segments after pop %d\n", iv[0]);
  printf("enabled after pop %d %d\n", glIsEnabled(GL_MAP1_VERTEX_3), glIsEnabled(GL_AUTO_NORMAL));

  /* 7. glGetMap. */
  GLdouble dpts[3][4] = {{0.5, 1.5, -2.5, 1}, {3.25, 4, 5, 1}, {6, 7, 8.75, 2}};
  glMap1d(GL_MAP1_VERTEX_4, -1.0, 3.0, 4, 3, &dpts[0][0]);
  glGetMapfv(GL_MAP1_VERTEX_4, GL_COEFF, fv); print_fv("coeff f", fv, 12);
  glGetMapiv(GL_MAP1_VERTEX_4, GL_COEFF, iv);
  GLint ic[12]; glGetMapiv(GL_MAP1_VERTEX_4, GL_COEFF, ic);
  printf("coeff i"); for (int i = 0; i < 12; i++) printf(" %d", ic[i]); printf("\n");
  glGetMapdv(GL_MAP1_VERTEX_4, GL_DOMAIN, dv); printf("domain d %.9g %.9g\n", dv[0], dv[1]);
  glGetMapiv(GL_MAP1_VERTEX_4, GL_ORDER, iv); printf("order %d\n", iv[0]);
  glGetMapfv(GL_MAP2_COLOR_4, GL_DOMAIN, fv); print_fv("domain 2", fv, 4);
  glGetMapiv(GL_MAP2_VERTEX_3, GL_ORDER, iv); printf("order 2 %d %d\n", iv[0], iv[1]);
  glGetMapfv(GL_MAP2_TEXTURE_COORD_2, GL_COEFF, fv); print_fv("coeff tex", fv, 8);
  E(glGetError());

  /* 8. Errors. */
  GLfloat pts[64] = {0};
  E(glMap1f(GL_MAP1_VERTEX_3, 1, 1, 3, 2, pts));
  E(glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 0, pts));
  E(glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 31, pts));
  E(glMap1f(GL_MAP1_VERTEX_3, 0, 1, 2, 2, pts));
  E(glMap1f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, pts));
  E(glMap1f(GL_TEXTURE_2D, 0, 1, 3, 2, pts));
  E(glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 0, 6, 2, pts));
  E(glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 2, 2, pts));
  E(glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 31, pts));
  E(glMap2f(GL_MAP1_COLOR_4, 0, 1, 4, 2, 0, 1, 8, 2, pts));
  E(glMapGrid1f(0, 0, 1));
  E(glMapGrid2f(1, 0, 1, 0, 0, 1));
  E(glEvalMesh1(GL_FILL, 0, 1));
  E(glEvalMesh2(GL_LINE_STRIP, 0, 1, 0, 1));
  E(glGetMapfv(GL_MAP1_VERTEX_3, GL_TEXTURE_2D, fv));
  E(glGetMapfv(GL_AUTO_NORMAL, GL_ORDER, fv));
  E(glEnable(GL_MAP2_INDEX));
  printf("index map enabled %d\n", glIsEnabled(GL_MAP2_INDEX));
  glDisable(GL_MAP2_INDEX);
  glBegin(GL_POINTS);
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, pts);
  glEnd();
  printf("map inside begin 0x%04x\n", glGetError());
  glBegin(GL_POINTS);
  glEvalMesh1(GL_POINT, 0, 1);
  glEnd();
  printf("mesh inside begin 0x%04x\n", glGetError());
  glBegin(GL_POINTS);
  glMapGrid1f(2, 0, 1);
  glEnd();
  printf("grid inside begin 0x%04x\n", glGetError());
  glActiveTexture(GL_TEXTURE1);
  E(glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, pts));
  glActiveTexture(GL_TEXTURE0);

  glFinish();
  dump("eval.color", buf, sizeof buf);
  OSMesaDestroyContext(ctx);
  printf("done\n");
  return 0;
}
