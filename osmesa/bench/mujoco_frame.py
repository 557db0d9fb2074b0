#!/usr/bin/env python3
"""Times MuJoCo frames through whichever libOSMesa the process loads
(MUJOCO_GL=osmesa; LD_LIBRARY_PATH picks softgl's). The model is the `full`
scene of osmesa/tests/mujoco/scenes.py (4096² shadow map, a directional and a
spot light casting shadows, reflection, skybox, textures, 4x multisampling).
Prints one line per row: `ROW MEDIAN_MS`:
  setup-WxH            the Renderer's creation (mjr_makeContext: FBOs, shadow map, lists, fonts)
  full-WxH             one RGB frame (mjr_render + glReadPixels + the Renderer's flip)
  noshadow-WxH         the same frame with mjRND_SHADOW off (the difference is the shadow passes)
  depth-WxH            the Renderer's depth mode
    python3 mujoco_frame.py [FRAMES] [SIZES] [--rows ROWS]   e.g. 5 320x240,640x480 --rows noshadow,depth
(--rows: only those rows, each frame; the default is full,noshadow,depth)
Run by osmesa/bench/mujoco.sh; not a test."""

import os
import sys
import tempfile
import time

os.environ.setdefault("MUJOCO_GL", "osmesa")
os.environ.setdefault("PYOPENGL_PLATFORM", "osmesa")
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "mujoco"))

import mujoco  # noqa: E402
import scenes  # noqa: E402


def median(xs):
    xs = sorted(xs)
    return xs[len(xs) // 2]


def main():
    args = sys.argv[1:]
    names = ["full", "noshadow", "depth"]
    if "--rows" in args:
        i = args.index("--rows")
        names = args[i + 1].split(",")
        del args[i:i + 2]
    frames = int(args[0]) if len(args) > 0 else 5
    sizes = [tuple(int(v) for v in s.split("x")) for s in (args[1] if len(args) > 1 else "320x240,640x480").split(",")]
    out = tempfile.mkdtemp(prefix="mujoco-bench-")
    scenes.png(os.path.join(out, "photo.png"), 64, 64,
               lambda x, y: ((x * 4) % 256, (y * 4) % 256, 255 if (x // 8 + y // 8) % 2 else 40))
    path = os.path.join(out, "full.xml")
    with open(path, "w") as f:
        f.write(scenes.model_xml("full", 4))
    model = mujoco.MjModel.from_xml_path(path)
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    for (w, h) in sizes:
        t0 = time.perf_counter()
        r = mujoco.Renderer(model, h, w)
        print(f"setup-{w}x{h} {1000 * (time.perf_counter() - t0):.3f}", flush=True)
        rows = {name: [] for name in names}
        for _ in range(frames + 1):  # the first frame of each row is a warm-up
            for row in rows:
                r.disable_depth_rendering()
                r.update_scene(data, camera="cam")
                r.scene.flags[mujoco.mjtRndFlag.mjRND_SHADOW] = row != "noshadow"
                if row == "depth":
                    r.enable_depth_rendering()
                t0 = time.perf_counter()
                r.render()
                rows[row].append(1000 * (time.perf_counter() - t0))
        for row, ts in rows.items():
            print(f"{row}-{w}x{h} {median(ts[1:]):.3f}", flush=True)
        r.close()


if __name__ == "__main__":
    main()
