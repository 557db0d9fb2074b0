#!/bin/sh
# One MuJoCo frame (osmesa/bench/mujoco_frame.py: the `full` scene of
# osmesa/tests/mujoco/scenes.py, shadows on, 4x multisampled, 320x240 and
# 640x480) on softgl with 1 and 2 threads (SOFTGL_THREADS) against Mesa's
# llvmpipe with 1 and 2 (LP_NUM_THREADS), interleaved round by round: each round
# runs softgl-1, softgl-2, llvmpipe-1, llvmpipe-2 once, each a fresh process
# printing the median of its frames. Prints per row the median of the rounds'
# medians and the ratios softgl / llvmpipe (below 1: softgl is faster). Rows:
# setup (the Renderer's creation), full (a frame), noshadow (the same frame
# without the shadow passes: full - noshadow is what the 4096² shadow maps
# cost), depth (the Renderer's depth mode). A softgl run that fails prints its
# error and leaves its columns "-" (MuJoCo does not run on softgl before issue
# 14 lands). Then the same for osmesa/bench/mujoco_passes.c, MuJoCo's floor
# passes through the C ABI without FBOs, which runs on softgl today (plane,
# floor, shadow-4096 rows: its header). Needs `python3 -m pip install mujoco
# PyOpenGL`, libosmesa6-dev, libglu1-mesa-dev, cc. Not a test.
#   cargo build --release -p softgl-osmesa && sh osmesa/bench/mujoco.sh [ROUNDS] [FRAMES] [SIZES]
#   SOFTGL_LIB=DIR names the directory holding softgl's libOSMesa.so.8 (and libOSMesa.so).
set -e
here=$(cd "$(dirname "$0")" && pwd)
lib=${SOFTGL_LIB:-$here/../../target/release/osmesa}
rounds=${1:-3}
frames=${2:-5}
sizes=${3:-320x240,640x480}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
python3 -c 'import mujoco, OpenGL' 2>/dev/null || { echo "SKIPPED: python3 -m pip install mujoco PyOpenGL" >&2; exit 1; }
[ -e /usr/lib/x86_64-linux-gnu/libOSMesa.so.8 ] || { echo "SKIPPED: apt-get install libosmesa6" >&2; exit 1; }
[ -e "$lib/libOSMesa.so" ] || echo "no softgl library at $lib/libOSMesa.so (cargo build --release -p softgl-osmesa, or SOFTGL_LIB=DIR): softgl columns empty" >&2
# run COLUMN ENV...: one process of $prog; its lines go to $tmp/COLUMN.
run() {
  col=$1; shift
  if env "$@" MUJOCO_GL=osmesa PYOPENGL_PLATFORM=osmesa $prog "$frames" "$sizes" >"$tmp/out" 2>"$tmp/err"; then
    cat "$tmp/out" >>"$tmp/$col"
  else
    echo "FAILED $col: $(grep -v '^ ' "$tmp/err" | tail -n 1)" >&2
  fi
}
med() {
  awk -v r="$2" '$1 == r { print $2 }' "$tmp/$1" 2>/dev/null | sort -n |
    awk '{ a[NR] = $1 } END { if (NR) print a[int((NR + 1) / 2)]; else print "-" }'
}
# table PROGRAM: the interleaved rounds and their table.
table() {
  prog=$1
  rm -f "$tmp/s1" "$tmp/s2" "$tmp/l1" "$tmp/l2"
  touch "$tmp/s1" "$tmp/s2" "$tmp/l1" "$tmp/l2"
  for r in $(seq "$rounds"); do
    run s1 SOFTGL_THREADS=1 LD_LIBRARY_PATH="$lib"
    run s2 SOFTGL_THREADS=2 LD_LIBRARY_PATH="$lib"
    run l1 -u LD_LIBRARY_PATH LP_NUM_THREADS=1 GALLIUM_DRIVER=llvmpipe MESA_SHADER_CACHE_DISABLE=true
    run l2 -u LD_LIBRARY_PATH LP_NUM_THREADS=2 GALLIUM_DRIVER=llvmpipe MESA_SHADER_CACHE_DISABLE=true
  done
  printf '%-18s %11s %11s %11s %11s %8s %8s\n' row softgl-1 softgl-2 llvmpipe-1 llvmpipe-2 s1/l1 s2/l2
  for row in $(cat "$tmp/l1" "$tmp/s1" | awk '!seen[$1]++ { print $1 }'); do
    awk -v c="$row" -v a="$(med s1 "$row")" -v b="$(med s2 "$row")" -v x="$(med l1 "$row")" -v y="$(med l2 "$row")" '
      function ms(v) { return v == "-" ? sprintf("%11s", "-") : sprintf("%8.2f ms", v) }
      function ratio(p, q) { return (p == "-" || q == "-" || q == 0) ? sprintf("%8s", "-") : sprintf("%7.2fx", p / q) }
      BEGIN { printf "%-18s %s %s %s %s %s %s\n", c, ms(a), ms(b), ms(x), ms(y), ratio(a, x), ratio(b, y) }'
  done
}
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg); rounds: $rounds; frames: $frames"
echo "MuJoCo frames (mujoco_frame.py):"
table "python3 $here/mujoco_frame.py"
if cc -O2 "$here/mujoco_passes.c" -o "$tmp/passes" -lOSMesa -lGLU -lm 2>"$tmp/cc.err"; then
  echo "MuJoCo's floor passes through the C ABI (mujoco_passes.c):"
  table "$tmp/passes"
else
  echo "SKIPPED mujoco_passes.c: apt-get install libosmesa6-dev libglu1-mesa-dev gcc" >&2
fi
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
