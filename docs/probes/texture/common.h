#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
static unsigned char fbuf[64*64*4];
static void init(void){
  OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  if(!c||!OSMesaMakeCurrent(c, fbuf, GL_UNSIGNED_BYTE, 64, 64)){fprintf(stderr,"ctx\n");exit(1);}
}
