/* Deep colour framebuffer objects from a GL 1.5-style program (an RGBA8
 * OSMesa context): renderbuffers of GL_RGBA16, GL_RGBA32F, GL_RGBA16F,
 * GL_RGB16, GL_RGB16F and GL_RGB32F, their sizes, completeness and GL_*_BITS while
 * bound; a scene rendered into each (smooth colour, blending over and
 * additive past 1, DST_COLOR, MAX and MIN, alpha test, fog, colour sum past 1, a
 * scissored clear through a colour mask, logic op XOR), read back as
 * GL_FLOAT, GL_UNSIGNED_SHORT and GL_UNSIGNED_BYTE (<fmt>.f, .us, .ub); and
 * blits between RGBA32F, RGBA16 and RGBA8 objects, NEAREST and LINEAR,
 * scaled and flipped (blit.<n>.<type>). Lines: what the queries answered. */
#define GL_GLEXT_PROTOTYPES
#include "common.h"
#include <GL/glext.h>
#include "fbo_object.h"

#define W 64
#define H 48

static void scene(void) {
  glViewport(0, 0, W, H);
  glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.5, 1.5, -1.1, 1.1, -5, 5);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_DEPTH_TEST);
  glBegin(GL_TRIANGLES);
  glColor4f(1.7f, 0.1f, 0.2f, 1.0f);
  glVertex3f(-1.4f, -1.0f, 0.2f);
  glColor4f(0.0f, 0.9f, 0.3f, 0.6f);
  glVertex3f(0.3f, -0.9f, -0.4f);
  glColor4f(0.3f, 0.2f, 1.0f, 0.8f);
  glVertex3f(-0.5f, 0.9f, 0.1f);
  glEnd();
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glBegin(GL_QUADS);
  glColor4f(0.9f, 0.9f, 0.1f, 0.37f);
  glVertex2f(-1.2f, 0.2f);
  glVertex2f(0.2f, 0.2f);
  glColor4f(0.1f, 0.8f, 0.9f, 0.71f);
  glVertex2f(0.2f, 0.8f);
  glVertex2f(-1.2f, 0.8f);
  glEnd();
  glBlendFunc(GL_ONE, GL_ONE);
  glBegin(GL_TRIANGLES);
  glColor4f(0.8f, 0.7f, 0.6f, 0.9f);
  glVertex2f(-0.3f, -0.8f);
  glVertex2f(1.4f, -0.6f);
  glVertex2f(0.9f, 0.6f);
  glEnd();
  glBlendFunc(GL_DST_COLOR, GL_ZERO);
  glBegin(GL_TRIANGLES);
  glColor4f(0.5f, 0.25f, 0.75f, 1.0f);
  glVertex2f(0.5f, -1.0f);
  glVertex2f(1.5f, -1.0f);
  glVertex2f(1.0f, 0.0f);
  glEnd();
  /* MIN and MAX of the unweighted colours (over the sum past 1). */
  glBlendEquation(GL_MAX);
  glBegin(GL_TRIANGLES);
  glColor4f(0.2f, 0.95f, 0.4f, 0.3f);
  glVertex2f(0.0f, -0.2f);
  glVertex2f(1.2f, -0.2f);
  glVertex2f(0.6f, 0.5f);
  glEnd();
  glBlendEquation(GL_MIN);
  glBegin(GL_TRIANGLES);
  glColor4f(0.6f, 0.35f, 0.9f, 0.5f);
  glVertex2f(0.3f, -0.7f);
  glVertex2f(1.3f, -0.5f);
  glVertex2f(0.7f, 0.1f);
  glEnd();
  glBlendEquation(GL_FUNC_ADD);
  glDisable(GL_BLEND);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.45f);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, -1.0f);
  glFogf(GL_FOG_END, 1.5f);
  GLfloat fogc[] = {0.6f, 0.1f, 0.5f, 1.0f};
  glFogfv(GL_FOG_COLOR, fogc);
  glBegin(GL_TRIANGLES);
  glColor4f(0.2f, 1.0f, 0.4f, 0.0f);
  glVertex3f(-1.5f, -0.2f, 1.0f);
  glColor4f(0.9f, 0.3f, 0.1f, 1.0f);
  glVertex3f(-0.2f, -1.1f, -1.0f);
  glColor4f(0.4f, 0.4f, 0.9f, 0.8f);
  glVertex3f(-0.6f, 0.4f, 0.0f);
  glEnd();
  glDisable(GL_FOG);
  glDisable(GL_ALPHA_TEST);
  glEnable(GL_COLOR_SUM);
  glBegin(GL_TRIANGLES);
  glColor4f(0.8f, 0.6f, 0.2f, 1.0f);
  glSecondaryColor3f(0.7f, 0.9f, 0.1f);
  glVertex2f(0.9f, 1.1f);
  glColor4f(0.4f, 0.9f, 0.9f, 1.0f);
  glSecondaryColor3f(0.9f, 0.3f, 0.6f);
  glVertex2f(1.5f, 1.1f);
  glVertex2f(1.5f, 0.2f);
  glEnd();
  glDisable(GL_COLOR_SUM);
  glEnable(GL_SCISSOR_TEST);
  glScissor(5, 30, 20, 12);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
  glClearColor(0.77f, 0.5f, 0.123f, 0.9f);
  glClear(GL_COLOR_BUFFER_BIT);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_SCISSOR_TEST);
}

static void logic_op(void) {
  glEnable(GL_COLOR_LOGIC_OP);
  glLogicOp(GL_XOR);
  glBegin(GL_TRIANGLES);
  glColor4f(0.3f, 0.6f, 0.9f, 0.5f);
  glVertex2f(-1.5f, 1.1f);
  glVertex2f(-0.5f, 1.1f);
  glVertex2f(-1.0f, 0.3f);
  glEnd();
  glDisable(GL_COLOR_LOGIC_OP);
}

/* An object of a colour renderbuffer of `format` and a DEPTH24_STENCIL8 one. */
static GLuint object(GLenum format, GLuint rbs[2]) { return colour_depth_object(format, 0, W, H, rbs); }

static float f[W * H * 4];
static unsigned short us[W * H * 4];
static unsigned char ub[W * H * 4];

/* The read framebuffer's pixels as floats, shorts and bytes: <name>.f, .us, .ub. */
static void read_all(const char *name) {
  char file[64];
  memset(f, 0, sizeof f);
  memset(us, 0, sizeof us);
  memset(ub, 0, sizeof ub);
  glReadPixels(0, 0, W, H, GL_RGBA, GL_FLOAT, f);
  glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_SHORT, us);
  glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, ub);
  snprintf(file, sizeof file, "%s.f", name);
  dump(file, f, sizeof f);
  snprintf(file, sizeof file, "%s.us", name);
  dump(file, us, sizeof us);
  snprintf(file, sizeof file, "%s.ub", name);
  dump(file, ub, sizeof ub);
}

int main(int argc, char **argv) {
  start(argc, argv);
  static unsigned char window[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(ctx);
  CHECK(OSMesaMakeCurrent(ctx, window, GL_UNSIGNED_BYTE, W, H));
  const struct { GLenum format; const char *name; } formats[] = {
    {GL_RGBA16, "rgba16"}, {GL_RGBA32F, "rgba32f"}, {GL_RGBA16F, "rgba16f"},
    {GL_RGB16, "rgb16"}, {GL_RGB16F, "rgb16f"}, {GL_RGB32F, "rgb32f"},
  };
  GLuint fbos[6], rbs[6][2];
  for (int i = 0; i < 6; i++) {
    fbos[i] = object(formats[i].format, rbs[i]);
    GLint s[6];
    glBindRenderbuffer(GL_RENDERBUFFER, rbs[i][0]);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_RED_SIZE, &s[0]);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_GREEN_SIZE, &s[1]);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_BLUE_SIZE, &s[2]);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_ALPHA_SIZE, &s[3]);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_INTERNAL_FORMAT, &s[4]);
    printf("%s sizes %d %d %d %d internal 0x%x error 0x%x\n", formats[i].name, s[0], s[1], s[2], s[3], s[4],
           glGetError());
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    printf("%s status 0x%x\n", formats[i].name, status);
    if (status != GL_FRAMEBUFFER_COMPLETE) continue;
    GLint bits[4];
    glGetIntegerv(GL_RED_BITS, &bits[0]);
    glGetIntegerv(GL_GREEN_BITS, &bits[1]);
    glGetIntegerv(GL_BLUE_BITS, &bits[2]);
    glGetIntegerv(GL_ALPHA_BITS, &bits[3]);
    printf("%s bits %d %d %d %d\n", formats[i].name, bits[0], bits[1], bits[2], bits[3]);
    scene();
    logic_op();
    printf("%s error 0x%x\n", formats[i].name, glGetError());
    read_all(formats[i].name);
  }
  /* A GL_RGBA16 texture drawn into, then read with glGetTexImage (tex16.us). */
  {
    GLuint tex, fbo, ds[2];
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16, W, H, 0, GL_RGBA, GL_UNSIGNED_SHORT, NULL);
    fbo = object(GL_RGBA8, ds);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
    printf("tex16 status 0x%x\n", glCheckFramebufferStatus(GL_FRAMEBUFFER));
    GLint bits = 0;
    glGetIntegerv(GL_RED_BITS, &bits);
    printf("tex16 bits %d\n", bits);
    scene();
    logic_op();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    memset(us, 0, sizeof us);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_SHORT, us);
    printf("tex16 error 0x%x\n", glGetError());
    dump("tex16.us", us, sizeof us);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  GLint red = 0;
  glGetIntegerv(GL_RED_BITS, &red);
  printf("window bits %d\n", red);

  /* An RGBA8 object with the scene, and blits between the three. */
  GLuint rgba8_rbs[2];
  GLuint rgba8 = object(GL_RGBA8, rgba8_rbs);
  scene();
  GLuint dst[3], dst_rbs[3][2];
  const GLenum dst_formats[] = {GL_RGBA8, GL_RGBA16, GL_RGBA32F};
  for (int i = 0; i < 3; i++) dst[i] = object(dst_formats[i], dst_rbs[i]);
  const struct { GLuint from; int to; int src[4]; int dst[4]; GLenum filter; } blits[] = {
    {fbos[1], 0, {0, 0, W, H}, {0, 0, W, H}, GL_NEAREST},       /* float to bytes */
    {fbos[0], 0, {0, 0, W, H}, {0, 0, W, H}, GL_NEAREST},       /* shorts to bytes */
    {rgba8, 2, {0, 0, W, H}, {0, 0, W, H}, GL_NEAREST},         /* bytes to float */
    {rgba8, 1, {0, 0, W, H}, {0, 0, W, H}, GL_NEAREST},         /* bytes to shorts */
    {fbos[1], 1, {0, 0, W / 2, H / 2}, {W, H, 0, 0}, GL_NEAREST}, /* float to shorts, scaled, flipped */
    {fbos[0], 2, {0, 0, W, H}, {0, 0, W, H}, GL_NEAREST},       /* shorts to float */
    {fbos[1], 2, {3, 5, W - 7, H - 2}, {0, 0, W, H}, GL_LINEAR}, /* float to float, linear */
    {fbos[0], 0, {0, 0, W, H}, {0, 0, W / 2 + 3, H / 2 + 1}, GL_LINEAR}, /* shorts to bytes, linear */
  };
  for (int i = 0; i < (int)(sizeof blits / sizeof blits[0]); i++) {
    glBindFramebuffer(GL_FRAMEBUFFER, dst[blits[i].to]);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, blits[i].from);
    glBlitFramebuffer(blits[i].src[0], blits[i].src[1], blits[i].src[2], blits[i].src[3], blits[i].dst[0],
                      blits[i].dst[1], blits[i].dst[2], blits[i].dst[3], GL_COLOR_BUFFER_BIT, blits[i].filter);
    printf("blit %d error 0x%x\n", i, glGetError());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, dst[blits[i].to]);
    char name[32];
    snprintf(name, sizeof name, "blit.%d", i);
    read_all(name);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  printf("done\n");
  return 0;
}
