"""PyOpenGL on softgl's EGL face: a surfaceless display, a pbuffer, a GL
context; draw, read back exact pixels.

Run with PYOPENGL_PLATFORM=egl and LD_LIBRARY_PATH naming softgl's egl
directory (SOFTGL_EGL_DIR too, to check the mapped library is softgl's).
"""
import ctypes
import os

assert os.environ.get("PYOPENGL_PLATFORM") == "egl", "set PYOPENGL_PLATFORM=egl"

from OpenGL import EGL  # noqa: E402
from OpenGL import GL  # noqa: E402

W, H = 16, 8
dpy = EGL.eglGetDisplay(EGL.EGL_DEFAULT_DISPLAY)
major, minor = EGL.EGLint(), EGL.EGLint()
assert EGL.eglInitialize(dpy, ctypes.pointer(major), ctypes.pointer(minor))
print("egl", major.value, minor.value, EGL.eglQueryString(dpy, EGL.EGL_VENDOR).decode())

want = [EGL.EGL_SURFACE_TYPE, EGL.EGL_PBUFFER_BIT, EGL.EGL_RENDERABLE_TYPE, EGL.EGL_OPENGL_BIT,
        EGL.EGL_DEPTH_SIZE, 24, EGL.EGL_NONE]
config = EGL.EGLConfig()
n = EGL.EGLint()
assert EGL.eglChooseConfig(dpy, (EGL.EGLint * len(want))(*want), ctypes.pointer(config), 1, ctypes.pointer(n))
assert n.value == 1, n.value
assert EGL.eglBindAPI(EGL.EGL_OPENGL_API)
size = [EGL.EGL_WIDTH, W, EGL.EGL_HEIGHT, H, EGL.EGL_NONE]
surface = EGL.eglCreatePbufferSurface(dpy, config, (EGL.EGLint * len(size))(*size))
ctx = EGL.eglCreateContext(dpy, config, EGL.EGL_NO_CONTEXT, None)
assert EGL.eglMakeCurrent(dpy, surface, surface, ctx)

lib_dir = os.environ.get("SOFTGL_EGL_DIR")
if lib_dir:
    with open("/proc/self/maps") as maps:
        names = ("libEGL", "libOpenGL", "libGL.", "libGLX", "libOSMesa")
        paths = {line.split()[-1] for line in maps if any(n in line for n in names)}
    real = {os.path.realpath(p) for p in paths}
    want_lib = os.path.realpath(os.path.join(lib_dir, "libEGL.so.1"))
    assert real == {want_lib}, f"mapped {paths}, want {want_lib}"

print("renderer", GL.glGetString(GL.GL_RENDERER).decode())
GL.glClearColor(0.0, 0.0, 1.0, 1.0)
GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
GL.glMatrixMode(GL.GL_PROJECTION)
GL.glLoadIdentity()
GL.glOrtho(0, W, 0, H, -1, 1)
GL.glColor3f(1.0, 0.0, 0.0)
GL.glRectf(4, 2, 12, 6)
pixels = GL.glReadPixels(0, 0, W, H, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE)
data = bytes(pixels)
red = sum(1 for i in range(0, len(data), 4) if data[i:i + 4] == b"\xff\x00\x00\xff")
blue = sum(1 for i in range(0, len(data), 4) if data[i:i + 4] == b"\x00\x00\xff\xff")
assert (red, blue) == (32, W * H - 32), (red, blue)
assert GL.glGetError() == GL.GL_NO_ERROR
assert EGL.eglMakeCurrent(dpy, EGL.EGL_NO_SURFACE, EGL.EGL_NO_SURFACE, EGL.EGL_NO_CONTEXT)
assert EGL.eglDestroyContext(dpy, ctx)
assert EGL.eglDestroySurface(dpy, surface)
assert EGL.eglTerminate(dpy)
print("ok")
