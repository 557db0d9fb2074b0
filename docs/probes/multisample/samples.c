#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
static unsigned char buf[16*16*4];
int main(void){
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 16, 16);
  for (int n = 0; n <= 5; n++) {
    GLuint rb; glGenRenderbuffers(1, &rb); glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, n, GL_RGBA8, 16, 16);
    GLenum e = glGetError(); GLint s = -1; glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &s);
    printf("asked %d: error %#x, GL_RENDERBUFFER_SAMPLES %d\n", n, e, s);
  }
  /* glReadPixels from a multisampled FBO, and GL_MULTISAMPLE default */
  GLuint fb, rb; glGenFramebuffers(1,&fb); glGenRenderbuffers(1,&rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb); glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_RGBA8, 16, 16);
  glBindFramebuffer(GL_FRAMEBUFFER, fb); glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
  unsigned char px[4]; glReadPixels(0,0,1,1,GL_RGBA,GL_UNSIGNED_BYTE,px);
  printf("readpixels ms fbo: %#x\n", glGetError());
  printf("GL_MULTISAMPLE %d GL_SAMPLE_COVERAGE_VALUE ", glIsEnabled(GL_MULTISAMPLE));
  GLfloat v; glGetFloatv(GL_SAMPLE_COVERAGE_VALUE, &v); printf("%g\n", v);
  return 0;
}
