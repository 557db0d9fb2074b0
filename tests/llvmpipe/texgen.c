/* Texture coordinate probe against Mesa's llvmpipe (OSMesa): one 32x32 scene
 * per input line, written as "name hex" (the RGBA bytes of the colour buffer,
 * bottom row first). tests/texturing.rs holds the lines (key=value words, see
 * `SCENES` there) and replays them through softgl:
 *
 *   gcc -O1 -o /tmp/texgen tests/llvmpipe/texgen.c -lOSMesa
 *   cargo test -p softgl --test texturing -- --ignored regenerate
 *
 * Every scene draws the same bumpy 8x8 grid (positions and normals exact in
 * f32: x, y multiples of 1/4, z = (x*x - y*y)/4, normal (-x/2, y/2, 1) under
 * GL_NORMALIZE) in perspective, textured NEAREST/REPEAT with a 16x16 LCG
 * texture, so that the colour of a pixel names the texel its coordinates
 * fall in. Keys: prim (tris, points, lines), gen_s/t/r/q (obj, eye, sphere,
 * reflect, normal), os/ot/or/oq and es/et/er/eq (planes "a,b,c,d"), rot
 * (degrees of the drawing modelview), spec (degrees of the modelview the eye
 * planes are given under), tz (the grid's distance, default -2.5: -1.2
 * crosses the near plane), tm_rot/tm_scale/tm_tx (texture matrix), unit
 * (the unit used), light (1: GL_LIGHT0 on, MODULATE), env (replace,
 * modulate), arrays (1: triangles from client arrays, the coordinates through
 * glClientActiveTexture and glTexCoordPointer). */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define N 32
static unsigned char buf[N * N * 4];

static unsigned rnd;
static unsigned char rb(void) { rnd = rnd * 1103515245u + 12345u; return (unsigned char)(rnd >> 16); }

struct kv { char key[32]; char val[64]; };
static struct kv kv[32];
static int nkv;

static const char *get(const char *key, const char *def) {
  for (int i = 0; i < nkv; i++)
    if (!strcmp(kv[i].key, key)) return kv[i].val;
  return def;
}
static float getf(const char *key, float def) {
  const char *v = get(key, NULL);
  return v ? (float)atof(v) : def;
}

static GLenum gen_mode(const char *s) {
  if (!strcmp(s, "obj")) return GL_OBJECT_LINEAR;
  if (!strcmp(s, "eye")) return GL_EYE_LINEAR;
  if (!strcmp(s, "sphere")) return GL_SPHERE_MAP;
  if (!strcmp(s, "reflect")) return GL_REFLECTION_MAP;
  if (!strcmp(s, "normal")) return GL_NORMAL_MAP;
  fprintf(stderr, "bad texgen mode %s\n", s);
  exit(1);
}

static void plane(const char *key, GLenum coord, GLenum pname) {
  const char *v = get(key, NULL);
  if (!v) return;
  float p[4];
  if (sscanf(v, "%f,%f,%f,%f", &p[0], &p[1], &p[2], &p[3]) != 4) { fprintf(stderr, "bad plane %s\n", v); exit(1); }
  glTexGenfv(coord, pname, p);
}

static void vertex(int i, int j, int unit) {
  float x = -1.0f + i / 4.0f, y = -1.0f + j / 4.0f;
  glNormal3f(-x / 2.0f, y / 2.0f, 1.0f);
  glMultiTexCoord4f(GL_TEXTURE0 + unit, (x + 1.0f) / 2.0f, (y + 1.0f) / 2.0f, 0.0f, 1.0f);
  glVertex3f(x, y, (x * x - y * y) / 4.0f);
}

static void scene(void) {
  int unit = (int)getf("unit", 0);
  glViewport(0, 0, N, N);
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glActiveTexture(GL_TEXTURE0 + unit);
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  unsigned char texels[16 * 16 * 4];
  rnd = 12345;
  for (int i = 0; i < 16 * 16 * 4; i++) texels[i] = rb();
  for (int i = 0; i < 16 * 16; i++) texels[4 * i + 3] = 255;
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, !strcmp(get("env", "replace"), "modulate") ? GL_MODULATE : GL_REPLACE);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  /* The eye planes are given under this modelview. */
  glTranslatef(0.25f, 0.0f, -1.0f);
  glRotatef(getf("spec", 0), 0.0f, 1.0f, 0.0f);
  const char *names[4] = {"s", "t", "r", "q"};
  for (int c = 0; c < 4; c++) {
    char key[8];
    GLenum coord = GL_S + c;
    snprintf(key, sizeof key, "gen_%s", names[c]);
    const char *m = get(key, NULL);
    if (!m) continue;
    glTexGeni(coord, GL_TEXTURE_GEN_MODE, gen_mode(m));
    snprintf(key, sizeof key, "o%s", names[c]);
    plane(key, coord, GL_OBJECT_PLANE);
    snprintf(key, sizeof key, "e%s", names[c]);
    plane(key, coord, GL_EYE_PLANE);
    glEnable(GL_TEXTURE_GEN_S + c);
  }
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glTranslatef(getf("tm_tx", 0), 0.0f, 0.0f);
  glRotatef(getf("tm_rot", 0), 0.0f, 0.0f, 1.0f);
  float sc = getf("tm_scale", 1);
  glScalef(sc, sc, 1.0f);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, getf("tz", -2.5f));
  glRotatef(getf("rot", 0), 1.0f, 0.5f, 0.25f);
  glEnable(GL_NORMALIZE);
  glEnable(GL_DEPTH_TEST);
  if (getf("light", 0) != 0) {
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
  }
  glColor4f(0.75f, 0.5f, 1.0f, 1.0f);
  const char *prim = get("prim", "tris");
  glPointSize(2.0f);
  if (!strcmp(prim, "points")) {
    glBegin(GL_POINTS);
    for (int j = 0; j <= 8; j++)
      for (int i = 0; i <= 8; i++) vertex(i, j, unit);
    glEnd();
  } else if (!strcmp(prim, "lines")) {
    for (int j = 0; j <= 8; j++) {
      glBegin(GL_LINE_STRIP);
      for (int i = 0; i <= 8; i++) vertex(i, j, unit);
      glEnd();
    }
  } else if (getf("arrays", 0) != 0) {
    static float pos[6 * 64 * 3], nrm[6 * 64 * 3], tc[6 * 64 * 2];
    int k = 0;
    for (int j = 0; j < 8; j++)
      for (int i = 0; i < 8; i++) {
        int di[6] = {0, 1, 1, 0, 1, 0}, dj[6] = {0, 0, 1, 0, 1, 1};
        for (int v = 0; v < 6; v++, k++) {
          float x = -1.0f + (i + di[v]) / 4.0f, y = -1.0f + (j + dj[v]) / 4.0f;
          pos[3 * k] = x; pos[3 * k + 1] = y; pos[3 * k + 2] = (x * x - y * y) / 4.0f;
          nrm[3 * k] = -x / 2.0f; nrm[3 * k + 1] = y / 2.0f; nrm[3 * k + 2] = 1.0f;
          tc[2 * k] = (x + 1.0f) / 2.0f; tc[2 * k + 1] = (y + 1.0f) / 2.0f;
        }
      }
    glVertexPointer(3, GL_FLOAT, 0, pos);
    glNormalPointer(GL_FLOAT, 0, nrm);
    glClientActiveTexture(GL_TEXTURE0 + unit);
    glTexCoordPointer(2, GL_FLOAT, 0, tc);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glDrawArrays(GL_TRIANGLES, 0, k);
  } else {
    glBegin(GL_TRIANGLES);
    for (int j = 0; j < 8; j++)
      for (int i = 0; i < 8; i++) {
        vertex(i, j, unit); vertex(i + 1, j, unit); vertex(i + 1, j + 1, unit);
        vertex(i, j, unit); vertex(i + 1, j + 1, unit); vertex(i, j + 1, unit);
      }
    glEnd();
  }
  glFinish();
}

int main(void) {
  char line[1024];
  while (fgets(line, sizeof line, stdin)) {
    char *save, *name = strtok_r(line, " \n", &save);
    if (!name) continue;
    nkv = 0;
    for (char *w; (w = strtok_r(NULL, " \n", &save)) && nkv < 32;) {
      char *eq = strchr(w, '=');
      if (!eq) continue;
      *eq = 0;
      snprintf(kv[nkv].key, sizeof kv[nkv].key, "%s", w);
      snprintf(kv[nkv].val, sizeof kv[nkv].val, "%s", eq + 1);
      nkv++;
    }
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, N, N)) { fprintf(stderr, "no context\n"); return 1; }
    scene();
    printf("%s ", name);
    for (int i = 0; i < N * N * 4; i++) printf("%02x", buf[i]);
    printf("\n");
    OSMesaDestroyContext(ctx);
  }
  return 0;
}
