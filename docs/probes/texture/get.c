#include "common.h"
static unsigned seed=4242; static unsigned rnd(void){seed=seed*1103515245u+12345u;return (seed>>16)&0x7fff;}
GLenum ifmts[]={GL_RGBA8,GL_RGB8,GL_LUMINANCE8,GL_LUMINANCE8_ALPHA8,GL_ALPHA8,GL_INTENSITY8,GL_RGBA4,GL_RGB5_A1,GL_RGB10_A2,GL_RGBA16,GL_LUMINANCE16,GL_SRGB8_ALPHA8,GL_DEPTH_COMPONENT16,GL_DEPTH_COMPONENT24};
GLenum fmts[]={GL_RGBA,GL_RGB,GL_BGRA,GL_BGR,GL_LUMINANCE,GL_LUMINANCE_ALPHA,GL_ALPHA,GL_RED,GL_GREEN,GL_BLUE,GL_DEPTH_COMPONENT};
GLenum types[]={GL_UNSIGNED_BYTE,GL_BYTE,GL_UNSIGNED_SHORT,GL_SHORT,GL_UNSIGNED_INT,GL_INT,GL_FLOAT,GL_UNSIGNED_BYTE_3_3_2,GL_UNSIGNED_BYTE_2_3_3_REV,GL_UNSIGNED_SHORT_5_6_5,GL_UNSIGNED_SHORT_5_6_5_REV,GL_UNSIGNED_SHORT_4_4_4_4,GL_UNSIGNED_SHORT_4_4_4_4_REV,GL_UNSIGNED_SHORT_5_5_5_1,GL_UNSIGNED_SHORT_1_5_5_5_REV,GL_UNSIGNED_INT_8_8_8_8,GL_UNSIGNED_INT_8_8_8_8_REV,GL_UNSIGNED_INT_10_10_10_2,GL_UNSIGNED_INT_2_10_10_10_REV};
int main(){
  init();
  unsigned char src[3*2*4*2]; unsigned char out[4096];
  GLuint t; glGenTextures(1,&t); glBindTexture(GL_TEXTURE_2D,t);
  for(unsigned ii=0;ii<sizeof ifmts/4;ii++){
    for(unsigned i=0;i<sizeof src;i++) src[i]=rnd()&255;
    glPixelStorei(GL_UNPACK_ALIGNMENT,1);
    int depth = ifmts[ii]==GL_DEPTH_COMPONENT16||ifmts[ii]==GL_DEPTH_COMPONENT24;
    GLenum sty = (ifmts[ii]==GL_RGBA16||ifmts[ii]==GL_LUMINANCE16||depth)?GL_UNSIGNED_SHORT:GL_UNSIGNED_BYTE;
    glTexImage2D(GL_TEXTURE_2D,0,ifmts[ii],3,2,0,depth?GL_DEPTH_COMPONENT:GL_RGBA,sty,src);
    printf("TEX %x %x err=%x src:",ifmts[ii],sty,glGetError()); for(unsigned i=0;i<sizeof src;i++) printf(" %u",src[i]); printf("\n");
    for(int cfg=0;cfg<3;cfg++)
    for(unsigned fi=0;fi<sizeof fmts/4;fi++)
    for(unsigned ti=0;ti<sizeof types/4;ti++){
      if(cfg==1){glPixelStorei(GL_PACK_SWAP_BYTES,0);glPixelStorei(GL_PACK_ROW_LENGTH,5);glPixelStorei(GL_PACK_SKIP_PIXELS,1);glPixelStorei(GL_PACK_SKIP_ROWS,1);glPixelStorei(GL_PACK_ALIGNMENT,8);}
      else if(cfg==2){glPixelStorei(GL_PACK_SWAP_BYTES,1);glPixelStorei(GL_PACK_ROW_LENGTH,0);glPixelStorei(GL_PACK_SKIP_PIXELS,0);glPixelStorei(GL_PACK_SKIP_ROWS,0);glPixelStorei(GL_PACK_ALIGNMENT,4);}
      else {glPixelStorei(GL_PACK_SWAP_BYTES,0);glPixelStorei(GL_PACK_ROW_LENGTH,0);glPixelStorei(GL_PACK_SKIP_PIXELS,0);glPixelStorei(GL_PACK_SKIP_ROWS,0);glPixelStorei(GL_PACK_ALIGNMENT,4);}
      memset(out,0xCD,sizeof out); glGetError();
      glGetTexImage(GL_TEXTURE_2D,0,fmts[fi],types[ti],out);
      GLenum e=glGetError();
      printf("GET %d %x %x err=%x",cfg,fmts[fi],types[ti],e);
      if(!e){printf(" out:"); for(int i=0;i<400;i++) printf(" %u",out[i]);}
      printf("\n");
    }
  }
  return 0;
}
