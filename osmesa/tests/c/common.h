/* Shared helpers of the OSMesa client tests: each program is built once
 * against Mesa's headers (-lOSMesa) and run twice, on Mesa and on softgl
 * (LD_LIBRARY_PATH), writing its results into the directory argv[1]. */
#define _GNU_SOURCE
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *out_dir = ".";

/* Writes n bytes to <out_dir>/<name>. */
static void dump(const char *name, const void *data, size_t n) {
  char path[4096];
  snprintf(path, sizeof path, "%s/%s", out_dir, name);
  FILE *f = fopen(path, "wb");
  if (!f) { perror(path); exit(2); }
  if (n && fwrite(data, 1, n, f) != n) { perror(path); exit(2); }
  fclose(f);
}

/* Prints which file provides OSMesaCreateContext (the test checks it). */
static void report_library(void) {
  Dl_info info;
  if (dladdr((void *)OSMesaCreateContext, &info) && info.dli_fname)
    printf("library %s\n", info.dli_fname);
}

static void start(int argc, char **argv) {
  if (argc > 1) out_dir = argv[1];
  report_library();
}

#define CHECK(cond) do { if (!(cond)) { fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); exit(1); } } while (0)
