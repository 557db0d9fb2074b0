/* The cost of one GL attribute call through the OSMesa C ABI (issue 13, item 4),
 * for Mesa and softgl with the same client (not a test):
 *   cc -O2 osmesa/bench/calls.c -o /tmp/calls -lOSMesa -lGLU -lm
 *   LP_NUM_THREADS=1 /tmp/calls [CASE] [CALLS] [REPS]                    # Mesa llvmpipe
 *   LD_LIBRARY_PATH=$PWD/target/release/osmesa /tmp/calls [CASE] ...      # softgl
 * CASE: all (default), color3f, color3fv, normal3f, normal3fv, texcoord2f,
 * texcoord2fv (each outside glBegin/glEnd), vertex3f, vertex3fv (inside
 * glBegin(GL_POINTS)/glEnd, 1000 vertices a batch, every point at z = 5, outside
 * the default clip volume, so nothing is rasterized), mixed (glColor3f,
 * glNormal3f, glTexCoord2f and glVertex3f per point, the same batches).
 * CALLS (default 10 million) calls a repetition, REPS (default 7) repetitions.
 * Prints per case the median over the repetitions of ns per call; the vertex
 * cases time the calls between glBegin and glEnd only and print glEnd's cost per
 * vertex beside them (clipping the points away: the draw path's, not the ABI's).
 * Instructions per call: run `valgrind --tool=callgrind /tmp/calls color3f 200000 1`
 * and again with 400000, and divide the difference of the totals by 220000 (each
 * run adds a tenth as warm-up); the benchmark's own loop counts 11 of them. */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
static double now(void){struct timespec t;clock_gettime(CLOCK_MONOTONIC,&t);return t.tv_sec+t.tv_nsec*1e-9;}
static int cmp(const void*a,const void*b){double x=*(const double*)a,y=*(const double*)b;return x<y?-1:x>y;}
#define BATCH 1000
#define MAXREPS 64
static double end_ns; /* glEnd's share of the last vertex repetition, ns per vertex */

/* One repetition of `n` calls of case `c`: ns per call. */
static double run(const char*c, long n){
  float v[4]={0.25f,0.5f,0.75f,1.0f};
  double t0=now(), tend=0;
  if(!strcmp(c,"color3f")) for(long i=0;i<n;i++) glColor3f((float)(i&255)*(1.0f/256),0.5f,0.25f);
  else if(!strcmp(c,"color3fv")) for(long i=0;i<n;i++){ v[0]=(float)(i&255)*(1.0f/256); glColor3fv(v); }
  else if(!strcmp(c,"normal3f")) for(long i=0;i<n;i++) glNormal3f((float)(i&255)*(1.0f/256),0.5f,0.25f);
  else if(!strcmp(c,"normal3fv")) for(long i=0;i<n;i++){ v[0]=(float)(i&255)*(1.0f/256); glNormal3fv(v); }
  else if(!strcmp(c,"texcoord2f")) for(long i=0;i<n;i++) glTexCoord2f((float)(i&255)*(1.0f/256),0.5f);
  else if(!strcmp(c,"texcoord2fv")) for(long i=0;i<n;i++){ v[0]=(float)(i&255)*(1.0f/256); glTexCoord2fv(v); }
  else if(!strcmp(c,"vertex3f")||!strcmp(c,"vertex3fv")||!strcmp(c,"mixed")){
    int fv=!strcmp(c,"vertex3fv"), mixed=!strcmp(c,"mixed");
    long per=mixed?4:1, verts=n/per;
    double calls=0;
    for(long done=0;done<verts;done+=BATCH){
      long m=verts-done<BATCH?verts-done:BATCH;
      glBegin(GL_POINTS);
      double a=now();
      for(long i=0;i<m;i++){
        float x=(float)(i&255)*(1.0f/128)-1.0f;
        if(mixed){ glColor3f(x,0.5f,0.25f); glNormal3f(0,0,1); glTexCoord2f(x,0.5f); glVertex3f(x,0.5f,5.0f); }
        else if(fv){ v[0]=x; v[2]=5.0f; glVertex3fv(v); }
        else glVertex3f(x,0.5f,5.0f);
      }
      double b=now();
      glEnd();
      calls+=b-a; tend+=now()-b;
    }
    end_ns=tend*1e9/(double)(verts?verts:1);
    return calls*1e9/(double)(verts*per);
  }
  else { fprintf(stderr,"unknown case %s\n",c); exit(2); }
  return (now()-t0)*1e9/(double)n;
}

int main(int argc,char**argv){
  const char*which = argc>1 ? argv[1] : "all";
  long n = argc>2 ? atol(argv[2]) : 10000000;
  int reps = argc>3 ? atoi(argv[3]) : 7;
  if(reps<1) reps=1;
  if(reps>MAXREPS) reps=MAXREPS;
  static unsigned char buf[16*16*4];
  OSMesaContext ctx=OSMesaCreateContextExt(OSMESA_RGBA,0,0,0,NULL);
  if(!ctx||!OSMesaMakeCurrent(ctx,buf,GL_UNSIGNED_BYTE,16,16)){fprintf(stderr,"no context\n");return 1;}
  static const char*cases[]={"color3f","color3fv","normal3f","normal3fv","texcoord2f","texcoord2fv",
                             "vertex3f","vertex3fv","mixed"};
  for(unsigned k=0;k<sizeof cases/sizeof*cases;k++){
    const char*c=cases[k];
    if(strcmp(which,"all")&&strcmp(which,c)) continue;
    double t[MAXREPS], e[MAXREPS];
    run(c,n/10>0?n/10:1); /* warm-up */
    for(int r=0;r<reps;r++){ t[r]=run(c,n); e[r]=end_ns; }
    qsort(t,reps,sizeof*t,cmp); qsort(e,reps,sizeof*e,cmp);
    if(!strncmp(c,"vertex",6)||!strcmp(c,"mixed"))
      printf("%-12s %7.2f ns/call  (glEnd %.2f ns/vertex)\n",c,t[reps/2],e[reps/2]);
    else printf("%-12s %7.2f ns/call\n",c,t[reps/2]);
  }
  if(glGetError()!=GL_NO_ERROR){fprintf(stderr,"GL error\n");return 1;}
  OSMesaMakeCurrent(NULL,NULL,0,0,0);
  OSMesaDestroyContext(ctx);
  return 0;
}
