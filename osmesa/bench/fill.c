/* Frames at 1024x1024 (RGBA8, 24-bit depth, 8-bit stencil) through the OSMesa
 * C ABI, for Mesa and softgl in one run (not a test; osmesa/bench/compare.sh
 * runs it):
 *   cc -O2 osmesa/bench/fill.c -o /tmp/fill -lOSMesa -lGLU -lm
 *   LP_NUM_THREADS=1 /tmp/fill CASE [FRAMES] [-o FILE]               # Mesa llvmpipe
 *   LD_LIBRARY_PATH=$PWD/target/release/osmesa /tmp/fill CASE ...    # softgl
 * CASE:
 *   fill     16 full-screen smooth-shaded quads, no depth (Mfrag/s);
 *   quads200 200 of them (Mfrag/s);
 *   depth    16 full-screen quads, depth test LESS, nearer each time so every
 *            fragment passes (Mfrag/s);
 *   fog      fill with EXP fog and GL_COLOR_SUM on (Mfrag/s);
 *   tris     20k random triangles of ~2000 px, depth test;
 *   ops      tris with scissor (4 px inside the window), alpha test GREATER 0.1
 *            (RGBA colours), stencil ALWAYS/1 with INCR on depth pass and
 *            fail, depth LESS, blend SRC_ALPHA/ONE_MINUS_SRC_ALPHA, colour mask
 *            RGB (alpha kept);
 *   xor      ops with GL_COLOR_LOGIC_OP XOR in place of the blend;
 *   thrash   256 distinct per-fragment states (depth func x stencil op x
 *            colour mask with alpha test x blend factors / logic op) x 50
 *            triangles of ~12 px; prints `thrash-first` (the first frame of the
 *            process: every state compiled cold) before `thrash` (the median
 *            of the frames after it);
 *   tex      the tris frame textured: a 256x256 RGBA8 texture with its
 *            box-filtered mipmaps uploaded level by level,
 *            GL_LINEAR_MIPMAP_LINEAR, REPEAT, MODULATE over the random
 *            colours, texture coordinates 3x the position so lambda is about
 *            0.6 and both levels are read, EXP fog;
 *   lit      a GLU sphere asked for with 1000x800 slices/stacks, one infinite
 *            light, depth test, immediate mode (Mtri/s). GLU clamps both to
 *            239 (CACHE_SIZE 240 in its quad.c; the image is byte-identical
 *            to gluSphere(q,1.5,239,239)), so a frame is 239 quad strips of
 *            239 quads: 114,242 triangles (478 of them degenerate, at the
 *            poles), not the 1.6 M the numbers suggest;
 *   litlist  the same sphere compiled once into a display list (outside the
 *            timed frames) and called each frame (Mtri/s);
 *   lit16    the lit frame at the size the issue means: a sphere of 1000
 *            slices x 800 stacks made here as GLU makes its (quad strips from
 *            the +z pole, normals per vertex), 1,600,000 triangles (Mtri/s);
 *   lit16list the same compiled once into a display list and called each frame;
 *   clear    glClear(GL_COLOR_BUFFER_BIT) + glFinish; a sample is 20 of them,
 *            the figure the time of one;
 *   clearall the same with colour, depth and stencil;
 *   create   OSMesaCreateContextExt + OSMesaMakeCurrent (1024x1024) + glFinish
 *            + OSMesaDestroyContext, a sample each.
 * FRAMES (default 9) are timed after one untimed first frame. Prints one line
 * per figure: the case, the median ms, and fragments (or triangles) per second
 * where the work is known. `-o FILE` writes the last frame: a binary PPM (RGB)
 * if FILE ends in .ppm, else a PAM (RGBA); rows bottom-up, as GL has them.
 * Exits non-zero on a GL error.
 * Without Mesa's headers (libosmesa6-dev) the four OSMesa entry points are
 * declared here; with -DNO_GLU (no libglu1-mesa-dev) the camera and sphere are
 * made here (GLU's triangles; on llvmpipe the lit image differs from GLU's in
 * 21 bytes by rounding). */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#if __has_include(<GL/osmesa.h>)
#include <GL/osmesa.h>
#else
typedef struct osmesa_context *OSMesaContext;
#define OSMESA_RGBA GL_RGBA
OSMesaContext OSMesaCreateContextExt(GLenum format, GLint depth, GLint stencil, GLint accum, OSMesaContext share);
GLboolean OSMesaMakeCurrent(OSMesaContext ctx, void *buffer, GLenum type, GLsizei width, GLsizei height);
void OSMesaDestroyContext(OSMesaContext ctx);
#endif
#include <math.h>
#include <stdlib.h>
/* A sphere of `slices` x `stacks` quad strips from the +z pole, as GLU's
 * gluSphere makes it (without its clamp to 239). */
static void strip_sphere(double r, int slices, int stacks){
  float *sn=malloc(sizeof(float)*2*(slices+stacks+2)), *cs=sn+slices+1, *sp=cs+slices+1, *cp=sp+stacks+1;
  for(int i=0;i<=slices;i++){ double t=2*3.14159265358979*(i%slices)/slices; sn[i]=(float)sin(t); cs[i]=(float)cos(t); }
  for(int j=0;j<=stacks;j++){ double p=3.14159265358979*j/stacks; sp[j]=(float)sin(p); cp[j]=(float)cos(p); }
  float rf=(float)r;
  for(int j=0;j<stacks;j++){
    glBegin(GL_QUAD_STRIP);
    for(int i=0;i<=slices;i++)
      for(int k=j+1;k>=j;k--){ float x=sn[i]*sp[k], y=cs[i]*sp[k], z=cp[k]; glNormal3f(x,y,z); glVertex3f(rf*x,rf*y,rf*z); }
    glEnd();
  }
  free(sn);
}
#ifndef NO_GLU
#include <GL/glu.h>
#else
typedef int GLUquadric;
static GLUquadric *gluNewQuadric(void){ static GLUquadric q; return &q; }
static void gluPerspective(double fovy, double aspect, double n, double f){
  double y=n*tan(fovy*3.14159265358979/360); glFrustum(-y*aspect,y*aspect,-y,y,n,f); }
/* Only the camera used here: at (0,0,z) looking at the origin, y up. */
static void gluLookAt(double ex,double ey,double ez,double cx,double cy,double cz,double ux,double uy,double uz){
  (void)ex;(void)ey;(void)cx;(void)cy;(void)cz;(void)ux;(void)uy;(void)uz; glTranslated(0,0,-ez); }
/* As GLU's: slices and stacks clamped to 239, quad strips from the +z pole. */
static void gluSphere(GLUquadric *q, double r, int slices, int stacks){
  (void)q; strip_sphere(r, slices>239?239:slices, stacks>239?239:stacks);
}
#endif
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
static double now(void){struct timespec t;clock_gettime(CLOCK_MONOTONIC,&t);return t.tv_sec+t.tv_nsec*1e-9;}
static int cmp(const void*a,const void*b){double x=*(const double*)a,y=*(const double*)b;return x<y?-1:x>y;}
static float rnd(void){return rand()/(float)RAND_MAX;}
#define W 1024
#define H 1024
#define STATES 256
#define PER_STATE 50
static float tri[20000*9], col[20000*9], tc[20000*6], col4[20000*12];
static float ttri[STATES*PER_STATE*9], tcol[STATES*PER_STATE*12];
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
static void quads(int n,int depth){
  for(int k=0;k<n;k++){
    float z = depth ? 0.9f - k*0.1f : 0.0f;
    glBegin(GL_QUADS);
    glColor3f(1,0,0); glVertex3f(-1,-1,z);
    glColor3f(0,1,0); glVertex3f( 1,-1,z);
    glColor3f(0,0,1); glVertex3f( 1, 1,z);
    glColor3f(1,1,(k&1)?1.f:0.f); glVertex3f(-1, 1,z);
    glEnd();
  }
}
/* State i of the thrash frame's 256, each a distinct per-fragment state: the
 * depth function (i%8), the stencil op on depth pass and fail (i/8%4, test
 * ALWAYS), colour mask RGBA without or RGB with an alpha test (i/32%2), and
 * blend SRC_ALPHA/ONE_MINUS_SRC_ALPHA, blend ONE/ONE, logic op XOR or logic
 * op OR (i/64), which also picks the alpha function. */
static void thrash_state(int i){
  static const GLenum depth[8]={GL_NEVER,GL_LESS,GL_EQUAL,GL_LEQUAL,GL_GREATER,GL_NOTEQUAL,GL_GEQUAL,GL_ALWAYS};
  static const GLenum sop[4]={GL_KEEP,GL_INCR,GL_DECR,GL_INVERT};
  static const GLenum afunc[4]={GL_GREATER,GL_LESS,GL_GEQUAL,GL_NOTEQUAL};
  static const float aref[4]={0.25f,0.75f,0.5f,0.0f};
  int g=i/64;
  glDepthFunc(depth[i%8]);
  glStencilOp(GL_KEEP,sop[(i/8)%4],sop[(i/8)%4]);
  if((i/32)&1){ glColorMask(1,1,1,0); glEnable(GL_ALPHA_TEST); glAlphaFunc(afunc[g],aref[g]); }
  else { glColorMask(1,1,1,1); glDisable(GL_ALPHA_TEST); }
  if(g<2){ glDisable(GL_COLOR_LOGIC_OP); glEnable(GL_BLEND);
    if(g==0) glBlendFunc(GL_SRC_ALPHA,GL_ONE_MINUS_SRC_ALPHA); else glBlendFunc(GL_ONE,GL_ONE); }
  else { glDisable(GL_BLEND); glEnable(GL_COLOR_LOGIC_OP); glLogicOp(g==2?GL_XOR:GL_OR); }
}
/* The 20k triangles with RGBA colours under scissor, alpha, stencil, depth and
 * colour mask; blend or XOR. */
static void ops(int xor){
  glEnable(GL_SCISSOR_TEST); glScissor(4,4,W-8,H-8);
  glEnable(GL_ALPHA_TEST); glAlphaFunc(GL_GREATER,0.1f);
  glEnable(GL_STENCIL_TEST); glStencilFunc(GL_ALWAYS,1,0xff); glStencilOp(GL_KEEP,GL_INCR,GL_INCR);
  glEnable(GL_DEPTH_TEST);
  if(xor){ glEnable(GL_COLOR_LOGIC_OP); glLogicOp(GL_XOR); }
  else { glEnable(GL_BLEND); glBlendFunc(GL_SRC_ALPHA,GL_ONE_MINUS_SRC_ALPHA); }
  glColorMask(1,1,1,0);
  glVertexPointer(3,GL_FLOAT,0,tri); glColorPointer(4,GL_FLOAT,0,col4);
  glEnableClientState(GL_VERTEX_ARRAY); glEnableClientState(GL_COLOR_ARRAY);
}
static int dump(const char*path,const unsigned char*buf){
  FILE*f=fopen(path,"wb"); if(!f){perror(path);return 1;}
  size_t n=strlen(path); int ppm=n>=4&&!strcmp(path+n-4,".ppm");
  if(ppm){ fprintf(f,"P6\n%d %d\n255\n",W,H); for(size_t i=0;i<(size_t)W*H;i++) fwrite(buf+i*4,1,3,f); }
  else { fprintf(f,"P7\nWIDTH %d\nHEIGHT %d\nDEPTH 4\nMAXVAL 255\nTUPLTYPE RGB_ALPHA\nENDHDR\n",W,H); fwrite(buf,4,(size_t)W*H,f); }
  return fclose(f)!=0;
}
static double median(double*ms,int n){ qsort(ms,n,sizeof ms[0],cmp); return ms[n/2]; }
int main(int argc,char**argv){
  const char*c="fill", *out=NULL; int frames=9, pos=0;
  for(int i=1;i<argc;i++){
    if(!strcmp(argv[i],"-o")&&i+1<argc) out=argv[++i];
    else if(pos++==0) c=argv[i];
    else frames=atoi(argv[i]);
  }
  if(frames<1) frames=1;
  if(frames>64) frames=64;
  /* FILL_TYPE=ushort or float: the window buffer is GL_UNSIGNED_SHORT or
   * GL_FLOAT (the deep colour formats; -o is then not written). */
  const char*ft=getenv("FILL_TYPE");
  GLenum type=ft&&!strcmp(ft,"float")?GL_FLOAT:ft&&!strcmp(ft,"ushort")?GL_UNSIGNED_SHORT:GL_UNSIGNED_BYTE;
  size_t bpp=type==GL_FLOAT?16:type==GL_UNSIGNED_SHORT?8:4;
  unsigned char*buf=calloc((size_t)W*H,bpp), *buf2=calloc((size_t)W*H,4);
  OSMesaContext ctx=OSMesaCreateContextExt(OSMESA_RGBA,24,8,0,NULL);
  if(!ctx||!OSMesaMakeCurrent(ctx,buf,type,W,H)){fprintf(stderr,"no context\n");return 1;}
  GLUquadric*q=gluNewQuadric();
  srand(1);
  for(int t=0;t<20000;t++){float cx=rnd()*1.8f-0.9f, cy=rnd()*1.8f-0.9f; for(int v=0;v<3;v++){tri[t*9+v*3]=cx+rnd()*0.2f-0.1f; tri[t*9+v*3+1]=cy+rnd()*0.2f-0.1f; tri[t*9+v*3+2]=rnd()*2-1;}}
  for(int i=0;i<20000*9;i++) col[i]=rnd();
  for(int v=0;v<20000*3;v++){ tc[v*2]=tri[v*3]*3; tc[v*2+1]=tri[v*3+1]*3; }
  /* Drawn after the arrays above so that those stay as they were. */
  for(int v=0;v<20000*3;v++){ for(int k=0;k<3;k++) col4[v*4+k]=col[v*3+k]; col4[v*4+3]=rnd(); }
  for(int t=0;t<STATES*PER_STATE;t++){float cx=rnd()*1.9f-0.95f, cy=rnd()*1.9f-0.95f; for(int v=0;v<3;v++){ttri[t*9+v*3]=cx+rnd()*0.025f-0.0125f; ttri[t*9+v*3+1]=cy+rnd()*0.025f-0.0125f; ttri[t*9+v*3+2]=rnd()*2-1;}}
  for(int i=0;i<STATES*PER_STATE*12;i++) tcol[i]=rnd();
  double work=0; const char*unit="Mfrag/s";
  GLbitfield clear=GL_COLOR_BUFFER_BIT|GL_DEPTH_BUFFER_BIT;
  int sphere=0;
  if(!strcmp(c,"fill")){ work=16.0*W*H; }
  else if(!strcmp(c,"quads200")){ work=200.0*W*H; }
  else if(!strcmp(c,"fog")){ glEnable(GL_FOG); glFogi(GL_FOG_MODE,GL_EXP); glFogf(GL_FOG_DENSITY,0.7f);
    glEnable(GL_COLOR_SUM); glSecondaryColor3f(0.1f,0.2f,0.3f); work=16.0*W*H; }
  else if(!strcmp(c,"depth")){ glEnable(GL_DEPTH_TEST); work=16.0*W*H; }
  else if(!strcmp(c,"tris")){ glEnable(GL_DEPTH_TEST);
    glVertexPointer(3,GL_FLOAT,0,tri); glColorPointer(3,GL_FLOAT,0,col);
    glEnableClientState(GL_VERTEX_ARRAY); glEnableClientState(GL_COLOR_ARRAY); }
  else if(!strcmp(c,"ops")||!strcmp(c,"xor")){ ops(!strcmp(c,"xor")); clear|=GL_STENCIL_BUFFER_BIT; }
  else if(!strcmp(c,"thrash")){ glEnable(GL_DEPTH_TEST); glEnable(GL_STENCIL_TEST); glStencilFunc(GL_ALWAYS,1,0xff);
    glVertexPointer(3,GL_FLOAT,0,ttri); glColorPointer(4,GL_FLOAT,0,tcol);
    glEnableClientState(GL_VERTEX_ARRAY); glEnableClientState(GL_COLOR_ARRAY); clear|=GL_STENCIL_BUFFER_BIT; }
  else if(!strcmp(c,"tex")){ glEnable(GL_DEPTH_TEST); texture();
    glEnable(GL_FOG); glFogi(GL_FOG_MODE,GL_EXP); glFogf(GL_FOG_DENSITY,0.7f);
    GLfloat fogc[4]={0.5f,0.6f,0.7f,1}; glFogfv(GL_FOG_COLOR,fogc);
    glVertexPointer(3,GL_FLOAT,0,tri); glColorPointer(3,GL_FLOAT,0,col); glTexCoordPointer(2,GL_FLOAT,0,tc);
    glEnableClientState(GL_VERTEX_ARRAY); glEnableClientState(GL_COLOR_ARRAY); glEnableClientState(GL_TEXTURE_COORD_ARRAY); }
  else if(!strncmp(c,"lit",3)){ glEnable(GL_DEPTH_TEST); glEnable(GL_LIGHTING); glEnable(GL_LIGHT0);
    GLfloat p[4]={1,1,2,0}; glLightfv(GL_LIGHT0,GL_POSITION,p);
    GLfloat red[4]={0.8f,0.2f,0.2f,1}; glMaterialfv(GL_FRONT_AND_BACK,GL_AMBIENT_AND_DIFFUSE,red);
    glMatrixMode(GL_PROJECTION); gluPerspective(40,1,1,20); glMatrixMode(GL_MODELVIEW); gluLookAt(0,0,5,0,0,0,0,1,0);
    int big=!strncmp(c,"lit16",5), list=strstr(c,"list")!=NULL;
    if(strcmp(c,"lit")&&strcmp(c,"litlist")&&strcmp(c,"lit16")&&strcmp(c,"lit16list")){ fprintf(stderr,"unknown case %s\n",c); return 2; }
    sphere=big?3:1; work=big?2.0*1000*800:2.0*239*239; unit="Mtri/s";
    if(list){ glNewList(1,GL_COMPILE); if(big) strip_sphere(1.5,1000,800); else gluSphere(q,1.5,1000,800); glEndList(); sphere=2; } }
  else if(!strcmp(c,"clear")){ clear=GL_COLOR_BUFFER_BIT; }
  else if(!strcmp(c,"clearall")){ clear=GL_COLOR_BUFFER_BIT|GL_DEPTH_BUFFER_BIT|GL_STENCIL_BUFFER_BIT; }
  else if(!strcmp(c,"create")){ }
  else { fprintf(stderr,"unknown case %s\n",c); return 2; }
  double ms[64], first=0;
  for(int f=-1; f<frames; f++){
    double t0=now();
    if(!strcmp(c,"create")){
      OSMesaContext o=OSMesaCreateContextExt(OSMESA_RGBA,24,8,0,NULL);
      if(!o||!OSMesaMakeCurrent(o,buf2,GL_UNSIGNED_BYTE,W,H)){fprintf(stderr,"no context\n");return 1;}
      glFinish(); OSMesaDestroyContext(o);
    } else if(!strcmp(c,"clear")||!strcmp(c,"clearall")){
      for(int k=0;k<20;k++){ glClear(clear); glFinish(); }
    } else {
      if(!strcmp(c,"thrash")){ glColorMask(1,1,1,1); glDisable(GL_ALPHA_TEST); }
      glClear(clear);
      if(!strcmp(c,"fill")||!strcmp(c,"fog")||!strcmp(c,"depth")) quads(16,!strcmp(c,"depth"));
      else if(!strcmp(c,"quads200")) quads(200,0);
      else if(!strcmp(c,"thrash")) for(int i=0;i<STATES;i++){ thrash_state(i); glDrawArrays(GL_TRIANGLES,i*PER_STATE*3,PER_STATE*3); }
      else if(sphere==1) gluSphere(q,1.5,1000,800);
      else if(sphere==3) strip_sphere(1.5,1000,800);
      else if(sphere==2) glCallList(1);
      else glDrawArrays(GL_TRIANGLES,0,20000*3);
      glFinish();
    }
    double t=(now()-t0)*1000;
    if(!strcmp(c,"clear")||!strcmp(c,"clearall")) t/=20;
    if(f>=0) ms[f]=t; else first=t;
    if(!strcmp(c,"create")&&!OSMesaMakeCurrent(ctx,buf,type,W,H)){fprintf(stderr,"no context\n");return 1;}
  }
  double med=median(ms,frames);
  if(!strcmp(c,"thrash")) printf("thrash-first %.2f ms\n",first);
  if(work>0) printf("%s %.2f ms %.1f %s\n",c,med,work/(med*1e-3)/1e6,unit);
  else printf("%s %.2f ms\n",c,med);
  if(out&&type==GL_UNSIGNED_BYTE&&dump(out,buf)) return 1;
  GLenum e=glGetError();
  if(e!=GL_NO_ERROR){ fprintf(stderr,"%s: GL error 0x%x\n",c,e); return 1; }
  return 0;
}
