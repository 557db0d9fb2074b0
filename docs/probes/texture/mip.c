#include "common.h"
static unsigned seed=12345; static unsigned rnd(void){seed=seed*1103515245u+12345u;return (seed>>16)&0x7fff;}
static void dump(GLenum tgt, GLenum gtgt, int levels, int comps, GLenum ty){
  for(int l=0;l<levels;l++){
    GLint w=0,h=0,d=0; glGetTexLevelParameteriv(gtgt,l,GL_TEXTURE_WIDTH,&w);glGetTexLevelParameteriv(gtgt,l,GL_TEXTURE_HEIGHT,&h);glGetTexLevelParameteriv(gtgt,l,GL_TEXTURE_DEPTH,&d);
    if(!w) break;
    int n=w*h*d*comps; int sz = ty==GL_UNSIGNED_BYTE?1:(ty==GL_UNSIGNED_SHORT?2:4);
    unsigned char*buf=calloc(n,sz);
    glPixelStorei(GL_PACK_ALIGNMENT,1);
    glGetTexImage(gtgt,l,comps==1&&ty==GL_FLOAT?GL_DEPTH_COMPONENT:(comps==1?GL_LUMINANCE:GL_RGBA),ty,buf);
    printf("L%d %dx%dx%d:",l,w,h,d);
    for(int i=0;i<n;i++){ if(sz==1)printf(" %u",buf[i]); else if(sz==2) printf(" %u",((unsigned short*)buf)[i]); else printf(" %.9g",((float*)buf)[i]);}
    printf("\n"); free(buf);
  }
}
static void run(const char*name, GLenum tgt, GLenum ifmt, int w,int h,int d, int viaparam){
  GLuint t; glGenTextures(1,&t); glBindTexture(tgt,t);
  int n=w*h*d*4; unsigned char*src=malloc(n); for(int i=0;i<n;i++) src[i]=rnd()&255;
  printf("CASE %s %dx%dx%d in:",name,w,h,d); for(int i=0;i<n;i++) printf(" %u",src[i]); printf("\n");
  glPixelStorei(GL_UNPACK_ALIGNMENT,1);
  if(viaparam) glTexParameteri(tgt,GL_GENERATE_MIPMAP,GL_TRUE);
  if(tgt==GL_TEXTURE_1D) glTexImage1D(tgt,0,ifmt,w,0,GL_RGBA,GL_UNSIGNED_BYTE,src);
  else if(tgt==GL_TEXTURE_3D) glTexImage3D(tgt,0,ifmt,w,h,d,0,GL_RGBA,GL_UNSIGNED_BYTE,src);
  else if(tgt==GL_TEXTURE_CUBE_MAP){ for(int f=0;f<6;f++) glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X+f,0,ifmt,w,h,0,GL_RGBA,GL_UNSIGNED_BYTE,src);}
  else glTexImage2D(tgt,0,ifmt,w,h,0,GL_RGBA,GL_UNSIGNED_BYTE,src);
  if(!viaparam) glGenerateMipmap(tgt); /* needs GL_GLEXT_PROTOTYPES */
  printf("err=%x\n",glGetError());
  GLenum ty = (ifmt==GL_RGBA16||ifmt==GL_RGB10_A2)?GL_UNSIGNED_SHORT:GL_UNSIGNED_BYTE;
  int comps = (ifmt==GL_LUMINANCE8)?1:4;
  dump(tgt, tgt==GL_TEXTURE_CUBE_MAP?GL_TEXTURE_CUBE_MAP_NEGATIVE_Y:tgt, 20, comps, ty);
  free(src);
}
int main(){
  init();
  run("rgba8_8x8",GL_TEXTURE_2D,GL_RGBA8,8,8,1,0);
  run("rgba8_5x3",GL_TEXTURE_2D,GL_RGBA8,5,3,1,0);
  run("rgba8_7x1",GL_TEXTURE_2D,GL_RGBA8,7,1,1,0);
  run("rgba8_3x7",GL_TEXTURE_2D,GL_RGBA8,3,7,1,0);
  run("l8_6x6",GL_TEXTURE_2D,GL_LUMINANCE8,6,6,1,0);
  run("rgba4_4x4",GL_TEXTURE_2D,GL_RGBA4,4,4,1,0);
  run("srgba8_4x4",GL_TEXTURE_2D,GL_SRGB8_ALPHA8,4,4,1,0);
  run("rgba16_4x4",GL_TEXTURE_2D,GL_RGBA16,4,4,1,0);
  run("rgb10a2_4x2",GL_TEXTURE_2D,GL_RGB10_A2,4,2,1,0);
  run("d1_rgba8_5",GL_TEXTURE_1D,GL_RGBA8,5,1,1,0);
  run("d3_rgba8_4x4x2",GL_TEXTURE_3D,GL_RGBA8,4,4,2,0);
  run("d3_rgba8_3x3x3",GL_TEXTURE_3D,GL_RGBA8,3,3,3,0);
  run("cube_rgba8_4",GL_TEXTURE_CUBE_MAP,GL_RGBA8,4,4,1,0);
  run("param_rgba8_4x4",GL_TEXTURE_2D,GL_RGBA8,4,4,1,1);
  run("rgb5_4x4",GL_TEXTURE_2D,GL_RGB5,4,4,1,0);

  run("rgba4_16",GL_TEXTURE_2D,GL_RGBA4,16,16,1,0);
  run("rgb5_16",GL_TEXTURE_2D,GL_RGB5,16,16,1,0);
  run("rgb5a1_16",GL_TEXTURE_2D,GL_RGB5_A1,16,16,1,0);
  run("r3g3b2_16",GL_TEXTURE_2D,GL_R3_G3_B2,16,16,1,0);
  run("rgb4_16",GL_TEXTURE_2D,GL_RGB4,16,16,1,0);
  run("l4a4_16",GL_TEXTURE_2D,GL_LUMINANCE4_ALPHA4,16,16,1,0);
  run("srgba8_16",GL_TEXTURE_2D,GL_SRGB8_ALPHA8,16,16,1,0);
  run("srgb8_16",GL_TEXTURE_2D,GL_SRGB8,16,16,1,0);
  run("rgba16_16",GL_TEXTURE_2D,GL_RGBA16,16,16,1,0);
  run("rgb10a2_16",GL_TEXTURE_2D,GL_RGB10_A2,16,16,1,0);
  run("d3_rgba8_4x4x2",GL_TEXTURE_3D,GL_RGBA8,4,4,2,0);
  run("d3_rgba8_3x3x3",GL_TEXTURE_3D,GL_RGBA8,3,3,3,0);
  run("d3_rgba8_5x4x6",GL_TEXTURE_3D,GL_RGBA8,5,4,6,0);
  run("rgba8_13x11",GL_TEXTURE_2D,GL_RGBA8,13,11,1,0);
  run("rgba8_100x3",GL_TEXTURE_2D,GL_RGBA8,100,3,1,0);
  return 0;
}
