/* What the C-ABI benches share (not tests): the clock, the order of
 * medians, MuJoCo's plane and camera. Include after GL/gl.h, stdlib.h and time.h. */

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + t.tv_nsec * 1e-9;
}

static int cmp(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : x > y;
}

/* MuJoCo's plane list for an infinite plane with texrepeat 2 (render_context.c, makePlane):
 * n×n quads, n 200 for MuJoCo's; texture coordinates when `textured`. */
static GLuint plane_list(int n, int textured) {
  const double zfar = 122.12278, sx = 1.0;
  const double d = (2.1 * zfar + 2 * sx) / n;
  GLuint l = glGenLists(1);
  glNewList(l, GL_COMPILE);
  glBegin(GL_QUADS);
  glNormal3d(0, 0, 1);
  for (int x = 0; x < n; x++)
    for (int y = 0; y < n; y++) {
      double x0 = d * x - d * n / 2, x1 = x0 + d, y0 = d * y - d * n / 2, y1 = y0 + d;
      double xs[4] = {x0, x1, x1, x0}, ys[4] = {y0, y0, y1, y1};
      for (int k = 0; k < 4; k++) {
        if (textured) glTexCoord2d(0.5 * xs[k], -0.5 * ys[k]);
        glVertex3d(xs[k], ys[k], 0);
      }
    }
  glEnd();
  glEndList();
  return l;
}

/* MuJoCo's camera over the plane: reverse Z without GL_ARB_clip_control. */
static void camera(void) {
  static const GLfloat view[16] = {0.741298497f, -0.300687939f, 0.600052893f, 0, 0.671175599f, 0.332103133f,
                                   -0.662744999f, 0, 0, 0.894032598f, 0.448001951f, 0, -0.0200352669f,
                                   0.0281088352f, -3.62750769f, 1};
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glScalef(1, 1, -1); /* reverse Z without GL_ARB_clip_control */
  glFrustum(-0.0134893097, 0.0134893097, -0.0101169823, 0.0101169823, 0.0244245548, 122.12278);
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixf(view);
}
