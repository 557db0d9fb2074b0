/* Contexts on different threads are independent: each thread has its own
 * current context, buffer and state, and they render at the same time. */
#include "common.h"
#include <math.h>
#include <pthread.h>

#define N 4
#define W 32
#define H 32
#define ROUNDS 40

static pthread_barrier_t barrier;
static int failures[N];

static void *worker(void *arg) {
  int id = (int)(size_t)arg;
  static unsigned char bufs[N][W * H * 4];
  unsigned char *buf = bufs[id];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) { failures[id]++; return NULL; }
  pthread_barrier_wait(&barrier);
  for (int r = 0; r < ROUNDS; r++) {
    if (OSMesaGetCurrentContext() != ctx) failures[id]++;
    float c = (float)(id + 1) / N;
    glClearColor(c, 0, 1 - c, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(0, (float)r / ROUNDS, 0);
    glBegin(GL_TRIANGLES);
    glVertex2f(-1, -1); glVertex2f(0, -1); glVertex2f(-1, 0);
    glEnd();
    glFinish();
    /* float to unorm8: round half to even in float, as llvmpipe and softgl do */
    const unsigned char *top = buf + ((H - 1) * W + (W - 1)) * 4;
    if (top[0] != lrintf(c * 255.0f) || top[2] != lrintf((1 - c) * 255.0f)) failures[id]++;
    if (buf[0] != 0 || buf[1] != lrintf((float)r / ROUNDS * 255.0f)) failures[id]++;
    if (glGetError() != GL_NO_ERROR) failures[id]++;
  }
  pthread_barrier_wait(&barrier);
  OSMesaDestroyContext(ctx);
  return NULL;
}

int main(int argc, char **argv) {
  start(argc, argv);
  pthread_t t[N];
  pthread_barrier_init(&barrier, NULL, N);
  for (int i = 0; i < N; i++) pthread_create(&t[i], NULL, worker, (void *)(size_t)i);
  for (int i = 0; i < N; i++) pthread_join(t[i], NULL);
  for (int i = 0; i < N; i++) printf("thread %d failures %d\n", i, failures[i]);
  printf("main thread current %d\n", OSMesaGetCurrentContext() == NULL);
  printf("done\n");
  return 0;
}
