#include "common.h"
static unsigned seed=777; static unsigned rnd(void){seed=seed*1103515245u+12345u;return (seed>>16)&0x7fff;}
GLenum ifmts[]={GL_RGBA8,GL_RGB8,GL_LUMINANCE8,GL_LUMINANCE8_ALPHA8,GL_ALPHA8,GL_INTENSITY8,GL_RGBA4,GL_RGB5_A1,GL_RGB10_A2,GL_RGBA16,GL_LUMINANCE16,GL_R3_G3_B2,GL_SRGB8_ALPHA8,GL_RGB5,GL_LUMINANCE4_ALPHA4};
GLenum fmts[]={GL_RGBA,GL_RGB,GL_BGRA,GL_BGR,GL_LUMINANCE,GL_LUMINANCE_ALPHA,GL_ALPHA,GL_RED,GL_GREEN,GL_BLUE};
GLenum types[]={GL_UNSIGNED_BYTE,GL_BYTE,GL_UNSIGNED_SHORT,GL_SHORT,GL_UNSIGNED_INT,GL_INT,GL_FLOAT,GL_UNSIGNED_BYTE_3_3_2,GL_UNSIGNED_BYTE_2_3_3_REV,GL_UNSIGNED_SHORT_5_6_5,GL_UNSIGNED_SHORT_5_6_5_REV,GL_UNSIGNED_SHORT_4_4_4_4,GL_UNSIGNED_SHORT_4_4_4_4_REV,GL_UNSIGNED_SHORT_5_5_5_1,GL_UNSIGNED_SHORT_1_5_5_5_REV,GL_UNSIGNED_INT_8_8_8_8,GL_UNSIGNED_INT_8_8_8_8_REV,GL_UNSIGNED_INT_10_10_10_2,GL_UNSIGNED_INT_2_10_10_10_REV};
int main(){
  init();
  unsigned char buf[4096];
  GLuint t; glGenTextures(1,&t); glBindTexture(GL_TEXTURE_2D,t);
  for(int cfg=0;cfg<3;cfg++)
  for(unsigned ti=0;ti<sizeof types/4;ti++)
  for(unsigned fi=0;fi<sizeof fmts/4;fi++)
  for(unsigned ii=0;ii<sizeof ifmts/4;ii++){
    GLenum ty=types[ti];
    for(int i=0;i<4096;i++) buf[i]=rnd()&255;
    if(ty==GL_FLOAT){ float*f=(float*)buf; for(int i=0;i<1024;i++) f[i]=((int)(rnd()%1500)-250)/1000.0f; }
    if(cfg==2){glPixelStorei(GL_UNPACK_SWAP_BYTES,1);glPixelStorei(GL_UNPACK_ROW_LENGTH,0);glPixelStorei(GL_UNPACK_SKIP_PIXELS,0);glPixelStorei(GL_UNPACK_SKIP_ROWS,0);glPixelStorei(GL_UNPACK_ALIGNMENT,4);}
    else if(cfg==1){glPixelStorei(GL_UNPACK_SWAP_BYTES,0);glPixelStorei(GL_UNPACK_ROW_LENGTH,5);glPixelStorei(GL_UNPACK_SKIP_PIXELS,1);glPixelStorei(GL_UNPACK_SKIP_ROWS,1);glPixelStorei(GL_UNPACK_ALIGNMENT,8);}
    else {glPixelStorei(GL_UNPACK_SWAP_BYTES,0);glPixelStorei(GL_UNPACK_ROW_LENGTH,0);glPixelStorei(GL_UNPACK_SKIP_PIXELS,0);glPixelStorei(GL_UNPACK_SKIP_ROWS,0);glPixelStorei(GL_UNPACK_ALIGNMENT,4);}
    glGetError();
    glTexImage2D(GL_TEXTURE_2D,0,ifmts[ii],3,2,0,fmts[fi],ty,buf);
    GLenum e=glGetError();
    printf("UP %d %x %x %x err=%x",cfg,ifmts[ii],fmts[fi],ty,e);
    if(!e){ unsigned short out[24]; glPixelStorei(GL_PACK_ALIGNMENT,1); glGetTexImage(GL_TEXTURE_2D,0,GL_RGBA,GL_UNSIGNED_SHORT,out);
      printf(" out:"); for(int i=0;i<24;i++) printf(" %u",out[i]); printf(" buf:"); for(int i=0;i<400;i++) printf(" %u",buf[i]); }
    printf("\n");
  }
  /* depth */
  GLenum dt[]={GL_UNSIGNED_BYTE,GL_BYTE,GL_UNSIGNED_SHORT,GL_SHORT,GL_UNSIGNED_INT,GL_INT,GL_FLOAT};
  GLenum di[]={GL_DEPTH_COMPONENT16,GL_DEPTH_COMPONENT24,GL_DEPTH_COMPONENT32};
  glPixelStorei(GL_UNPACK_SWAP_BYTES,0);glPixelStorei(GL_UNPACK_ROW_LENGTH,0);glPixelStorei(GL_UNPACK_SKIP_PIXELS,0);glPixelStorei(GL_UNPACK_SKIP_ROWS,0);glPixelStorei(GL_UNPACK_ALIGNMENT,4);
  for(unsigned a=0;a<7;a++) for(unsigned b=0;b<3;b++){
    for(int i=0;i<4096;i++) buf[i]=rnd()&255;
    if(dt[a]==GL_FLOAT){ float*f=(float*)buf; for(int i=0;i<1024;i++) f[i]=((int)(rnd()%1500)-250)/1000.0f; }
    glTexImage2D(GL_TEXTURE_2D,0,di[b],3,2,0,GL_DEPTH_COMPONENT,dt[a],buf);
    GLenum e=glGetError();
    printf("UP 0 %x %x %x err=%x",di[b],GL_DEPTH_COMPONENT,dt[a],e);
    if(!e){ unsigned out[6]; glPixelStorei(GL_PACK_ALIGNMENT,1); glGetTexImage(GL_TEXTURE_2D,0,GL_DEPTH_COMPONENT,GL_UNSIGNED_INT,out);
      printf(" out:"); for(int i=0;i<6;i++) printf(" %u",out[i]); printf(" buf:"); for(int i=0;i<400;i++) printf(" %u",buf[i]); }
    printf("\n");
  }
  return 0;
}
