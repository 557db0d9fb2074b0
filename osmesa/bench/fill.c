/* Fill rate through the OSMesa C ABI, for Mesa and softgl (not a test):
 *   cc -O2 osmesa/bench/fill.c -o /tmp/fill -lOSMesa
 *   LP_NUM_THREADS=1 /tmp/fill                                  # Mesa llvmpipe
 *   LD_LIBRARY_PATH=$PWD/target/release/osmesa /tmp/fill        # softgl
 * 1024x1024 RGBA8 + depth 24, single thread. Frames: 16 full-screen smooth
 * quads without depth (fill), the same with a LESS depth test each passing
 * (depth), and 20,000 random smooth depth-tested triangles of 2,000 pixels
 * (tris). Prints ms/frame and Mfragments/s for each, then a fogged variant
 * (EXP fog + colour sum) of each. */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#define W 1024
#define H 1024
#define NT 20000
static double now(void){struct timespec t;clock_gettime(CLOCK_MONOTONIC,&t);return t.tv_sec+t.tv_nsec*1e-9;}
static float tri[NT*9], col[NT*9];
static void quads(int depth){
  glBegin(GL_QUADS);
  for(int q=0;q<16;q++){ float z = depth ? 0.9f - q*0.1f : 0.0f;
    glColor3f(1,0,0); glVertex3f(-1,-1,z); glColor3f(0,1,0); glVertex3f(1,-1,z);
    glColor3f(0,0,1); glVertex3f(1,1,z); glColor3f(1,1,1); glVertex3f(-1,1,z); }
  glEnd();
}
static void run(const char*name, int kind, double frags){
  for(int pass=0;pass<2;pass++){
    int frames=pass?10:2; double t0=now();
    for(int f=0;f<frames;f++){
      glClear(GL_COLOR_BUFFER_BIT|GL_DEPTH_BUFFER_BIT);
      if(kind==0){glDisable(GL_DEPTH_TEST); quads(0);}
      else if(kind==1){glEnable(GL_DEPTH_TEST); quads(1);}
      else {glEnable(GL_DEPTH_TEST); glDrawArrays(GL_TRIANGLES,0,NT*3);}
      glFinish();
    }
    double dt=(now()-t0)/frames;
    if(pass) printf("%-22s %8.2f ms/frame %8.1f Mfrag/s\n",name,dt*1000,frags/dt/1e6);
  }
}
int main(void){
  unsigned char*buf=malloc(W*H*4);
  OSMesaContext c=OSMesaCreateContextExt(OSMESA_RGBA,24,8,0,NULL); OSMesaMakeCurrent(c,buf,GL_UNSIGNED_BYTE,W,H);
  srand(1);
  const float a = 0.12351f; /* legs of 63.2 px: 2,000 px a triangle */
  for(int t=0;t<NT;t++){float cx=(rand()/(float)RAND_MAX)*1.7f-0.9f, cy=(rand()/(float)RAND_MAX)*1.7f-0.9f;
    float v[3][2]={{cx,cy},{cx+a,cy},{cx,cy+a}};
    for(int k=0;k<3;k++){tri[t*9+k*3]=v[k][0];tri[t*9+k*3+1]=v[k][1];tri[t*9+k*3+2]=(rand()/(float)RAND_MAX)*2-1;}}
  for(int i=0;i<NT*9;i++) col[i]=rand()/(float)RAND_MAX;
  glVertexPointer(3,GL_FLOAT,0,tri); glColorPointer(3,GL_FLOAT,0,col);
  glEnableClientState(GL_VERTEX_ARRAY); glEnableClientState(GL_COLOR_ARRAY);
  for(int fog=0;fog<2;fog++){
    if(fog){ glEnable(GL_FOG); glFogi(GL_FOG_MODE,GL_EXP); glFogf(GL_FOG_DENSITY,0.5f); glEnable(GL_COLOR_SUM);
             glSecondaryColor3f(0.1f,0.2f,0.05f); printf("fog EXP + colour sum:\n"); }
    run("fill 16 quads", 0, 16.0*W*H);
    run("depth 16 quads", 1, 16.0*W*H);
    run("20k tris 2000px", 2, (double)NT*2000);
  }
  return 0;
}
