/* Frame times through the OSMesa C ABI, for Mesa and softgl (not a test):
 *   cc -O2 osmesa/bench/frames.c -o /tmp/frames -lOSMesa -lGLU
 *   LP_NUM_THREADS=1 /tmp/frames                                  # Mesa llvmpipe
 *   LD_LIBRARY_PATH=$PWD/target/release/osmesa /tmp/frames        # softgl
 * Add the argument `f` for a GL_FLOAT buffer. */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glu.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
static double now(void){struct timespec t;clock_gettime(CLOCK_MONOTONIC,&t);return t.tv_sec+t.tv_nsec*1e-9;}
int main(int argc,char**argv){
  int W=512,H=512; unsigned char*buf=malloc(W*H*4);
  GLenum fmt = argc>1 && argv[1][0]=='f' ? GL_FLOAT : GL_UNSIGNED_BYTE;
  void *b = fmt==GL_FLOAT ? malloc(W*H*16) : buf;
  OSMesaContext c=OSMesaCreateContextExt(OSMESA_RGBA,24,8,0,NULL); OSMesaMakeCurrent(c,b,fmt,W,H);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION); gluPerspective(40,1,1,20); glMatrixMode(GL_MODELVIEW); gluLookAt(0,2,8,0,0,0,0,1,0);
  GLUquadric*q=gluNewQuadric();
  srand(1); static float tri[20000*9], col[20000*9];
  for(int t=0;t<20000;t++){float cx=(rand()/(float)RAND_MAX)*1.8f-0.9f, cy=(rand()/(float)RAND_MAX)*1.8f-0.9f; for(int v=0;v<3;v++){tri[t*9+v*3]=cx+(rand()/(float)RAND_MAX)*0.2f-0.1f; tri[t*9+v*3+1]=cy+(rand()/(float)RAND_MAX)*0.2f-0.1f; tri[t*9+v*3+2]=(rand()/(float)RAND_MAX)*2-1;}}
  for(int i=0;i<20000*9;i++) col[i]=rand()/(float)RAND_MAX;
  /* warm-up */
  for(int pass=0;pass<2;pass++){
    int frames=pass?20:3; double t0=now();
    for(int f=0;f<frames;f++){
      glClear(GL_COLOR_BUFFER_BIT|GL_DEPTH_BUFFER_BIT);
      glColor3f(1,0,0); gluSphere(q,1.5,64,48);
      glFinish();
    }
    double t1=now();
    if(pass) printf("sphere 64x48 512x512: %.2f ms/frame\n",(t1-t0)*1000/frames);
  }
  glMatrixMode(GL_PROJECTION); glLoadIdentity(); glMatrixMode(GL_MODELVIEW); glLoadIdentity();
  glVertexPointer(3,GL_FLOAT,0,tri); glColorPointer(3,GL_FLOAT,0,col); glEnableClientState(GL_VERTEX_ARRAY); glEnableClientState(GL_COLOR_ARRAY);
  for(int pass=0;pass<2;pass++){
    int frames=pass?10:2; double t0=now();
    for(int f=0;f<frames;f++){ glClear(GL_COLOR_BUFFER_BIT|GL_DEPTH_BUFFER_BIT); glDrawArrays(GL_TRIANGLES,0,20000*3); glFinish(); }
    double t1=now();
    if(pass) printf("20k random triangles (arrays) 512x512: %.2f ms/frame\n",(t1-t0)*1000/frames);
  }
  glDisableClientState(GL_VERTEX_ARRAY); glDisableClientState(GL_COLOR_ARRAY);
  for(int pass=0;pass<2;pass++){
    int frames=pass?10:2; double t0=now();
    for(int f=0;f<frames;f++){ glClear(GL_COLOR_BUFFER_BIT|GL_DEPTH_BUFFER_BIT); glBegin(GL_TRIANGLES); for(int i=0;i<20000*3;i++){glColor3fv(col+i*3);glVertex3fv(tri+i*3);} glEnd(); glFinish(); }
    double t1=now();
    if(pass) printf("20k random triangles (immediate) 512x512: %.2f ms/frame\n",(t1-t0)*1000/frames);
  }
  return 0;
}
