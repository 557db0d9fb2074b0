/* The framebuffer object the deep-colour clients draw into: a colour
 * renderbuffer of `format` and a DEPTH24_STENCIL8 one on the depth and
 * stencil attachments, w x h, of `samples` samples (0: single-sampled,
 * through glRenderbufferStorage); the renderbuffers' names in `rbs`, the
 * object left bound. Include after GL/glext.h with GL_GLEXT_PROTOTYPES. */
static GLuint colour_depth_object(GLenum format, int samples, int w, int h, GLuint rbs[2]) {
  GLuint fbo;
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glGenRenderbuffers(2, rbs);
  GLenum formats[2] = {format, GL_DEPTH24_STENCIL8};
  for (int i = 0; i < 2; i++) {
    glBindRenderbuffer(GL_RENDERBUFFER, rbs[i]);
    if (samples)
      glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, formats[i], w, h);
    else
      glRenderbufferStorage(GL_RENDERBUFFER, formats[i], w, h);
  }
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rbs[0]);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rbs[1]);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rbs[1]);
  return fbo;
}
