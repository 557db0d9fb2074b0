/* Renders the reference scenes of tests/llvmpipe_goldens.rs with Mesa's
   OSMesa (llvmpipe) and writes every GL call to a trace file (floats as %.9g,
   which read back bit-identical), so softgl replays exactly the same calls.

   Regenerate (Debian 12: apt-get install libosmesa6-dev), from the repository root:
     gcc -O1 tests/llvmpipe/gen.c -o /tmp/llvmpipe-gen -lOSMesa -lm
     (cd tests/llvmpipe && mkdir -p raw && MESA_SHADER_CACHE_DISABLE=true /tmp/llvmpipe-gen)
     SOFTGL_BLESS_LLVMPIPE=1 cargo test --test llvmpipe_goldens
   The last step turns raw/ (colour, depth, stencil dumps) into the PNGs the test reads. */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stdint.h>
static int W=128,H=128; static unsigned char *buf; static OSMesaContext ctx; static FILE *T;
static uint32_t rs=2463534242u;
static float rnd(void){ rs^=rs<<13; rs^=rs>>17; rs^=rs<<5; return (float)rs/4294967295.0f; }
static float rr(float a,float b){ return a+(b-a)*rnd(); }
#define F "%.9g"
static const char* nm(GLenum e){ switch(e){
#define N(x) case x: return #x;
 N(GL_DEPTH_TEST)N(GL_BLEND)N(GL_COLOR_LOGIC_OP)N(GL_STENCIL_TEST)N(GL_POLYGON_OFFSET_FILL)N(GL_POLYGON_OFFSET_LINE)N(GL_POLYGON_OFFSET_POINT)N(GL_CULL_FACE)N(GL_SCISSOR_TEST)
 N(GL_NEVER)N(GL_LESS)N(GL_EQUAL)N(GL_LEQUAL)N(GL_GREATER)N(GL_NOTEQUAL)N(GL_GEQUAL)N(GL_ALWAYS)
 N(GL_ZERO)N(GL_ONE)N(GL_SRC_ALPHA)N(GL_ONE_MINUS_SRC_ALPHA)N(GL_XOR)N(GL_COPY)N(GL_KEEP)N(GL_INCR)N(GL_REPLACE)
 N(GL_FLAT)N(GL_SMOOTH)N(GL_FRONT_AND_BACK)N(GL_FRONT)N(GL_BACK)N(GL_LINE)N(GL_POINT)N(GL_FILL)N(GL_PROJECTION)N(GL_MODELVIEW)
 default: fprintf(stderr,"unknown enum %x\n",e); exit(1);} }
static const char* mn(GLenum e){ switch(e){
 N(GL_POINTS)N(GL_LINES)N(GL_LINE_STRIP)N(GL_LINE_LOOP)N(GL_TRIANGLES)N(GL_TRIANGLE_STRIP)N(GL_TRIANGLE_FAN)N(GL_QUADS)N(GL_QUAD_STRIP)N(GL_POLYGON)
 default: exit(1);} }
static void EN(GLenum c){ glEnable(c); fprintf(T,"EN %s\n",nm(c)); }
static void DIS(GLenum c){ glDisable(c); fprintf(T,"DIS %s\n",nm(c)); }
static void B(GLenum m){ glBegin(m); fprintf(T,"B %s\n",mn(m)); }
static void E(void){ glEnd(); fprintf(T,"E\n"); }
static void C4(float r,float g,float b,float a){ glColor4f(r,g,b,a); fprintf(T,"C "F" "F" "F" "F"\n",r,g,b,a); }
static void C3(float r,float g,float b){ C4(r,g,b,1.0f); }
static void V3(float x,float y,float z){ glVertex3f(x,y,z); fprintf(T,"V "F" "F" "F"\n",x,y,z); }
static void V2(float x,float y){ V3(x,y,0.0f); }
static void VP(int x,int y,int w,int h){ glViewport(x,y,w,h); fprintf(T,"VP %d %d %d %d\n",x,y,w,h); }
static void MM(GLenum m){ glMatrixMode(m); fprintf(T,"MM %s\n",nm(m)); }
static void LI(void){ glLoadIdentity(); fprintf(T,"LI\n"); }
static void ORTHO(double l,double r,double b,double t,double n,double f){ glOrtho(l,r,b,t,n,f); fprintf(T,"ORTHO %.17g %.17g %.17g %.17g %.17g %.17g\n",l,r,b,t,n,f); }
static void FRUST(double l,double r,double b,double t,double n,double f){ glFrustum(l,r,b,t,n,f); fprintf(T,"FRUST %.17g %.17g %.17g %.17g %.17g %.17g\n",l,r,b,t,n,f); }
static void CC(float r,float g,float b,float a){ glClearColor(r,g,b,a); fprintf(T,"CC "F" "F" "F" "F"\n",r,g,b,a); }
static void CLR(void){ glClear(GL_COLOR_BUFFER_BIT|GL_DEPTH_BUFFER_BIT|GL_STENCIL_BUFFER_BIT); fprintf(T,"CLR\n"); }
static void DF(GLenum f){ glDepthFunc(f); fprintf(T,"DF %s\n",nm(f)); }
static void DM(int b){ glDepthMask(b); fprintf(T,"DM %d\n",b); }
static void SM(GLenum m){ glShadeModel(m); fprintf(T,"SM %s\n",nm(m)); }
static void PS(float s){ glPointSize(s); fprintf(T,"PS "F"\n",s); }
static void LW(float s){ glLineWidth(s); fprintf(T,"LW "F"\n",s); }
static void BF(GLenum s,GLenum d){ glBlendFunc(s,d); fprintf(T,"BF %s %s\n",nm(s),nm(d)); }
static void LO(GLenum o){ glLogicOp(o); fprintf(T,"LO %s\n",nm(o)); }
static void SF(GLenum f,int ref,unsigned m){ glStencilFunc(f,ref,m); fprintf(T,"SF %s %d %u\n",nm(f),ref,m); }
static void SO(GLenum a,GLenum b,GLenum c){ glStencilOp(a,b,c); fprintf(T,"SO %s %s %s\n",nm(a),nm(b),nm(c)); }
static void PO(float f,float u){ glPolygonOffset(f,u); fprintf(T,"PO "F" "F"\n",f,u); }
static void PM(GLenum face,GLenum m){ glPolygonMode(face,m); fprintf(T,"PM %s %s\n",nm(face),nm(m)); }

static void init(int w,int h){ W=w;H=h; ctx=OSMesaCreateContextExt(OSMESA_RGBA,24,8,0,NULL); if(!ctx){printf("ctx fail\n");exit(1);}
 buf=calloc(W*H*4,1); if(!OSMesaMakeCurrent(ctx,buf,GL_UNSIGNED_BYTE,W,H)){printf("mc fail\n");exit(1);}
 fprintf(T,"INIT %d %d\n",W,H);
 VP(0,0,W,H); MM(GL_PROJECTION); LI(); ORTHO(0,W,0,H,-1,1); MM(GL_MODELVIEW); LI();
 CC(0,0,0,0); CLR(); }
static void rcol(void){ C3(rnd(),rnd(),rnd()); }

static void scene1(void){ EN(GL_DEPTH_TEST); DF(GL_LESS);
 B(GL_TRIANGLES);
 for(int i=0;i<600;i++){ float cx=rr(-4,132),cy=rr(-4,132);
  for(int k=0;k<3;k++){ rcol(); V3(cx+rr(-8,8),cy+rr(-8,8),rr(-1,1)); } }
 E(); }
static void scene2(void){ EN(GL_DEPTH_TEST); DF(GL_LESS);
 MM(GL_PROJECTION); LI(); FRUST(-1,1,-1,1,1,10); MM(GL_MODELVIEW); LI();
 B(GL_TRIANGLES);
 for(int i=0;i<500;i++){ float cz=-rr(0.3f,11.0f); float s=-cz; float cx=rr(-1.3f,1.3f)*s, cy=rr(-1.3f,1.3f)*s;
  for(int k=0;k<3;k++){ rcol(); V3(cx+rr(-0.25f,0.25f)*s,cy+rr(-0.25f,0.25f)*s,cz+rr(-1.5f,1.5f)); } }
 E(); }
static void scene3(void){ EN(GL_DEPTH_TEST); DF(GL_LESS);
 for(int i=0;i<40;i++){ B(GL_TRIANGLES);
  float sc = (i<20)?1e5f:3e3f;
  rcol(); V3(rr(0,128),rr(0,128),rr(-1,1));
  rcol(); V3(rr(-1,1)*sc,rr(-1,1)*sc,rr(-1,1));
  rcol(); V3(rr(-1,1)*sc,rr(-1,1)*sc,rr(-1,1)); E(); }
}
static void scene4a(void){ B(GL_LINES); for(int i=0;i<300;i++){ rcol(); V2(rr(-5,133),rr(-5,133)); rcol(); V2(rr(-5,133),rr(-5,133)); } E(); }
static void scene4b(void){ float ws[3]={2,3,5}; for(int i=0;i<100;i++){ LW(ws[i%3]); B(GL_LINES); rcol(); V2(rr(-5,133),rr(-5,133)); rcol(); V2(rr(-5,133),rr(-5,133)); E(); } }
static void scene5(void){ for(int i=0;i<300;i++){ PS(1.0f+5.0f*rnd()); B(GL_POINTS); rcol(); V2(rr(-3,131),rr(-3,131)); E(); } }
static void scene6(void){ SM(GL_FLAT); GLenum modes[10]={GL_POINTS,GL_LINES,GL_LINE_STRIP,GL_LINE_LOOP,GL_TRIANGLES,GL_TRIANGLE_STRIP,GL_TRIANGLE_FAN,GL_QUADS,GL_QUAD_STRIP,GL_POLYGON};
 PS(3.0f);
 for(int m=0;m<10;m++){ float x0=(m%5)*25.6f, y0=(m/5)*64.0f; B(modes[m]);
  switch(modes[m]){
   case GL_TRIANGLE_STRIP: case GL_QUAD_STRIP: for(int k=0;k<8;k++){ rcol(); V2(x0+2+(k&1?20:0)+rr(-2,2), y0+2+(k/2)*19+rr(-2,2)); } break;
   case GL_TRIANGLE_FAN: case GL_POLYGON: { float cx=x0+12.8f, cy=y0+32; rcol(); V2(cx,cy); for(int k=0;k<7;k++){ float a=k*0.85f; rcol(); V2(cx+11*__builtin_cosf(a)+rr(-1,1), cy+28*__builtin_sinf(a)+rr(-1,1)); } } break;
   case GL_QUADS: for(int q=0;q<2;q++){ float yb=y0+2+q*31; rcol(); V2(x0+2+rr(0,3),yb+rr(0,3)); rcol(); V2(x0+23-rr(0,3),yb+rr(0,3)); rcol(); V2(x0+23-rr(0,3),yb+29-rr(0,3)); rcol(); V2(x0+2+rr(0,3),yb+29-rr(0,3)); } break;
   default: for(int k=0;k<12;k++){ rcol(); V2(x0+rr(1,24.6f), y0+rr(1,63)); }
  }
  E(); } }
static void gradient(void){ B(GL_QUADS); C3(0,0,0); V2(0,0); C3(1,0,0); V2(128,0); C3(1,1,0); V2(128,128); C3(0,0,1); V2(0,128); E(); }
static void scene7a(void){ gradient(); EN(GL_BLEND); BF(GL_SRC_ALPHA,GL_ONE_MINUS_SRC_ALPHA);
 B(GL_TRIANGLES); for(int i=0;i<300;i++){ float cx=rr(-4,132),cy=rr(-4,132); for(int k=0;k<3;k++){ C4(rnd(),rnd(),rnd(),rnd()); V2(cx+rr(-20,20),cy+rr(-20,20)); } } E(); }
static void scene7b(void){ EN(GL_BLEND); BF(GL_ONE,GL_ONE);
 B(GL_TRIANGLES); for(int i=0;i<300;i++){ float cx=rr(-4,132),cy=rr(-4,132); for(int k=0;k<3;k++){ C4(rr(0,0.2f),rr(0,0.2f),rr(0,0.2f),rr(0,0.2f)); V2(cx+rr(-20,20),cy+rr(-20,20)); } } E(); }
static void scene7c(void){ gradient(); EN(GL_COLOR_LOGIC_OP); LO(GL_XOR);
 B(GL_TRIANGLES); for(int i=0;i<200;i++){ float cx=rr(-4,132),cy=rr(-4,132); for(int k=0;k<3;k++){ C4(rnd(),rnd(),rnd(),rnd()); V2(cx+rr(-20,20),cy+rr(-20,20)); } } E(); }
static void scene7d(void){ EN(GL_STENCIL_TEST); SF(GL_ALWAYS,0,255); SO(GL_KEEP,GL_KEEP,GL_INCR);
 B(GL_TRIANGLES); for(int i=0;i<300;i++){ float cx=rr(-4,132),cy=rr(-4,132); for(int k=0;k<3;k++){ rcol(); V2(cx+rr(-20,20),cy+rr(-20,20)); } } E(); }
/* polygon offset: cells of 32x32; quad A then coplanar quad B with offset */
static void quad(float x0,float y0,float s,float z00,float dzx,float dzy){
 B(GL_QUADS); V3(x0,y0,z00); V3(x0+s,y0,z00+dzx*s); V3(x0+s,y0+s,z00+dzx*s+dzy*s); V3(x0,y0+s,z00+dzy*s); E(); }
static void scene8(void){ EN(GL_DEPTH_TEST); DF(GL_LESS);
 float offs[4][2]={{1,1},{-1,-1},{0,0},{0,-1}};
 float slopes[4][2]={{0,0},{0.01f,0.004f},{-0.03f,0.02f},{0.001f,-0.0005f}};
 for(int o=0;o<4;o++) for(int s=0;s<4;s++){ float x0=2+o*32, y0=2+s*32;
  DIS(GL_POLYGON_OFFSET_FILL); C3(1,0,0); quad(x0,y0,28.3f,0.1f+0.1f*s,slopes[s][0],slopes[s][1]);
  EN(GL_POLYGON_OFFSET_FILL); PO(offs[o][0],offs[o][1]); C3(0,1,0); quad(x0,y0,28.3f,0.1f+0.1f*s,slopes[s][0],slopes[s][1]);
 } }
/* offset depth values written directly (DF ALWAYS), ortho and perspective */
static void scene8b(void){ EN(GL_DEPTH_TEST); DF(GL_ALWAYS);
 float offs[4][2]={{1,1},{-1,-1},{2.5f,0},{0,3}};
 float slopes[4][2]={{0,0},{0.01f,0.004f},{-0.03f,0.02f},{0.001f,-0.0005f}};
 EN(GL_POLYGON_OFFSET_FILL);
 for(int o=0;o<4;o++) for(int s=0;s<2;s++){ float x0=2+o*32, y0=2+s*32;
  PO(offs[o][0],offs[o][1]); C3(0,1,0); quad(x0,y0,28.3f,0.1f+0.2f*s,slopes[s*2+1][0],slopes[s*2+1][1]); }
 MM(GL_PROJECTION); LI(); FRUST(-1,1,-1,1,1,10); MM(GL_MODELVIEW); LI();
 for(int o=0;o<4;o++){ PO(offs[o][0],offs[o][1]); C3(0,0,1); float x=-1+o*0.5f;
  B(GL_QUADS); V3(x*3,-3,-2.5f); V3(x*3+1.4f,-3,-3.5f); V3(x*3+1.4f,-0.1f,-5.0f); V3(x*3,-0.1f,-4.f); E(); }
}
static void scene9(void){ SM(GL_SMOOTH); PM(GL_FRONT_AND_BACK,GL_LINE);
 for(int i=0;i<4;i++){ float x0=4+i*31, y0=70; B(GL_TRIANGLES); rcol(); V2(x0+rr(0,3),y0+rr(0,3)); rcol(); V2(x0+27-rr(0,3),y0+rr(0,5)); rcol(); V2(x0+rr(5,20),y0+50-rr(0,4)); E(); }
 for(int i=0;i<2;i++){ float x0=4+i*31, y0=36; B(GL_QUADS); rcol(); V2(x0+rr(0,3),y0+rr(0,3)); rcol(); V2(x0+27-rr(0,3),y0+rr(0,3)); rcol(); V2(x0+27-rr(0,3),y0+30-rr(0,3)); rcol(); V2(x0+rr(0,3),y0+30-rr(0,3)); E(); }
 { B(GL_QUAD_STRIP); for(int k=0;k<6;k++){ rcol(); V2(66+(k&1)*26+rr(-1,1), 36+(k/2)*14+rr(-1,1)); } E(); }
 { B(GL_POLYGON); float cx=112,cy=50; for(int k=0;k<6;k++){ float a=k*1.0472f; rcol(); V2(cx+13*__builtin_cosf(a),cy+13*__builtin_sinf(a)); } E(); }
 PM(GL_FRONT_AND_BACK,GL_POINT); PS(1.0f);
 for(int i=0;i<4;i++){ float x0=4+i*31, y0=2; B(GL_TRIANGLES); rcol(); V2(x0+rr(0,3),y0+rr(0,3)); rcol(); V2(x0+27-rr(0,3),y0+rr(0,5)); rcol(); V2(x0+rr(5,20),y0+30-rr(0,4)); E(); }
 PS(3.0f);
 { B(GL_QUADS); for(int q=0;q<2;q++){ float x0=4+q*31,y0=110; rcol(); V2(x0,y0); rcol(); V2(x0+20.3f,y0+0.5f); rcol(); V2(x0+20,y0+15.7f); rcol(); V2(x0+0.2f,y0+15); } E(); }
 PM(GL_FRONT_AND_BACK,GL_FILL); }
static void scene10(void){ VP(20,30,60,50); MM(GL_PROJECTION); LI(); ORTHO(0,60,0,50,-1,1); MM(GL_MODELVIEW); LI();
 EN(GL_DEPTH_TEST); DF(GL_LESS);
 B(GL_TRIANGLES); for(int i=0;i<60;i++){ float cx=rr(-10,70),cy=rr(-10,60); for(int k=0;k<3;k++){ rcol(); V3(cx+rr(-15,15),cy+rr(-15,15),rr(-1.5f,1.5f)); } } E();
 DIS(GL_DEPTH_TEST);
 B(GL_LINES); for(int i=0;i<30;i++){ rcol(); V2(rr(-20,80),rr(-20,70)); rcol(); V2(rr(-20,80),rr(-20,70)); } E();
 LW(4.0f); B(GL_LINES); for(int i=0;i<10;i++){ rcol(); V2(rr(-20,80),rr(-20,70)); rcol(); V2(rr(-20,80),rr(-20,70)); } E();
 for(int i=0;i<40;i++){ PS(1.0f+8.0f*rnd()); B(GL_POINTS); rcol(); float x=(i&1)? rr(-4,4): rr(56,64); float y=rr(-4,54); if(i%4>=2){ float t=x; x=rr(-4,64); y=(i&1)? t: rr(46,54);} V2(x,y); E(); }
}
static void (*scenes[])(void)={0,scene1,scene2,scene3,scene4a,scene4b,scene5,scene6,scene7a,scene7b,scene7c,scene7d,scene8,scene8b,scene9,scene10};
static const char* names[]={"","1","2","3","4a","4b","5","6","7a","7b","7c","7d","8","8b","9","10"};
int main(int argc,char**argv){
 int n=sizeof(scenes)/sizeof(scenes[0]);
 for(int s=1;s<n;s++){ if(argc>1 && strcmp(argv[1],names[s])) continue;
  char p[256]; sprintf(p,"s%s.trace",names[s]); T=fopen(p,"w"); rs=2463534242u+s;
  init(128,128); scenes[s](); glFinish(); fprintf(T,"END\n"); fclose(T);
  sprintf(p,"raw/s%s.rgba",names[s]); FILE*f=fopen(p,"wb"); fwrite(buf,1,W*H*4,f); fclose(f);
  GLint dw,dh,bpv; void*db; OSMesaGetDepthBuffer(ctx,&dw,&dh,&bpv,&db);
  uint32_t *d=malloc(W*H*4); for(int i=0;i<W*H;i++){ d[i]= bpv==4? ((uint32_t*)db)[i]&0xffffff : ((uint16_t*)db)[i]; }
  sprintf(p,"raw/s%s.depth",names[s]); f=fopen(p,"wb"); fwrite(d,4,W*H,f); fclose(f); free(d);
  unsigned char *st=malloc(W*H); glPixelStorei(GL_PACK_ALIGNMENT,1); glReadPixels(0,0,W,H,GL_STENCIL_INDEX,GL_UNSIGNED_BYTE,st);
  sprintf(p,"raw/s%s.stencil",names[s]); f=fopen(p,"wb"); fwrite(st,1,W*H,f); fclose(f); free(st);
  OSMesaDestroyContext(ctx); free(buf);
 }
 return 0; }
