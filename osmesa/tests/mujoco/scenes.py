#!/usr/bin/env python3
"""MuJoCo scenes rendered through whichever libOSMesa the process loads
(MUJOCO_GL=osmesa, PyOpenGL's PYOPENGL_PLATFORM=osmesa, LD_LIBRARY_PATH picks
the library: PyOpenGL dlopens `libOSMesa.so` first, then `libOSMesa.so.9..0`).

    python3 scenes.py OUTDIR [--sizes 320x240,640x480] [--samples 0,4] [--scenes basic,full]

Writes the models (MJCF, a PNG texture) into OUTDIR and, per scene, sample
count, size and mode, `OUTDIR/<scene>_s<samples>_<w>x<h>_<mode>.npy`:
  rgb      the Renderer's RGB (uint8, H×W×3)
  depth    the Renderer's depth mode (metric, float32 H×W)
  seg      the Renderer's segmentation mode (int32 H×W×2: object id, type)
  zbuf     the window depth MuJoCo reads back (mjr_readPixels, mjDEPTH_ZEROFAR: float32, reverse Z)
  overlay  RGB with mjr_overlay / mjr_text drawn (low-level mjr_* API, glBitmap text)
and OUTDIR/results.json: GL strings, per frame the GL errors left after it
(glGetError until 0), MuJoCo's warnings, the first exception, times.
A failure in one frame is recorded and the next frame is tried.

With the tracing libOSMesa of gltrace.py loaded, each first frame of a (scene,
samples, size, mode) starts with a `mark` line; GLTRACE_FRAMES=1 traces those
frames only (GLTRACE_CALLS=1: everything).
"""

import json
import os
import struct
import sys
import time
import traceback
import zlib

os.environ.setdefault("MUJOCO_GL", "osmesa")
os.environ.setdefault("PYOPENGL_PLATFORM", "osmesa")

import numpy as np  # noqa: E402
import mujoco  # noqa: E402


def png(path, w, h, pixel, srgb=True):
    """Writes an 8-bit RGB PNG (with an sRGB chunk) from pixel(x, y) -> (r, g, b)."""
    raw = b"".join(b"\0" + bytes(c for x in range(w) for c in pixel(x, y)) for y in range(h))

    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)

    body = chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    if srgb:
        body += chunk(b"sRGB", b"\0")
    body += chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + body)


def cube_mesh():
    """A unit cube with 4 vertices and texture coordinates per face (24 vertices, 12 triangles)."""
    verts, tex, faces = [], [], []
    for axis in range(3):
        for sign in (-1, 1):
            u, v = [(a) for a in range(3) if a != axis]
            base = len(verts) // 3
            for (a, b) in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = [0.0, 0.0, 0.0]
                p[axis], p[u], p[v] = sign, a * sign, b
                verts += p
                tex += [(a + 1) / 2, (b + 1) / 2]
            faces += [base, base + 1, base + 2, base, base + 2, base + 3]
    f = lambda xs: " ".join(f"{x:g}" for x in xs)  # noqa: E731
    return f(verts), f(tex), f(faces)


def model_xml(scene, samples, shadowsize=4096):
    head = f"""<mujoco model="{scene}">
  <visual>
    <global offwidth="640" offheight="480"/>
    <quality offsamples="{samples}" shadowsize="{shadowsize}"/>
  </visual>"""
    cam = '<camera name="cam" pos="2.2 -2.4 1.6" xyaxes="0.74 0.67 0 -0.30 0.33 0.89"/>'
    if scene == "basic":
        # Lit geoms on a plain plane: no texture, no shadow, no reflection.
        return head + f"""
  <worldbody>
    {cam}
    <light pos="0 0 3" dir="0 0 -1" castshadow="false"/>
    <geom name="floor" type="plane" size="2 2 0.1" rgba="0.5 0.6 0.7 1"/>
    <geom name="box" type="box" size="0.3 0.3 0.3" pos="0 0 0.3" rgba="0.8 0.3 0.2 1"/>
    <geom name="ball" type="sphere" size="0.25" pos="0.7 0.5 0.25" rgba="0.2 0.7 0.3 1"/>
    <geom name="rod" type="capsule" size="0.08" fromto="-0.8 0.6 0.1 -0.4 -0.6 0.1" rgba="0.9 0.8 0.2 1"/>
  </worldbody>
</mujoco>
"""
    verts, tex, faces = cube_mesh()
    # Everything issue 14 names: checker plane with reflectance, sRGB PNG on a
    # mesh, skybox, directional and spot light with shadows, a transparent geom,
    # a skin (VBOs), fog off (MuJoCo's default).
    return head + f"""
  <asset>
    <texture name="sky" type="skybox" builtin="gradient" rgb1="0.4 0.6 0.8" rgb2="0 0 0" width="64" height="64"/>
    <texture name="grid" type="2d" builtin="checker" rgb1="0.2 0.3 0.4" rgb2="0.1 0.15 0.2" width="256" height="256" mark="edge" markrgb="0.8 0.8 0.8"/>
    <material name="grid" texture="grid" texrepeat="2 2" reflectance="0.3"/>
    <texture name="photo" type="2d" file="photo.png" colorspace="sRGB"/>
    <material name="photo" texture="photo"/>
    <mesh name="cube" vertex="{verts}" texcoord="{tex}" face="{faces}" scale="0.25 0.25 0.25"/>
  </asset>
  <worldbody>
    {cam}
    <light name="sun" directional="true" pos="0 0 4" dir="0.3 0.2 -1" castshadow="true" diffuse="0.6 0.6 0.6"/>
    <light name="spot" pos="1.2 -1.0 2.0" dir="-0.5 0.4 -1" cutoff="35" exponent="10" castshadow="true" diffuse="0.5 0.5 0.4"/>
    <geom name="floor" type="plane" size="0 0 0.05" material="grid"/>
    <body name="crate" pos="0 0 0.3" euler="0 0 30">
      <geom name="crate" type="mesh" mesh="cube" material="photo"/>
    </body>
    <geom name="ball" type="sphere" size="0.25" pos="0.8 0.4 0.25" rgba="0.2 0.7 0.3 1"/>
    <geom name="glass" type="box" size="0.35 0.05 0.3" pos="0.3 -0.6 0.3" rgba="0.3 0.5 1 0.4"/>
    <geom name="rod" type="capsule" size="0.06" fromto="-0.9 0.7 0.06 -0.5 -0.5 0.06" rgba="0.9 0.8 0.2 1"/>
    <body name="bone" pos="-0.6 -0.2 0.02">
      <geom type="sphere" size="0.01" rgba="0 0 0 0"/>
    </body>
  </worldbody>
  <deformable>
    <skin name="sheet" rgba="0.8 0.4 0.7 1" vertex="-0.3 -0.3 0.02  0.3 -0.3 0.02  0.3 0.3 0.15  -0.3 0.3 0.15"
          face="0 1 2  0 2 3">
      <bone body="bone" bindpos="0 0 0" bindquat="1 0 0 0" vertid="0 1 2 3" vertweight="1 1 1 1"/>
    </skin>
  </deformable>
</mujoco>
"""


class GL:
    """PyOpenGL bits: the current context's errors and strings, the trace hooks."""

    def __init__(self):
        from OpenGL import GL as gl
        from OpenGL import platform

        self.gl = gl
        lib = platform.PLATFORM.GL
        self.mark = getattr(lib, "gltrace_mark", None)
        self.enable = getattr(lib, "gltrace_enable", None)
        self.trace = os.environ.get("GLTRACE_FRAMES") == "1" and self.enable is not None

    def errors(self):
        out = []
        for _ in range(16):
            e = self.gl.glGetError()
            if not e:
                break
            out.append(f"0x{e:04x}")
        return out

    def strings(self):
        g = self.gl
        s = lambda e: (g.glGetString(e) or b"").decode()  # noqa: E731
        return {"version": s(g.GL_VERSION), "renderer": s(g.GL_RENDERER), "vendor": s(g.GL_VENDOR)}

    def begin(self, name):
        if self.mark is not None:
            self.mark(name.encode())
        if self.trace:
            self.enable(1)

    def end(self):
        if self.trace:
            self.enable(0)


def save(out, results):
    with open(os.path.join(out, "results.json"), "w") as f:
        json.dump(results, f, indent=1)


GLAD_EXTENSIONS = ["GL_ARB_clip_control", "GL_ARB_depth_buffer_float", "GL_ARB_framebuffer_object",
                   "GL_ARB_seamless_cube_map", "GL_ARB_vertex_buffer_object", "GL_EXT_texture_sRGB",
                   "GL_KHR_debug"]


def probe_gl():
    """The GL strings of a context made as MuJoCo's Python bindings make it, and
    which of the extensions MuJoCo's loader looks for are listed."""
    ctx = mujoco.GLContext(16, 16)
    ctx.make_current()
    g = GL()
    strings = g.strings()
    ext = (g.gl.glGetString(g.gl.GL_EXTENSIONS) or b"").decode().split()
    ctx.free()
    strings["glad_extensions"] = [e for e in GLAD_EXTENSIONS if e in ext]
    print(f"mujoco {mujoco.__version__}", flush=True)
    print(f"gl {strings['version']} | {strings['renderer']}", flush=True)
    print("extensions " + " ".join(strings["glad_extensions"]), flush=True)
    return strings


def render_all(out, sizes, samples_list, scenes, repeat):
    png(os.path.join(out, "photo.png"), 64, 64,
        lambda x, y: ((x * 4) % 256, (y * 4) % 256, 255 if (x // 8 + y // 8) % 2 else 40))
    warnings = []
    mujoco.set_mju_user_warning(lambda msg: warnings.append(msg))
    results = {"frames": {}, "gl": probe_gl(), "mujoco": mujoco.__version__}
    gl = None
    for scene in scenes:
        for samples in samples_list:
            path = os.path.join(out, f"{scene}_s{samples}.xml")
            with open(path, "w") as f:
                f.write(model_xml(scene, samples))
            model = mujoco.MjModel.from_xml_path(path)
            data = mujoco.MjData(model)
            mujoco.mj_forward(model, data)
            for (w, h) in sizes:
                key = f"{scene}_s{samples}_{w}x{h}"
                frames = {}
                try:
                    del warnings[:]
                    renderer = mujoco.Renderer(model, h, w)
                except Exception as e:  # noqa: BLE001 - recorded, the run goes on
                    results["frames"][key] = {"error": f"{type(e).__name__}: {e}", "warnings": list(warnings)}
                    print(f"frame {key} error {type(e).__name__}: {e}", flush=True)
                    for w_ in warnings[:3]:
                        print(f"warning {key} {w_}", flush=True)
                    save(out, results)
                    continue
                if gl is None:
                    gl = GL()
                setup_errors = gl.errors()
                setup_warnings = list(warnings)
                print(f"setup {key} | errors={','.join(setup_errors) or '-'} warnings={len(setup_warnings)}", flush=True)
                for w_ in setup_warnings[:3]:
                    print(f"warning {key} {w_}", flush=True)
                for mode in ("rgb", "depth", "seg", "zbuf", "overlay"):
                    rec = {"warnings": [], "errors": []}
                    try:
                        del warnings[:]
                        times = []
                        for i in range(repeat):
                            if i == 0:
                                gl.begin(f"{key}_{mode}")
                            t0 = time.perf_counter()
                            img = frame(renderer, model, data, mode)
                            times.append(time.perf_counter() - t0)
                            if i == 0:
                                gl.end()
                            rec["errors"] += gl.errors()
                        np.save(os.path.join(out, f"{key}_{mode}.npy"), img)
                        rec["ms"] = 1000 * sorted(times)[len(times) // 2]
                    except Exception as e:  # noqa: BLE001
                        gl.end()
                        rec["error"] = f"{type(e).__name__}: {e}"
                        rec["trace"] = traceback.format_exc(limit=3)
                    rec["warnings"] = list(warnings)
                    frames[mode] = rec
                    results["frames"][key] = frames
                    save(out, results)
                    status = f"error {rec['error']}" if "error" in rec else "ok"
                    errs = ",".join(rec["errors"]) or "-"
                    print(f"frame {key}_{mode} {status} | errors={errs} warnings={len(rec['warnings'])}", flush=True)
                    for w_ in rec["warnings"][:3]:
                        print(f"warning {key}_{mode} {w_}", flush=True)
                frames["setup_errors"] = setup_errors
                frames["setup_warnings"] = setup_warnings
                results["frames"][key] = frames
                renderer.close()
    return results


def frame(renderer, model, data, mode):
    renderer.disable_depth_rendering()
    renderer.disable_segmentation_rendering()
    renderer.update_scene(data, camera="cam")
    if mode == "rgb":
        return renderer.render()
    if mode == "depth":
        renderer.enable_depth_rendering()
        return renderer.render()
    if mode == "seg":
        renderer.enable_segmentation_rendering()
        return renderer.render()
    # The low-level API on the Renderer's own context (the public Renderer has
    # no overlay and reads depth back converted): its GL context is current.
    con = renderer._mjr_context  # noqa: SLF001
    rect = mujoco.MjrRect(0, 0, renderer.width, renderer.height)
    mujoco.mjr_setBuffer(mujoco.mjtFramebuffer.mjFB_OFFSCREEN, con)
    mujoco.mjr_render(rect, renderer.scene, con)
    if mode == "zbuf":
        z = np.zeros((renderer.height, renderer.width), np.float32)
        mujoco.mjr_readPixels(None, z, rect, con)
        return np.flipud(z)
    mujoco.mjr_overlay(mujoco.mjtFont.mjFONT_NORMAL, mujoco.mjtGridPos.mjGRID_TOPLEFT, rect,
                       "softgl MuJoCo", "frame 1", con)
    mujoco.mjr_overlay(mujoco.mjtFont.mjFONT_BIG, mujoco.mjtGridPos.mjGRID_BOTTOMRIGHT, rect,
                       "Big 0.5", "", con)
    mujoco.mjr_text(mujoco.mjtFont.mjFONT_SHADOW, "shadow text", con, 0.5, 0.5, 1, 1, 0)
    rgb = np.zeros((renderer.height, renderer.width, 3), np.uint8)
    mujoco.mjr_readPixels(rgb, None, rect, con)
    return np.flipud(rgb)


def main():
    args = sys.argv[1:]
    out = args[0]
    opts = dict(zip(args[1::2], args[2::2]))
    sizes = [tuple(int(v) for v in s.split("x")) for s in opts.get("--sizes", "320x240,640x480").split(",")]
    samples = [int(s) for s in opts.get("--samples", "0,4").split(",")]
    scenes = opts.get("--scenes", "basic,full").split(",")
    repeat = int(opts.get("--repeat", "1"))
    os.makedirs(out, exist_ok=True)
    save(out, render_all(out, sizes, samples, scenes, repeat))
    print("done")


if __name__ == "__main__":
    main()
