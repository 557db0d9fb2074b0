"""PyOpenGL on softgl's libOSMesa: create a context, draw, read back.

Run with PYOPENGL_PLATFORM=osmesa and LD_LIBRARY_PATH (or SOFTGL_OSMESA_DIR)
naming softgl's library directory; asserts real pixel values and that the
library PyOpenGL loaded is softgl's.
"""
import ctypes
import os
import sys

assert os.environ.get("PYOPENGL_PLATFORM") == "osmesa", "set PYOPENGL_PLATFORM=osmesa"

from OpenGL import GL  # noqa: E402
from OpenGL import osmesa  # noqa: E402
from OpenGL.platform import PLATFORM  # noqa: E402

# The library PyOpenGL loaded must be softgl's, not Mesa's.
lib_dir = os.environ.get("SOFTGL_OSMESA_DIR")
loaded = PLATFORM.GL._name
print("loaded", loaded)
if lib_dir:
    with open("/proc/self/maps") as maps:
        paths = {line.split()[-1] for line in maps if "libOSMesa" in line}
    real = {os.path.realpath(p) for p in paths}
    want = os.path.realpath(os.path.join(lib_dir, "libOSMesa.so"))
    assert real == {want}, f"mapped {paths}, want {want}"

W, H = 32, 24
ctx = osmesa.OSMesaCreateContextExt(osmesa.OSMESA_RGBA, 24, 8, 8, None)
assert ctx, "OSMesaCreateContextExt failed"
buf = (ctypes.c_ubyte * (W * H * 4))()  # plain ctypes: no numpy needed
assert osmesa.OSMesaMakeCurrent(ctx, buf, GL.GL_UNSIGNED_BYTE, W, H)
assert osmesa.OSMesaGetCurrentContext()

print("vendor", GL.glGetString(GL.GL_VENDOR).decode())
print("renderer", GL.glGetString(GL.GL_RENDERER).decode())
print("version", GL.glGetString(GL.GL_VERSION).decode())

GL.glViewport(0, 0, W, H)
GL.glClearColor(0.0, 0.0, 1.0, 1.0)
GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
GL.glMatrixMode(GL.GL_PROJECTION)
GL.glLoadIdentity()
GL.glOrtho(0, W, 0, H, -1, 1)
GL.glMatrixMode(GL.GL_MODELVIEW)
GL.glLoadIdentity()
# A red rectangle over the left half, then a half-transparent green one blended over its bottom.
GL.glColor3f(1.0, 0.0, 0.0)
GL.glBegin(GL.GL_QUADS)
GL.glVertex2f(0, 0)
GL.glVertex2f(W / 2, 0)
GL.glVertex2f(W / 2, H)
GL.glVertex2f(0, H)
GL.glEnd()
GL.glEnable(GL.GL_BLEND)
GL.glBlendFunc(GL.GL_SRC_ALPHA, GL.GL_ONE_MINUS_SRC_ALPHA)
GL.glColor4f(0.0, 1.0, 0.0, 0.5)
GL.glRectf(0, 0, W, 4)
GL.glDisable(GL.GL_BLEND)
GL.glFinish()

px = (ctypes.c_ubyte * (W * H * 4))()
GL.glReadPixels(0, 0, W, H, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE, px)
data = bytes(px)
assert len(data) == W * H * 4, len(data)


def pixel(x, y):
    o = (y * W + x) * 4
    return tuple(data[o:o + 4])


# Exact values: red and blue are unblended; the blend is llvmpipe's
# mul(s,a) + mul(d,255-a), mul(x,y) = (t + (t>>8) + 128) >> 8, with a = 128
# (0.5 rounds to even 128), alpha blended the same way: 64 + 127 = 191.
assert pixel(3, 10) == (255, 0, 0, 255), pixel(3, 10)
assert pixel(28, 10) == (0, 0, 255, 255), pixel(28, 10)
assert pixel(3, 1) == (127, 128, 0, 191), pixel(3, 1)
assert pixel(28, 1) == (0, 128, 127, 191), pixel(28, 1)
# The caller's buffer holds the same image (softgl renders into it).
assert bytes(buf) == data
assert GL.glGetError() == GL.GL_NO_ERROR

# Errors come back through glGetError (PyOpenGL raises GLError).
try:
    GL.glEnable(0x1234)
    raise SystemExit("glEnable(0x1234) did not raise")
except GL.GLError as e:
    assert e.err == GL.GL_INVALID_ENUM, e.err

# Float read-back and state queries.
f = (ctypes.c_float * 4)()
GL.glReadPixels(3, 10, 1, 1, GL.GL_RGBA, GL.GL_FLOAT, f)
assert list(f) == [1.0, 0.0, 0.0, 1.0], list(f)
vp = (ctypes.c_int * 4)()
GL.glGetIntegerv(GL.GL_VIEWPORT, vp)
assert list(vp) == [0, 0, W, H], list(vp)
w, h, bpv, ptr = osmesa.OSMesaGetDepthBuffer(ctx)
assert (w, h, bpv) == (W, H, 4), (w, h, bpv)
depth = ctypes.cast(ptr, ctypes.POINTER(ctypes.c_uint32))
assert depth[0] == 0xFFFFFF, hex(depth[0])  # cleared to 1.0, stencil 0 in the high byte
w, h, fmt, cbuf = osmesa.OSMesaGetColorBuffer(ctx)
assert (w, h, fmt) == (W, H, osmesa.OSMESA_RGBA) and cbuf.value == ctypes.addressof(buf)

# A textured quad: a 2x2 RGBA texture (red, green / blue, white), NEAREST,
# GL_REPLACE, over the whole window; each quadrant is one texel, exactly.
tex = int(GL.glGenTextures(1))
GL.glBindTexture(GL.GL_TEXTURE_2D, tex)
texels = (ctypes.c_ubyte * 16)(255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255)
GL.glTexImage2D(GL.GL_TEXTURE_2D, 0, GL.GL_RGBA, 2, 2, 0, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE, texels)
GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MIN_FILTER, GL.GL_NEAREST)
GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MAG_FILTER, GL.GL_NEAREST)
GL.glTexEnvi(GL.GL_TEXTURE_ENV, GL.GL_TEXTURE_ENV_MODE, GL.GL_REPLACE)
GL.glEnable(GL.GL_TEXTURE_2D)
GL.glBegin(GL.GL_QUADS)
for s, t in ((0, 0), (1, 0), (1, 1), (0, 1)):
    GL.glTexCoord2f(s, t)
    GL.glVertex2f(s * W, t * H)
GL.glEnd()
GL.glDisable(GL.GL_TEXTURE_2D)
GL.glFinish()
data = bytes(buf)
assert pixel(3, 3) == (255, 0, 0, 255), pixel(3, 3)
assert pixel(28, 3) == (0, 255, 0, 255), pixel(28, 3)
assert pixel(3, 20) == (0, 0, 255, 255), pixel(3, 20)
assert pixel(28, 20) == (255, 255, 255, 255), pixel(28, 20)
assert GL.glGetTexLevelParameteriv(GL.GL_TEXTURE_2D, 0, GL.GL_TEXTURE_WIDTH) == 2
assert GL.glIsTexture(tex)
GL.glDeleteTextures([tex])
assert not GL.glIsTexture(tex)
assert GL.glGetError() == GL.GL_NO_ERROR

osmesa.OSMesaDestroyContext(ctx)
print("ok")
sys.exit(0)
