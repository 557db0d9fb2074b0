/* Fill, depth and lit frames at 1024x1024 through the OSMesa C ABI, for Mesa
 * and softgl in one run (not a test; osmesa/bench/compare.sh runs it):
 *   cc -O2 osmesa/bench/fill.c -o /tmp/fill -lOSMesa -lGLU -lm
 *   LP_NUM_THREADS=1 /tmp/fill CASE                                 # Mesa llvmpipe
 *   LD_LIBRARY_PATH=$PWD/target/release/osmesa /tmp/fill CASE       # softgl
 * CASE: fill (16 full-screen smooth-shaded quads, no depth), depth (16 full-screen
 * quads, depth test LESS, nearer each time so every fragment passes), tris (20k random
 * triangles of ~2000 px, depth test), lit (a GLU sphere of 1000x800 slices/stacks,
 * ~1.6 M triangles, one infinite light, depth test), fog (fill with EXP fog and
 * GL_COLOR_SUM on), tex (the tris frame textured: a 256x256 RGBA8 texture with its
 * box-filtered mipmaps uploaded level by level, GL_LINEAR_MIPMAP_LINEAR, REPEAT,
 * MODULATE over the random colours, texture coordinates 3x the position so lambda
 * is about 0.6 and both levels are read, EXP fog). Prints one line: the case, the
 * median ms of the frames, and fragments (or triangles) per second. */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/glu.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
static double now(void){struct timespec t;clock_gettime(CLOCK_MONOTONIC,&t);return t.tv_sec+t.tv_nsec*1e-9;}
static int cmp(const void*a,const void*b){double x=*(const double*)a,y=*(const double*)b;return x<y?-1:x>y;}
#define W 1024
#define H 1024
static float tri[20000*9], col[20000*9], tc[20000*6];
/* A 256x256 RGBA checker of 16-texel cells with a colour ramp, and its mipmaps
 * (2x2 box, rounded), uploaded level by level. */
static void texture(void){
  static unsigned char lv[2][256*256*4];
  int n=256;
  for(int y=0;y<n;y++) for(int x=0;x<n;x++){ unsigned char*p=&lv[0][(y*n+x)*4]; int on=((x>>4)^(y>>4))&1;
    p[0]=on?255:(unsigned char)x; p[1]=on?(unsigned char)y:40; p[2]=on?60:200; p[3]=255; }
  glBindTexture(GL_TEXTURE_2D,1);
  for(int l=0;;l++){
    unsigned char*s=lv[l&1], *d=lv[(l+1)&1];
    glTexImage2D(GL_TEXTURE_2D,l,GL_RGBA8,n,n,0,GL_RGBA,GL_UNSIGNED_BYTE,s);
    if(n==1) break;
    int m=n/2;
    for(int y=0;y<m;y++) for(int x=0;x<m;x++) for(int c=0;c<4;c++)
      d[(y*m+x)*4+c]=(unsigned char)((s[((2*y)*n+2*x)*4+c]+s[((2*y)*n+2*x+1)*4+c]+s[((2*y+1)*n+2*x)*4+c]+s[((2*y+1)*n+2*x+1)*4+c]+2)/4);
    n=m;
  }
  glTexParameteri(GL_TEXTURE_2D,GL_TEXTURE_MIN_FILTER,GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D,GL_TEXTURE_MAG_FILTER,GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D,GL_TEXTURE_WRAP_S,GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D,GL_TEXTURE_WRAP_T,GL_REPEAT);
  glTexEnvi(GL_TEXTURE_ENV,GL_TEXTURE_ENV_MODE,GL_MODULATE);
  glEnable(GL_TEXTURE_2D);
}
static void quads(int depth){
  for(int k=0;k<16;k++){
    float z = depth ? 0.9f - k*0.1f : 0.0f;
    glBegin(GL_QUADS);
    glColor3f(1,0,0); glVertex3f(-1,-1,z);
    glColor3f(0,1,0); glVertex3f( 1,-1,z);
    glColor3f(0,0,1); glVertex3f( 1, 1,z);
    glColor3f(1,1,(k&1)?1.f:0.f); glVertex3f(-1, 1,z);
    glEnd();
  }
}
int main(int argc,char**argv){
  const char*c = argc>1 ? argv[1] : "fill";
  int frames = argc>2 ? atoi(argv[2]) : 9;
  unsigned char*buf=malloc((size_t)W*H*4);
  OSMesaContext ctx=OSMesaCreateContextExt(OSMESA_RGBA,24,8,0,NULL);
  if(!ctx||!OSMesaMakeCurrent(ctx,buf,GL_UNSIGNED_BYTE,W,H)){fprintf(stderr,"no context\n");return 1;}
  GLUquadric*q=gluNewQuadric();
  srand(1);
  for(int t=0;t<20000;t++){float cx=(rand()/(float)RAND_MAX)*1.8f-0.9f, cy=(rand()/(float)RAND_MAX)*1.8f-0.9f; for(int v=0;v<3;v++){tri[t*9+v*3]=cx+(rand()/(float)RAND_MAX)*0.2f-0.1f; tri[t*9+v*3+1]=cy+(rand()/(float)RAND_MAX)*0.2f-0.1f; tri[t*9+v*3+2]=(rand()/(float)RAND_MAX)*2-1;}}
  for(int i=0;i<20000*9;i++) col[i]=rand()/(float)RAND_MAX;
  for(int v=0;v<20000*3;v++){ tc[v*2]=tri[v*3]*3; tc[v*2+1]=tri[v*3+1]*3; }
  double work=0; const char*unit="Mfrag/s";
  if(!strcmp(c,"fill")){ work=16.0*W*H; }
  else if(!strcmp(c,"fog")){ glEnable(GL_FOG); glFogi(GL_FOG_MODE,GL_EXP); glFogf(GL_FOG_DENSITY,0.7f);
    glEnable(GL_COLOR_SUM); glSecondaryColor3f(0.1f,0.2f,0.3f); work=16.0*W*H; }
  else if(!strcmp(c,"depth")){ glEnable(GL_DEPTH_TEST); work=16.0*W*H; }
  else if(!strcmp(c,"tris")){ glEnable(GL_DEPTH_TEST);
    glVertexPointer(3,GL_FLOAT,0,tri); glColorPointer(3,GL_FLOAT,0,col);
    glEnableClientState(GL_VERTEX_ARRAY); glEnableClientState(GL_COLOR_ARRAY); work=0; unit="ms"; }
  else if(!strcmp(c,"tex")){ glEnable(GL_DEPTH_TEST); texture();
    glEnable(GL_FOG); glFogi(GL_FOG_MODE,GL_EXP); glFogf(GL_FOG_DENSITY,0.7f);
    GLfloat fogc[4]={0.5f,0.6f,0.7f,1}; glFogfv(GL_FOG_COLOR,fogc);
    glVertexPointer(3,GL_FLOAT,0,tri); glColorPointer(3,GL_FLOAT,0,col); glTexCoordPointer(2,GL_FLOAT,0,tc);
    glEnableClientState(GL_VERTEX_ARRAY); glEnableClientState(GL_COLOR_ARRAY); glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    work=0; unit="ms"; }
  else if(!strcmp(c,"lit")){ glEnable(GL_DEPTH_TEST); glEnable(GL_LIGHTING); glEnable(GL_LIGHT0);
    GLfloat pos[4]={1,1,2,0}; glLightfv(GL_LIGHT0,GL_POSITION,pos);
    GLfloat red[4]={0.8f,0.2f,0.2f,1}; glMaterialfv(GL_FRONT_AND_BACK,GL_AMBIENT_AND_DIFFUSE,red);
    glMatrixMode(GL_PROJECTION); gluPerspective(40,1,1,20); glMatrixMode(GL_MODELVIEW); gluLookAt(0,0,5,0,0,0,0,1,0);
    work=2.0*1000*800; unit="Mtri/s"; }
  else { fprintf(stderr,"unknown case %s\n",c); return 2; }
  double ms[64]; if(frames>64) frames=64;
  for(int f=-1; f<frames; f++){
    double t0=now();
    glClear(GL_COLOR_BUFFER_BIT|GL_DEPTH_BUFFER_BIT);
    if(!strcmp(c,"fill")||!strcmp(c,"fog")||!strcmp(c,"depth")) quads(!strcmp(c,"depth"));
    else if(!strcmp(c,"tris")||!strcmp(c,"tex")) glDrawArrays(GL_TRIANGLES,0,20000*3);
    else gluSphere(q,1.5,1000,800);
    glFinish();
    if(f>=0) ms[f]=(now()-t0)*1000;
  }
  qsort(ms,frames,sizeof ms[0],cmp);
  double med=ms[frames/2];
  if(work>0) printf("%s %.2f ms %.1f %s\n",c,med,work/(med*1e-3)/1e6,unit);
  else printf("%s %.2f ms\n",c,med);
  return glGetError()!=GL_NO_ERROR;
}
