/* Texture probe against Mesa's llvmpipe (OSMesa): one scene per input line
 * of cases.txt (a name, then key=value words; 16x16 unless size=), written as
 * "name hex" (the RGBA bytes of the colour buffer, bottom row first).
 * jit/tests/texture.rs feeds it the cases and records its output in probe.txt:
 *
 *   gcc -O1 -o /tmp/probe jit/tests/llvmpipe/probe.c -lOSMesa
 *   cargo test -p softgl-jit --test texture -- --ignored regenerate
 *
 * Every texture coordinate is affine in the window position with
 * power-of-two steps, so its value at each pixel is exact on both sides:
 * c(X, Y) = c0 + X*cx + Y*cy at window position (X, Y). Texels come from the
 * same LCG as the test's. */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAXN 64
static unsigned char buf[MAXN * MAXN * 4];
static int N = 16;

static unsigned rnd;
static unsigned char rb(void) { rnd = rnd * 1103515245u + 12345u; return (unsigned char)(rnd >> 16); }

struct kv { char key[32]; char val[64]; };

static const char *get(struct kv *kv, int n, const char *key, const char *def) {
  for (int i = 0; i < n; i++)
    if (!strcmp(kv[i].key, key)) return kv[i].val;
  return def;
}
static float getf(struct kv *kv, int n, const char *key, float def) {
  const char *v = get(kv, n, key, NULL);
  return v ? (float)atof(v) : def;
}
static int geti(struct kv *kv, int n, const char *key, int def) {
  const char *v = get(kv, n, key, NULL);
  return v ? atoi(v) : def;
}

/* Unit u's key: "name" for unit 0, "name@u" for the others. */
static const char *K(const char *name, int u) {
  static char buf[4][48];
  static int i;
  i = (i + 1) & 3;
  if (u) snprintf(buf[i], sizeof buf[i], "%s@%d", name, u);
  else snprintf(buf[i], sizeof buf[i], "%s", name);
  return buf[i];
}

static GLenum genum(const char *s) {
  static const struct { const char *n; GLenum e; } t[] = {
    {"nearest", GL_NEAREST}, {"linear", GL_LINEAR},
    {"nearest_mipmap_nearest", GL_NEAREST_MIPMAP_NEAREST}, {"linear_mipmap_nearest", GL_LINEAR_MIPMAP_NEAREST},
    {"nearest_mipmap_linear", GL_NEAREST_MIPMAP_LINEAR}, {"linear_mipmap_linear", GL_LINEAR_MIPMAP_LINEAR},
    {"repeat", GL_REPEAT}, {"clamp", GL_CLAMP}, {"clamp_to_edge", GL_CLAMP_TO_EDGE},
    {"clamp_to_border", GL_CLAMP_TO_BORDER}, {"mirrored_repeat", GL_MIRRORED_REPEAT},
    {"modulate", GL_MODULATE}, {"replace", GL_REPLACE}, {"decal", GL_DECAL}, {"blend", GL_BLEND},
    {"add", GL_ADD}, {"combine", GL_COMBINE}, {"add_signed", GL_ADD_SIGNED}, {"interpolate", GL_INTERPOLATE},
    {"subtract", GL_SUBTRACT}, {"dot3_rgb", GL_DOT3_RGB}, {"dot3_rgba", GL_DOT3_RGBA},
    {"texture", GL_TEXTURE}, {"texture0", GL_TEXTURE0}, {"texture1", GL_TEXTURE1}, {"texture2", GL_TEXTURE2},
    {"constant", GL_CONSTANT}, {"primary_color", GL_PRIMARY_COLOR}, {"previous", GL_PREVIOUS},
    {"src_color", GL_SRC_COLOR}, {"one_minus_src_color", GL_ONE_MINUS_SRC_COLOR},
    {"src_alpha", GL_SRC_ALPHA}, {"one_minus_src_alpha", GL_ONE_MINUS_SRC_ALPHA},
    {"never", GL_NEVER}, {"less", GL_LESS}, {"equal", GL_EQUAL}, {"lequal", GL_LEQUAL}, {"greater", GL_GREATER},
    {"notequal", GL_NOTEQUAL}, {"gequal", GL_GEQUAL}, {"always", GL_ALWAYS},
    {"luminance", GL_LUMINANCE}, {"intensity", GL_INTENSITY}, {"alpha", GL_ALPHA},
  };
  for (unsigned i = 0; i < sizeof t / sizeof t[0]; i++)
    if (!strcmp(t[i].n, s)) return t[i].e;
  fprintf(stderr, "unknown enum %s\n", s);
  exit(1);
}

/* Uploads one image of level l (and face) in format f with LCG texels. */
static void upload(GLenum target, const char *f, int l, int w, int h, int d) {
  int n = w * h * d;
  GLenum ifmt, fmt, type;
  int bytes;
  if (!strcmp(f, "rgba8")) { ifmt = GL_RGBA8; fmt = GL_RGBA; type = GL_UNSIGNED_BYTE; bytes = 4; }
  else if (!strcmp(f, "rgb8")) { ifmt = GL_RGB8; fmt = GL_RGB; type = GL_UNSIGNED_BYTE; bytes = 3; }
  else if (!strcmp(f, "l8")) { ifmt = GL_LUMINANCE8; fmt = GL_LUMINANCE; type = GL_UNSIGNED_BYTE; bytes = 1; }
  else if (!strcmp(f, "a8")) { ifmt = GL_ALPHA8; fmt = GL_ALPHA; type = GL_UNSIGNED_BYTE; bytes = 1; }
  else if (!strcmp(f, "i8")) { ifmt = GL_INTENSITY8; fmt = GL_LUMINANCE; type = GL_UNSIGNED_BYTE; bytes = 1; }
  else if (!strcmp(f, "la8")) { ifmt = GL_LUMINANCE8_ALPHA8; fmt = GL_LUMINANCE_ALPHA; type = GL_UNSIGNED_BYTE; bytes = 2; }
  else if (!strcmp(f, "rgba16")) { ifmt = GL_RGBA16; fmt = GL_RGBA; type = GL_UNSIGNED_SHORT; bytes = 8; }
  else if (!strcmp(f, "srgba8")) { ifmt = GL_SRGB8_ALPHA8; fmt = GL_RGBA; type = GL_UNSIGNED_BYTE; bytes = 4; }
  else if (!strcmp(f, "depth")) { ifmt = GL_DEPTH_COMPONENT24; fmt = GL_DEPTH_COMPONENT; type = GL_FLOAT; bytes = 4; }
  else { fprintf(stderr, "unknown format %s\n", f); exit(1); }
  unsigned char *p = malloc((size_t)n * bytes + 8);
  for (int i = 0; i < n * bytes; i++) p[i] = rb();
  if (!strcmp(f, "depth"))
    for (int i = 0; i < n; i++) ((float *)p)[i] = (p[4 * i] & 1) ? 1.0f : 0.0f;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  if (target == GL_TEXTURE_1D) glTexImage1D(target, l, ifmt, w, 0, fmt, type, p);
  else if (target == GL_TEXTURE_3D) glTexImage3D(target, l, ifmt, w, h, d, 0, fmt, type, p);
  else glTexImage2D(target, l, ifmt, w, h, 0, fmt, type, p);
  free(p);
}

static void scene(struct kv *kv, int n, int index) {
  const char *tgt = get(kv, n, "target", "2d");
  GLenum target = !strcmp(tgt, "1d") ? GL_TEXTURE_1D : !strcmp(tgt, "3d") ? GL_TEXTURE_3D
                  : !strcmp(tgt, "cube") ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
  const char *f = get(kv, n, "format", "rgba8");
  int w = geti(kv, n, "w", 8), h = geti(kv, n, "h", 8), d = geti(kv, n, "d", 1);
  int levels = geti(kv, n, "levels", 1);
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(target, tex);
  for (int l = 0; l < levels; l++) {
    int lw = w >> l ? w >> l : 1, lh = h >> l ? h >> l : 1, ld = d >> l ? d >> l : 1;
    if (target == GL_TEXTURE_1D) lh = 1;
    if (target != GL_TEXTURE_3D) ld = 1;
    if (target == GL_TEXTURE_CUBE_MAP) {
      for (int face = 0; face < 6; face++) {
        rnd = (unsigned)(index * 1000 + l * 10 + face);
        upload(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, f, l, lw, lh, 1);
      }
    } else {
      rnd = (unsigned)(index * 1000 + l * 10);
      upload(target, f, l, lw, lh, ld);
    }
  }
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, genum(get(kv, n, "min", "linear")));
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, genum(get(kv, n, "mag", "linear")));
  glTexParameteri(target, GL_TEXTURE_WRAP_S, genum(get(kv, n, "wrap_s", "repeat")));
  glTexParameteri(target, GL_TEXTURE_WRAP_T, genum(get(kv, n, "wrap_t", "repeat")));
  glTexParameteri(target, GL_TEXTURE_WRAP_R, genum(get(kv, n, "wrap_r", "repeat")));
  float border[4] = {getf(kv, n, "br", 0), getf(kv, n, "bg", 0), getf(kv, n, "bb", 0), getf(kv, n, "ba", 0)};
  glTexParameterfv(target, GL_TEXTURE_BORDER_COLOR, border);
  glTexParameterf(target, GL_TEXTURE_LOD_BIAS, getf(kv, n, "bias", 0));
  glTexParameterf(target, GL_TEXTURE_MIN_LOD, getf(kv, n, "min_lod", -1000));
  glTexParameterf(target, GL_TEXTURE_MAX_LOD, getf(kv, n, "max_lod", 1000));
  glTexParameteri(target, GL_TEXTURE_BASE_LEVEL, geti(kv, n, "base", 0));
  glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, geti(kv, n, "max_level", 1000));
  if (get(kv, n, "compare", NULL)) {
    glTexParameteri(target, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(target, GL_TEXTURE_COMPARE_FUNC, genum(get(kv, n, "compare", "lequal")));
  }
  glTexParameteri(target, GL_DEPTH_TEXTURE_MODE, genum(get(kv, n, "depth_mode", "luminance")));
  /* units=k: the same texture and coordinates on units 0..k, each with its
   * own environment (keys name@u); off@u=1 leaves unit u disabled. */
  int units = geti(kv, n, "units", 1);
  for (int u = 0; u < units; u++) {
    glActiveTexture(GL_TEXTURE0 + u);
    glBindTexture(target, tex);
    if (geti(kv, n, K("off", u), 0)) glDisable(target);
    else glEnable(target);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, genum(get(kv, n, K("env", u), "replace")));
    float ec[4] = {getf(kv, n, K("er", u), 0), getf(kv, n, K("eg", u), 0), getf(kv, n, K("eb", u), 0),
                   getf(kv, n, K("ea", u), 0)};
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, ec);
    if (!strcmp(get(kv, n, K("env", u), "replace"), "combine")) {
      glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, genum(get(kv, n, K("crgb", u), "modulate")));
      glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, genum(get(kv, n, K("calpha", u), "modulate")));
      static const char *srgb[] = {"srgb0", "srgb1", "srgb2"}, *orgb[] = {"orgb0", "orgb1", "orgb2"};
      static const char *sa[] = {"sa0", "sa1", "sa2"}, *oa[] = {"oa0", "oa1", "oa2"};
      static const char *dsrc[] = {"texture", "previous", "constant"};
      static const char *dorgb[] = {"src_color", "src_color", "src_alpha"};
      for (int i = 0; i < 3; i++) {
        glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB + i, genum(get(kv, n, K(srgb[i], u), dsrc[i])));
        glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB + i, genum(get(kv, n, K(orgb[i], u), dorgb[i])));
        glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA + i, genum(get(kv, n, K(sa[i], u), dsrc[i])));
        glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA + i, genum(get(kv, n, K(oa[i], u), "src_alpha")));
      }
      glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, getf(kv, n, K("scrgb", u), 1));
      glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, getf(kv, n, K("sca", u), 1));
    }
  }
  glActiveTexture(GL_TEXTURE0);

  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  if (!strcmp(get(kv, n, "geom", "flat"), "persp")) {
    /* A floor receding from z = -1.5 to z = -30 under glFrustum: texture
     * coordinates (0,0)..(ps,pt) at its corners. */
    glMatrixMode(GL_PROJECTION);
    glFrustum(-0.5, 0.5, -0.5, 0.5, 1, 30);
    glMatrixMode(GL_MODELVIEW);
    float ps = getf(kv, n, "ps", 8), pt = getf(kv, n, "pt", 16), y = getf(kv, n, "py", -1);
    static const float fl[4][4] = {{-4, -1.5f, 0, 0}, {4, -1.5f, 1, 0}, {4, -30, 1, 1}, {-4, -30, 0, 1}};
    glColor4f(getf(kv, n, "cr", 1), getf(kv, n, "cg", 1), getf(kv, n, "cb", 1), getf(kv, n, "ca", 1));
    glBegin(GL_QUADS);
    for (int v = 0; v < 4; v++) {
      /* cvary=1: the colour given per vertex (a varying, not Mesa's current-attribute uniform) */
      if (geti(kv, n, "cvary", 0))
        glColor4f(getf(kv, n, "cr", 1), getf(kv, n, "cg", 1), getf(kv, n, "cb", 1), getf(kv, n, "ca", 1));
      glTexCoord2f(fl[v][2] * ps, fl[v][3] * pt);
      glVertex3f(fl[v][0], y, fl[v][1]);
    }
    glEnd();
    glFinish();
    glDisable(target);
    glDeleteTextures(1, &tex);
    return;
  }
  glColor4f(getf(kv, n, "cr", 1), getf(kv, n, "cg", 1), getf(kv, n, "cb", 1), getf(kv, n, "ca", 1));
  static const char *c0[] = {"s0", "t0", "r0", "q0"}, *cx[] = {"sx", "tx", "rx", "qx"}, *cy[] = {"sy", "ty", "ry", "qy"};
  const float corner[4][2] = {{0, 0}, {(float)N, 0}, {(float)N, (float)N}, {0, (float)N}};
  glBegin(GL_QUADS);
  for (int v = 0; v < 4; v++) {
    float tc[4];
    for (int c = 0; c < 4; c++)
      tc[c] = getf(kv, n, c0[c], c == 3 ? 1 : 0) + corner[v][0] * getf(kv, n, cx[c], 0) +
              corner[v][1] * getf(kv, n, cy[c], 0);
    for (int u = 0; u < units; u++) glMultiTexCoord4fv(GL_TEXTURE0 + u, tc);
    glVertex2f(corner[v][0] * 2.0f / N - 1, corner[v][1] * 2.0f / N - 1);
  }
  glEnd();
  glFinish();
  for (int u = units; u--;) {
    glActiveTexture(GL_TEXTURE0 + u);
    glDisable(target);
  }
  glDeleteTextures(1, &tex);
}

int main(void) {
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  if (!ctx) return 1;
  char line[4096];
  int index = 0;
  while (fgets(line, sizeof line, stdin)) {
    struct kv kv[64];
    int n = 0;
    char name[64] = "";
    for (char *tok = strtok(line, " \t\n"); tok && n < 64; tok = strtok(NULL, " \t\n")) {
      char *eq = strchr(tok, '=');
      if (!eq) { snprintf(name, sizeof name, "%s", tok); continue; }
      *eq = 0;
      snprintf(kv[n].key, sizeof kv[n].key, "%s", tok);
      snprintf(kv[n].val, sizeof kv[n].val, "%s", eq + 1);
      n++;
    }
    N = geti(kv, n, "size", 16);
    if (N > MAXN || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, N, N)) return 1;
    glViewport(0, 0, N, N);
    scene(kv, n, geti(kv, n, "seed", index));
    printf("%s ", name);
    for (int i = 0; i < N * N * 4; i++) printf("%02x", buf[i]);
    printf("\n");
    index++;
  }
  OSMesaDestroyContext(ctx);
  return 0;
}
