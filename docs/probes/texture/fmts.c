#include "common.h"
#define F(x) {x, #x}
struct {GLenum e; const char*n;} fm[] = {
 {1,"1"},{2,"2"},{3,"3"},{4,"4"},
 F(GL_ALPHA),F(GL_ALPHA4),F(GL_ALPHA8),F(GL_ALPHA12),F(GL_ALPHA16),
 F(GL_LUMINANCE),F(GL_LUMINANCE4),F(GL_LUMINANCE8),F(GL_LUMINANCE12),F(GL_LUMINANCE16),
 F(GL_LUMINANCE_ALPHA),F(GL_LUMINANCE4_ALPHA4),F(GL_LUMINANCE6_ALPHA2),F(GL_LUMINANCE8_ALPHA8),F(GL_LUMINANCE12_ALPHA4),F(GL_LUMINANCE12_ALPHA12),F(GL_LUMINANCE16_ALPHA16),
 F(GL_INTENSITY),F(GL_INTENSITY4),F(GL_INTENSITY8),F(GL_INTENSITY12),F(GL_INTENSITY16),
 F(GL_RGB),F(GL_R3_G3_B2),F(GL_RGB4),F(GL_RGB5),F(GL_RGB8),F(GL_RGB10),F(GL_RGB12),F(GL_RGB16),
 F(GL_RGBA),F(GL_RGBA2),F(GL_RGBA4),F(GL_RGB5_A1),F(GL_RGBA8),F(GL_RGB10_A2),F(GL_RGBA12),F(GL_RGBA16),
 F(GL_SRGB),F(GL_SRGB8),F(GL_SRGB_ALPHA),F(GL_SRGB8_ALPHA8),F(GL_SLUMINANCE),F(GL_SLUMINANCE8),F(GL_SLUMINANCE_ALPHA),F(GL_SLUMINANCE8_ALPHA8),
 F(GL_COMPRESSED_ALPHA),F(GL_COMPRESSED_LUMINANCE),F(GL_COMPRESSED_LUMINANCE_ALPHA),F(GL_COMPRESSED_INTENSITY),F(GL_COMPRESSED_RGB),F(GL_COMPRESSED_RGBA),
 F(GL_DEPTH_COMPONENT),F(GL_DEPTH_COMPONENT16),F(GL_DEPTH_COMPONENT24),F(GL_DEPTH_COMPONENT32),
};
int main(int argc,char**argv){
  init();
  int full = argc>1;
  unsigned char src[256*4]; float dsrc[256];
  for(int i=0;i<256;i++){src[4*i]=i;src[4*i+1]=255-i;src[4*i+2]=(i*7+3)&255;src[4*i+3]=(i*13+5)&255;dsrc[i]=i/255.0f;}
  GLuint t; glGenTextures(1,&t); glBindTexture(GL_TEXTURE_2D,t);
  for(unsigned k=0;k<sizeof fm/sizeof fm[0];k++){
    int depth = (fm[k].e>=GL_DEPTH_COMPONENT16 && fm[k].e<=GL_DEPTH_COMPONENT32) || fm[k].e==GL_DEPTH_COMPONENT;
    if(depth) glTexImage2D(GL_TEXTURE_2D,0,fm[k].e,256,1,0,GL_DEPTH_COMPONENT,GL_FLOAT,dsrc);
    else glTexImage2D(GL_TEXTURE_2D,0,fm[k].e,256,1,0,GL_RGBA,GL_UNSIGNED_BYTE,src);
    GLenum err=glGetError();
    GLint v[10]; GLenum q[10]={GL_TEXTURE_INTERNAL_FORMAT,GL_TEXTURE_RED_SIZE,GL_TEXTURE_GREEN_SIZE,GL_TEXTURE_BLUE_SIZE,GL_TEXTURE_ALPHA_SIZE,GL_TEXTURE_LUMINANCE_SIZE,GL_TEXTURE_INTENSITY_SIZE,GL_TEXTURE_DEPTH_SIZE,GL_TEXTURE_COMPRESSED,GL_TEXTURE_COMPRESSED_IMAGE_SIZE};
    for(int j=0;j<10;j++){v[j]=-1;glGetTexLevelParameteriv(GL_TEXTURE_2D,0,q[j],&v[j]);}
    glGetError();
    printf("%-28s err=%x ifmt=0x%x R%d G%d B%d A%d L%d I%d D%d comp=%d csize=%d\n",fm[k].n,err,v[0],v[1],v[2],v[3],v[4],v[5],v[6],v[7],v[8],v[9]);
    if(full){
      unsigned short out[256*4]; memset(out,0xAB,sizeof out);
      if(depth){ glGetTexImage(GL_TEXTURE_2D,0,GL_DEPTH_COMPONENT,GL_UNSIGNED_INT,out); unsigned*o=(unsigned*)out;
        printf("  depth u32:"); for(int i=0;i<256;i+=1) printf(" %u",o[i]); printf("\n");}
      else { glGetTexImage(GL_TEXTURE_2D,0,GL_RGBA,GL_UNSIGNED_SHORT,out);
      for(int c=0;c<4;c++){printf("  c%d:",c); for(int i=0;i<256;i++) printf(" %u",out[4*i+c]); printf("\n");} }
      printf("  geterr=%x\n",glGetError());
    }
  }
  return 0;
}
