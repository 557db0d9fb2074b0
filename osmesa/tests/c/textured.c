/* Texturing through the C ABI, compared with Mesa: six 128x128 scenes in one
 * 384x256 image, each a lit, smooth-shaded GLU sphere under the same camera:
 * 0. gluBuild2DMipmaps of a 100x60 (non-power-of-two) RGB image, trilinear
 *    (GL_LINEAR_MIPMAP_LINEAR), GL_MODULATE;
 * 1-5. one 64x64 texture per environment mode, each of another base format,
 *    bilinear with GL_REPEAT and a texture matrix:
 *    1 GL_MODULATE over RGBA, 2 GL_REPLACE over RGB (from a display list),
 *    3 GL_DECAL over RGBA, 4 GL_BLEND over LUMINANCE_ALPHA (with an
 *    environment colour), 5 GL_ADD over INTENSITY (BGRA bytes in, alignment 1,
 *    a row length and skips).
 * Between them it prints the texture state it reads back and the errors of
 * bad calls: the test compares those lines with Mesa's. */
#include "common.h"
#include <GL/glu.h>
#include <math.h>

#define W 384
#define H 256

static unsigned char buf[W * H * 4];

/* Viewport of scene i (0..5: three a row, bottom row first), camera reset. */
static void view(int i) {
  glViewport((i % 3) * 128, (i / 3) * 128, 128, 128);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, 1.0, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0, 0.5, 4.2, 0, 0, 0, 0, 1, 0);
  glRotatef(25.0f * i, 0, 1, 0);
  glRotatef(-70, 1, 0, 0); /* the sphere's poles up and away */
}

/* A w x h image of `comps` bytes a pixel: stripes, rings and a gradient,
 * with alpha (when there is one) from 0 to 255 across. */
static unsigned char *pattern(int w, int h, int comps, int seed) {
  unsigned char *p = malloc((size_t)w * h * comps);
  CHECK(p);
  for (int y = 0; y < h; y++)
    for (int x = 0; x < w; x++) {
      unsigned char *q = p + ((size_t)y * w + x) * comps;
      float dx = x - w / 2.0f, dy = y - h / 2.0f;
      int ring = ((int)(sqrtf(dx * dx + dy * dy) / 3.0f) + seed) & 1;
      int stripe = ((x / 4) ^ (y / 8)) & 1;
      unsigned char v[4] = {(unsigned char)(ring ? 240 : 30 + x * 3),
                            (unsigned char)(stripe ? 200 : 50 + y * 2),
                            (unsigned char)((x * 255) / (w - 1) ^ (seed * 40)),
                            (unsigned char)((x * 255) / (w - 1))};
      for (int c = 0; c < comps; c++) q[c] = v[comps == 2 && c == 1 ? 3 : c];
    }
  return p;
}

static void sphere(GLUquadric *q) { gluSphere(q, 1.3, 40, 28); }

/* Prints a level's size and format as glGetTexLevelParameteriv reads them. */
static void print_level(GLenum target, int level) {
  GLint w = -1, h = -1, f = -1, r = -1, a = -1, l = -1, i = -1;
  glGetTexLevelParameteriv(target, level, GL_TEXTURE_WIDTH, &w);
  glGetTexLevelParameteriv(target, level, GL_TEXTURE_HEIGHT, &h);
  glGetTexLevelParameteriv(target, level, GL_TEXTURE_INTERNAL_FORMAT, &f);
  glGetTexLevelParameteriv(target, level, GL_TEXTURE_RED_SIZE, &r);
  glGetTexLevelParameteriv(target, level, GL_TEXTURE_ALPHA_SIZE, &a);
  glGetTexLevelParameteriv(target, level, GL_TEXTURE_LUMINANCE_SIZE, &l);
  glGetTexLevelParameteriv(target, level, GL_TEXTURE_INTENSITY_SIZE, &i);
  printf("level %d: %dx%d format 0x%x sizes r%d a%d l%d i%d\n", level, w, h, f, r, a, l, i);
}

/* A 64x64 texture object of `internal` from `format` bytes, bilinear, repeating. */
static GLuint texture(GLint internal, GLenum format, int comps, int seed) {
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  unsigned char *p = pattern(64, 64, comps, seed);
  glTexImage2D(GL_TEXTURE_2D, 0, internal, 64, 64, 0, format, GL_UNSIGNED_BYTE, p);
  free(p);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  return t;
}

static void lights(void) {
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  GLfloat pos[4] = {1, 1.5f, 2, 0}, spec[4] = {0.6f, 0.6f, 0.6f, 1}, amb[4] = {0.15f, 0.15f, 0.2f, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
  GLfloat diff[4] = {0.9f, 0.75f, 0.6f, 0.8f};
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diff);
  glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT, GL_SHININESS, 20);
}

/* Bad calls: each prints the error it made (Mesa's and softgl's must agree). */
static void errors(void) {
  unsigned char px[64] = {0};
  GLuint t;
  glGenTextures(-1, &t);
  printf("gen -1: 0x%x\n", glGetError());
  glBindTexture(0x1234, 1);
  printf("bind bad target: 0x%x\n", glGetError());
  glTexImage2D(GL_TEXTURE_1D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  printf("teximage2d 1d target: 0x%x\n", glGetError());
  glTexImage2D(GL_TEXTURE_2D, -1, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  printf("level -1: 0x%x\n", glGetError());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 2, GL_RGBA, GL_UNSIGNED_BYTE, px);
  printf("border 2: 0x%x\n", glGetError());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  printf("width -1: 0x%x\n", glGetError());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, 0x1234, GL_UNSIGNED_BYTE, px);
  printf("bad format: 0x%x\n", glGetError());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, 0x1234, px);
  printf("bad type: 0x%x\n", glGetError());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, px);
  printf("565 with rgba: 0x%x\n", glGetError());
  glTexImage2D(GL_TEXTURE_2D, 0, 0x1234, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  printf("bad internal format: 0x%x\n", glGetError());
  glTexImage2D(GL_TEXTURE_2D, 0, 5, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  printf("internal format 5: 0x%x\n", glGetError());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, px);
  printf("rgba from depth: 0x%x\n", glGetError());
  glTexSubImage2D(GL_TEXTURE_2D, 0, 60, 0, 8, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  printf("subimage outside: 0x%x\n", glGetError());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_REPEAT);
  printf("min filter repeat: 0x%x\n", glGetError());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  printf("mag filter mipmap: 0x%x\n", glGetError());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_LINEAR);
  printf("wrap linear: 0x%x\n", glGetError());
  glTexParameteri(GL_TEXTURE_2D, 0x1234, 0);
  printf("bad pname: 0x%x\n", glGetError());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, -1);
  printf("base level -1: 0x%x\n", glGetError());
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_LINEAR);
  printf("env mode linear: 0x%x\n", glGetError());
  glTexEnvi(0x1234, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  printf("env bad target: 0x%x\n", glGetError());
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 3.0f);
  printf("rgb scale 3: 0x%x\n", glGetError());
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, GL_SRC_COLOR);
  printf("alpha operand src colour: 0x%x\n", glGetError());
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_MODULATE);
  printf("texgen mode modulate: 0x%x\n", glGetError());
  glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  printf("texgen r sphere map: 0x%x\n", glGetError());
  glTexGeni(0x1234, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  printf("texgen bad coord: 0x%x\n", glGetError());
  glActiveTexture(GL_TEXTURE0 + 4096); /* llvmpipe has more units than 8 for shaders */
  printf("active texture 4096: 0x%x\n", glGetError());
  glClientActiveTexture(GL_TEXTURE0 + 8);
  printf("client active texture 8: 0x%x\n", glGetError());
  GLint v = -1;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, 0x1234, &v);
  printf("level param bad pname: 0x%x\n", glGetError());
  glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP, 0, GL_TEXTURE_WIDTH, &v);
  printf("level param cube map: 0x%x\n", glGetError());
  glGetTexLevelParameteriv(GL_TEXTURE_2D, -1, GL_TEXTURE_WIDTH, &v);
  printf("level param level -1: 0x%x\n", glGetError());
  glBegin(GL_TRIANGLES);
  glBindTexture(GL_TEXTURE_2D, 0);
  glEnd();
  printf("bind inside begin: 0x%x\n", glGetError());
  glDeleteTextures(-1, &t);
  printf("delete -1: 0x%x\n", glGetError());
  glCopyTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 0, 0, 4, 4, 0);
  printf("copy to proxy: 0x%x\n", glGetError());
  /* A proxy that does not fit: no error, zero sizes. */
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 1 << 20, 1 << 20, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &v);
  printf("huge proxy: width %d error 0x%x\n", v, glGetError());
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 64, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &v);
  printf("small proxy: width %d error 0x%x\n", v, glGetError());
}

int main(int argc, char **argv) {
  start(argc, argv);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(ctx);
  CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
  glClearColor(0.05f, 0.05f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  GLUquadric *q = gluNewQuadric();
  CHECK(q);
  gluQuadricTexture(q, GL_TRUE);
  gluQuadricNormals(q, GLU_SMOOTH);
  lights();

  /* 0: gluBuild2DMipmaps of a non-power-of-two image, trilinear. */
  view(0);
  GLuint mip;
  glGenTextures(1, &mip);
  glBindTexture(GL_TEXTURE_2D, mip);
  unsigned char *img = pattern(100, 60, 3, 0);
  GLint r = gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGB, 100, 60, GL_RGB, GL_UNSIGNED_BYTE, img);
  free(img);
  printf("gluBuild2DMipmaps %d error 0x%x\n", r, glGetError());
  for (int l = 0; l < 9; l++) print_level(GL_TEXTURE_2D, l);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_TEXTURE_2D);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glScalef(3, 2, 1); /* small on screen: the far levels are sampled */
  glMatrixMode(GL_MODELVIEW);
  sphere(q);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  printf("scene 0 error 0x%x\n", glGetError());

  /* 1-5: one environment mode each. */
  GLuint tex[5];
  tex[0] = texture(GL_RGBA, GL_RGBA, 4, 1);
  /* 2: the RGB image is uploaded from a display list compiled from a buffer
   * that is then overwritten: the list keeps the pixels of compile time. */
  glGenTextures(1, &tex[1]);
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  unsigned char *rgb = pattern(64, 64, 3, 2);
  glNewList(1, GL_COMPILE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, 64, 64, 0, GL_RGB, GL_UNSIGNED_BYTE, rgb);
  glEndList();
  memset(rgb, 0, 64 * 64 * 3);
  glCallList(1);
  free(rgb);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  tex[2] = texture(GL_RGBA8, GL_RGBA, 4, 3);
  tex[3] = texture(GL_LUMINANCE_ALPHA, GL_LUMINANCE_ALPHA, 2, 4);
  /* 5: INTENSITY from BGRA bytes, read 3 pixels in and 2 rows up of a 70-pixel-wide buffer. */
  glGenTextures(1, &tex[4]);
  glBindTexture(GL_TEXTURE_2D, tex[4]);
  unsigned char *wide = pattern(70, 66, 4, 5);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 70);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_INTENSITY, 64, 64, 0, GL_BGRA, GL_UNSIGNED_BYTE, wide);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  free(wide);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  printf("uploads error 0x%x\n", glGetError());
  for (int k = 0; k < 5; k++) {
    glBindTexture(GL_TEXTURE_2D, tex[k]);
    print_level(GL_TEXTURE_2D, 0);
  }

  GLenum modes[5] = {GL_MODULATE, GL_REPLACE, GL_DECAL, GL_BLEND, GL_ADD};
  GLfloat env_color[4] = {0.2f, 0.9f, 0.4f, 0.5f};
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env_color);
  for (int k = 0; k < 5; k++) {
    view(k + 1);
    glBindTexture(GL_TEXTURE_2D, tex[k]);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, modes[k]);
    if (modes[k] == GL_ADD) { /* a darker material: the sum stays below 1 */
      GLfloat dark[4] = {0.35f, 0.25f, 0.2f, 1};
      glMaterialfv(GL_FRONT, GL_DIFFUSE, dark);
    }
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glTranslatef(0.1f * k, 0, 0);
    glScalef(2, 1, 1);
    glMatrixMode(GL_MODELVIEW);
    sphere(q);
    GLint mode = -1, binding = -1;
    glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &mode);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &binding);
    printf("scene %d mode 0x%x binding %d error 0x%x\n", k + 1, mode, binding == (GLint)tex[k], glGetError());
  }
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);

  /* State read back. */
  GLint iv[4];
  GLfloat fv[4];
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, fv);
  printf("env colour %g %g %g %g\n", fv[0], fv[1], fv[2], fv[3]);
  glBindTexture(GL_TEXTURE_2D, mip);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, iv);
  printf("min filter 0x%x\n", iv[0]);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, iv);
  printf("wrap t 0x%x\n", iv[0]);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, fv);
  printf("max lod %g\n", fv[0]);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, iv);
  printf("max level %d\n", iv[0]);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_RESIDENT, iv);
  printf("resident %d\n", iv[0]);
  GLfloat border[4] = {0.25f, 0.5f, 0.75f, 1};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, iv);
  printf("border %d %d %d %d\n", iv[0], iv[1], iv[2], iv[3]);
  printf("is texture %d %d %d\n", glIsTexture(mip), glIsTexture(tex[4]), glIsTexture(9999));
  GLboolean res[2] = {7, 7};
  GLuint two[2] = {mip, tex[0]};
  printf("resident %d %d %d\n", glAreTexturesResident(2, two, res), res[0], res[1]);
  glGetIntegerv(GL_MAX_TEXTURE_UNITS, iv);
  printf("units %d\n", iv[0]);
  glActiveTexture(GL_TEXTURE1);
  glGetIntegerv(GL_ACTIVE_TEXTURE, iv);
  printf("active 0x%x enabled %d binding %d\n", iv[0], glIsEnabled(GL_TEXTURE_2D), (glGetIntegerv(GL_TEXTURE_BINDING_2D, iv + 1), iv[1]));
  glActiveTexture(GL_TEXTURE0);
  glPushAttrib(GL_TEXTURE_BIT);
  glBindTexture(GL_TEXTURE_2D, tex[2]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
  glDisable(GL_TEXTURE_2D);
  glPopAttrib();
  glGetIntegerv(GL_TEXTURE_BINDING_2D, iv);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, iv + 1);
  printf("after pop: binding %d mode 0x%x enabled %d\n", iv[0] == (GLint)mip, iv[1], glIsEnabled(GL_TEXTURE_2D));
  /* tex[2] was not bound at the push: its new wrap mode stays. */
  glBindTexture(GL_TEXTURE_2D, tex[2]);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, iv);
  printf("unbound object keeps wrap 0x%x\n", iv[0]);
  printf("state error 0x%x\n", glGetError());

  errors();

  glFinish();
  dump("textured.color", buf, sizeof buf);
  gluDeleteQuadric(q);
  OSMesaDestroyContext(ctx);
  printf("done\n");
  return 0;
}
