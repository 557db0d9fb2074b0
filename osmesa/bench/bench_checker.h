/* MuJoCo's 256² floor checker as the benches upload it (not a test): RGB
 * texels stored as `internal`, REPEAT, LINEAR_MIPMAP_LINEAR mipmaps from
 * gluBuild2DMipmaps, MODULATE; bound on the active unit. Include after
 * GL/glu.h. */

static GLuint checker_texture(GLint internal) {
  GLuint tex;
  static unsigned char t[256 * 256 * 3];
  for (int y = 0; y < 256; y++)
    for (int x = 0; x < 256; x++) {
      int on = ((x / 128) ^ (y / 128)) & 1, edge = x == 0 || y == 0;
      unsigned char *p = t + (y * 256 + x) * 3;
      p[0] = edge ? 204 : on ? 51 : 26;
      p[1] = edge ? 204 : on ? 77 : 38;
      p[2] = edge ? 204 : on ? 102 : 51;
    }
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  gluBuild2DMipmaps(GL_TEXTURE_2D, internal, 256, 256, GL_RGB, GL_UNSIGNED_BYTE, t);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  return tex;
}
