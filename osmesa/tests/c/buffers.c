/* Buffer objects (GL 1.5), every function loaded through
 * OSMesaGetProcAddress as MuJoCo loads them: vertex and colour arrays in
 * buffers (offsets, strides, mixed with client arrays), element buffers for
 * glDrawElements/glDrawRangeElements/glMultiDrawElements, glMultiDrawArrays,
 * glInterleavedArrays and glArrayElement from a buffer, glBufferSubData and
 * glMapBuffer writes, a draw compiled into a display list (the buffer read at
 * compile time), reads past a buffer's end, and the state, queries and errors.
 * The image and every printed line are compared with Mesa's, except the
 * "mapped draw" line (Mesa 22 does not check it). */
#include "common.h"
#include <GL/glext.h>
#include <stddef.h>

#define W 128
#define H 96
#define E(call) do { call; printf("%-60s 0x%04x\n", #call, glGetError()); } while (0)

static PFNGLGENBUFFERSPROC GenBuffers;
static PFNGLDELETEBUFFERSPROC DeleteBuffers;
static PFNGLISBUFFERPROC IsBuffer;
static PFNGLBINDBUFFERPROC BindBuffer;
static PFNGLBUFFERDATAPROC BufferData;
static PFNGLBUFFERSUBDATAPROC BufferSubData;
static PFNGLGETBUFFERSUBDATAPROC GetBufferSubData;
static PFNGLMAPBUFFERPROC MapBuffer;
static PFNGLUNMAPBUFFERPROC UnmapBuffer;
static PFNGLGETBUFFERPARAMETERIVPROC GetBufferParameteriv;
static PFNGLGETBUFFERPOINTERVPROC GetBufferPointerv;
static PFNGLMULTIDRAWARRAYSPROC MultiDrawArrays;
static PFNGLMULTIDRAWELEMENTSPROC MultiDrawElements;
static PFNGLDRAWRANGEELEMENTSPROC DrawRangeElements;
static PFNGLBINDBUFFERARBPROC BindBufferARB;

#define LOAD(var, name) do { var = (void *)OSMesaGetProcAddress(name); CHECK(var); } while (0)

/* Position (x, y) and colour (r, g, b, a) floats of one vertex. */
typedef struct { float x, y; float r, g, b, a; } Vert;

static void params(const char *what) {
  GLint size = -1, usage = -1, access = -1, mapped = -1;
  GetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &size);
  GetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_USAGE, &usage);
  GetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS, &access);
  GetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED, &mapped);
  printf("%s: size %d usage 0x%x access 0x%x mapped %d error 0x%x\n", what, size, usage, access, mapped,
         glGetError());
}

static void binding(const char *what) {
  GLint a = -1, e = -1, v = -1, c = -1, t = -1;
  glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &a);
  glGetIntegerv(GL_ELEMENT_ARRAY_BUFFER_BINDING, &e);
  glGetIntegerv(GL_VERTEX_ARRAY_BUFFER_BINDING, &v);
  glGetIntegerv(GL_COLOR_ARRAY_BUFFER_BINDING, &c);
  glGetIntegerv(GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING, &t);
  void *p = (void *)1;
  glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
  printf("%s: array %d element %d vertex %d color %d texcoord %d vertex pointer %ld\n", what, a, e, v, c, t,
         (long)(size_t)p);
}

/* A quad of two triangles at (x, y) with side s, each corner its colour. */
static void quad(Vert *v, float x, float y, float s, float r, float g, float b) {
  Vert q[6] = {{x, y, r, 0, 0, 1},     {x + s, y, 0, g, 0, 1}, {x + s, y + s, 0, 0, b, 1},
               {x, y, r, 0, 0, 1},     {x + s, y + s, 0, 0, b, 1}, {x, y + s, r, g, b, 1}};
  memcpy(v, q, sizeof q);
}

int main(int argc, char **argv) {
  start(argc, argv);
  static unsigned char buf[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
  LOAD(GenBuffers, "glGenBuffers");
  LOAD(DeleteBuffers, "glDeleteBuffers");
  LOAD(IsBuffer, "glIsBuffer");
  LOAD(BindBuffer, "glBindBuffer");
  LOAD(BufferData, "glBufferData");
  LOAD(BufferSubData, "glBufferSubData");
  LOAD(GetBufferSubData, "glGetBufferSubData");
  LOAD(MapBuffer, "glMapBuffer");
  LOAD(UnmapBuffer, "glUnmapBuffer");
  LOAD(GetBufferParameteriv, "glGetBufferParameteriv");
  LOAD(GetBufferPointerv, "glGetBufferPointerv");
  LOAD(MultiDrawArrays, "glMultiDrawArrays");
  LOAD(MultiDrawElements, "glMultiDrawElements");
  LOAD(DrawRangeElements, "glDrawRangeElements");
  LOAD(BindBufferARB, "glBindBufferARB");

  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, W, 0, H, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glShadeModel(GL_SMOOTH);

  /* Names and objects. */
  GLuint b[4] = {0};
  GenBuffers(4, b);
  printf("gen %u %u %u %u is %d\n", b[0], b[1], b[2], b[3], IsBuffer(b[0]));
  binding("initial");
  E(BindBuffer(GL_ARRAY_BUFFER, b[0]));
  printf("is after bind %d\n", IsBuffer(b[0]));
  params("new buffer");

  /* 1. Vertices and colours interleaved in one buffer, pointers as offsets. */
  Vert v[6 * 8];
  quad(v, 4, 4, 20, 1, 1, 1);
  quad(v + 6, 28, 4, 20, 1, 0.5f, 0.25f);
  E(BufferData(GL_ARRAY_BUFFER, sizeof v, v, GL_STATIC_DRAW));
  params("after data");
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, sizeof(Vert), (void *)offsetof(Vert, x));
  glColorPointer(4, GL_FLOAT, sizeof(Vert), (void *)offsetof(Vert, r));
  binding("pointers set");
  E(glDrawArrays(GL_TRIANGLES, 0, 12));

  /* 2. glBufferSubData moves the second quad up; the first is drawn from offset 0 again. */
  Vert moved[6];
  quad(moved, 28, 28, 20, 0.25f, 1, 0.5f);
  E(BufferSubData(GL_ARRAY_BUFFER, 6 * sizeof(Vert), sizeof moved, moved));
  E(glDrawArrays(GL_TRIANGLES, 6, 6));
  Vert back[6];
  E(GetBufferSubData(GL_ARRAY_BUFFER, 6 * sizeof(Vert), sizeof back, back));
  printf("read back %g %g %g\n", back[2].x, back[2].y, back[2].g);

  /* 3. Mapped: written through the pointer, errors while mapped, unmapped. */
  Vert *m = MapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY);
  printf("map error 0x%x\n", glGetError());
  params("mapped");
  void *mp = NULL;
  GetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &mp);
  printf("map pointer same %d\n", mp == (void *)m);
  E(MapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY));
  E(BufferSubData(GL_ARRAY_BUFFER, 0, 4, v));
  E(GetBufferSubData(GL_ARRAY_BUFFER, 0, 4, back));
  glDrawArrays(GL_TRIANGLES, 0, 6);
  printf("mapped draw 0x%04x\n", glGetError());
  quad(m + 12, 52, 4, 20, 0, 1, 1);
  GLboolean un = UnmapBuffer(GL_ARRAY_BUFFER);
  printf("unmap %d error 0x%x\n", un, glGetError());
  E(UnmapBuffer(GL_ARRAY_BUFFER));
  params("unmapped");
  GetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &mp);
  printf("map pointer after unmap %p\n", mp);
  E(glDrawArrays(GL_TRIANGLES, 12, 6));

  /* 4. An element buffer: glDrawElements, glDrawRangeElements with an offset. */
  quad(v + 18, 76, 4, 20, 1, 1, 0);
  quad(v + 24, 100, 4, 20, 1, 0, 1);
  E(BufferSubData(GL_ARRAY_BUFFER, 18 * sizeof(Vert), 12 * sizeof(Vert), v + 18));
  GLushort idx[12] = {18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29};
  E(BindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[1]));
  E(BufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx, idx, GL_STREAM_DRAW));
  E(glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, 0));
  E(DrawRangeElements(GL_TRIANGLES, 24, 29, 6, GL_UNSIGNED_SHORT, (void *)(6 * sizeof(GLushort))));
  binding("element bound");

  /* 5. glMultiDrawArrays and glMultiDrawElements (offsets into the element buffer), translated up. */
  glPushMatrix();
  glTranslatef(0, 50, 0);
  GLint firsts[2] = {0, 12};
  GLsizei counts[2] = {6, 6};
  E(MultiDrawArrays(GL_TRIANGLES, firsts, counts, 2));
  const void *offs[2] = {(void *)0, (void *)(6 * sizeof(GLushort))};
  glTranslatef(0, -25, 0);
  E(MultiDrawElements(GL_TRIANGLES, counts, GL_UNSIGNED_SHORT, offs, 2));
  E(MultiDrawArrays(GL_TRIANGLES, firsts, counts, -1));
  glPopMatrix();

  /* 6. Client indices again once the element buffer is unbound; a client colour array mixed in. */
  E(BindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0));
  static const GLubyte cidx[6] = {0, 1, 2, 3, 4, 5};
  static const float red[6 * 4] = {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1};
  E(BindBuffer(GL_ARRAY_BUFFER, 0));
  glColorPointer(4, GL_FLOAT, 0, red);
  binding("colour from the client");
  glPushMatrix();
  glTranslatef(0, 72, 0);
  E(glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, cidx));
  glPopMatrix();

  /* 7. glArrayElement from the buffer (vertex) and client memory (colour). */
  glPushMatrix();
  glTranslatef(24, 72, 0);
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 3; i++) glArrayElement(i);
  glEnd();
  glPopMatrix();
  printf("array element error 0x%x\n", glGetError());

  /* 8. glInterleavedArrays with a buffer bound: GL_C4UB_V2F at an offset. */
  struct { GLubyte c[4]; float x, y; } il[4] = {
      {{255, 0, 0, 255}, 52, 72}, {{0, 255, 0, 255}, 70, 72}, {{0, 0, 255, 255}, 70, 90}, {{255, 255, 255, 255}, 52, 90}};
  E(BindBuffer(GL_ARRAY_BUFFER, b[2]));
  E(BufferData(GL_ARRAY_BUFFER, 16 + sizeof il, NULL, GL_DYNAMIC_DRAW));
  E(BufferSubData(GL_ARRAY_BUFFER, 16, sizeof il, il));
  E(glInterleavedArrays(GL_C4UB_V2F, 0, (void *)16));
  binding("interleaved");
  E(glDrawArrays(GL_QUADS, 0, 4));

  /* 9. A draw compiled into a list reads the buffer then: changing it later does not change the list. */
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glTranslatef(22, 0, 0);
  glDrawArrays(GL_QUADS, 0, 4);
  E(BufferSubData(GL_ARRAY_BUFFER, 16 + 8, 4, &il[1].x));
  glEndList();
  E(glCallList(list));
  glLoadIdentity();

  /* 10. Past the end: colours of vertices outside the buffer, and indices past the element buffer. */
  struct { float x, y, z, w; } pos[4] = {{100, 30, 0, 1}, {124, 30, 0, 1}, {124, 48, 0, 1}, {100, 48, 0, 1}};
  float cols[2 * 4] = {1, 1, 0, 1, 0, 1, 1, 1};
  E(BindBuffer(GL_ARRAY_BUFFER, b[3]));
  E(BufferData(GL_ARRAY_BUFFER, sizeof pos + sizeof cols, NULL, GL_STATIC_DRAW));
  E(BufferSubData(GL_ARRAY_BUFFER, 0, sizeof pos, pos));
  E(BufferSubData(GL_ARRAY_BUFFER, sizeof pos, sizeof cols, cols));
  glInterleavedArrays(GL_V2F, 0, NULL);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(4, GL_FLOAT, 0, 0);
  glColorPointer(4, GL_FLOAT, 0, (void *)sizeof pos);
  E(glDrawArrays(GL_QUADS, 0, 4));
  GLubyte few[2] = {1, 2};
  E(BindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[1]));
  E(BufferData(GL_ELEMENT_ARRAY_BUFFER, 2, few, GL_STATIC_DRAW));
  glTranslatef(0, 20, 0);
  E(glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_BYTE, 0));
  glLoadIdentity();

  /* 11. The client attribute stack keeps the bindings. */
  E(glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT));
  E(BindBuffer(GL_ARRAY_BUFFER, b[0]));
  E(BindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0));
  glVertexPointer(3, GL_FLOAT, 0, (void *)8);
  binding("pushed and changed");
  E(glPopClientAttrib());
  binding("popped");
  E(glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT));
  E(BindBuffer(GL_ARRAY_BUFFER, b[0]));
  E(glPopClientAttrib());
  binding("pixel store bit only");

  /* 12. Errors. */
  E(GenBuffers(-1, b));
  E(DeleteBuffers(-1, b));
  E(BindBuffer(GL_TEXTURE_2D, b[0]));
  E(BufferData(GL_ARRAY_BUFFER, -1, NULL, GL_STATIC_DRAW));
  E(BufferData(GL_ARRAY_BUFFER, 4, NULL, GL_TEXTURE_2D));
  E(BufferData(GL_TEXTURE_2D, 4, NULL, GL_STATIC_DRAW));
  E(BufferSubData(GL_ARRAY_BUFFER, -1, 4, v));
  E(BufferSubData(GL_ARRAY_BUFFER, 0, sizeof v + 4, v));
  E(GetBufferSubData(GL_ARRAY_BUFFER, 4, sizeof v, back));
  E(MapBuffer(GL_ARRAY_BUFFER, GL_TEXTURE_2D));
  E(GetBufferParameteriv(GL_ARRAY_BUFFER, GL_TEXTURE_2D, (GLint *)back));
  E(GetBufferPointerv(GL_ARRAY_BUFFER, GL_TEXTURE_2D, &mp));
  E(BindBufferARB(GL_ARRAY_BUFFER, 0));
  E(BufferData(GL_ARRAY_BUFFER, 4, NULL, GL_STATIC_DRAW));
  E(BufferSubData(GL_ARRAY_BUFFER, 0, 0, v));
  E(MapBuffer(GL_ARRAY_BUFFER, GL_READ_WRITE));
  E(UnmapBuffer(GL_ARRAY_BUFFER));
  E(GetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, (GLint *)back));
  glBegin(GL_POINTS);
  GenBuffers(1, b + 3);
  glEnd();
  printf("gen inside begin 0x%x\n", glGetError());

  /* 13. Deleting bound buffers unbinds them, from the arrays too. */
  E(BindBuffer(GL_ARRAY_BUFFER, b[0]));
  E(BindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[1]));
  glVertexPointer(2, GL_FLOAT, sizeof(Vert), 0);
  glColorPointer(4, GL_FLOAT, sizeof(Vert), (void *)8);
  E(DeleteBuffers(2, b));
  printf("is after delete %d %d\n", IsBuffer(b[0]), IsBuffer(b[1]));
  binding("deleted");
  E(DeleteBuffers(4, b));

  glFinish();
  dump("buffers.color", buf, sizeof buf);
  OSMesaDestroyContext(ctx);
  printf("done\n");
  return 0;
}
