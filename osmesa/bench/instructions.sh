#!/bin/sh
# Instructions per fragment of a frame of osmesa/bench/fill.c, on softgl and
# on Mesa llvmpipe, counted by callgrind. Not a test.
#   cargo build --release -p softgl-osmesa && sh osmesa/bench/instructions.sh [CASES...]
#   SOFTGL_LIB=DIR names the directory holding softgl's libOSMesa.so.8.
# Method: `valgrind --tool=callgrind` runs the client twice, `fill CASE 1` and
# `fill CASE 3` (each also renders its untimed first frame, so 2 and 4 frames),
# and reports the difference of the two runs' total instruction counts
# ("Collected"), which is what 2 frames cost: start-up, set-up, compiles and
# the first frame cancel out; each frame's clear and glFinish stay in. That
# divided by the fragments of 2 frames is the figure. The fragments a frame
# generates are known for `fill`, `depth` and `fog` (16 full-screen quads at
# 1024x1024: 16,777,216) and `quads200` (200 of them; slow under callgrind);
# for other cases only the instructions per frame are printed. One thread on
# both (SOFTGL_THREADS=1, LP_NUM_THREADS=1; callgrind counts every thread's
# instructions anyway), softgl's optimized code only (SOFTGL_JIT_TIER=optimized,
# so that no background compile lands in one run and not the other), Mesa's
# disk cache off (MESA_SHADER_CACHE_DISABLE=true, so both runs compile the
# same), and --smc-check=all-non-file because both run code they generate.
set -e
here=$(cd "$(dirname "$0")" && pwd)
lib=${SOFTGL_LIB:-$here/../../target/release/osmesa}
cases=${*:-fill}
command -v valgrind >/dev/null || { echo "SKIPPED instruction counts: apt-get install valgrind"; exit 0; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mesa=1
if [ -e /usr/lib/x86_64-linux-gnu/libOSMesa.so.8 ] && cc -O2 -g "$here/fill.c" -o "$tmp/fill" -lOSMesa -lGLU -lm 2>/dev/null; then :; else
  mesa=0
  echo "SKIPPED llvmpipe: apt-get install libosmesa6-dev libglu1-mesa-dev"
  cc -O2 -g "$here/fill.c" -o "$tmp/fill" -L"$lib" -lOSMesa -lGLU -lm 2>/dev/null ||
    cc -O2 -g -DNO_GLU "$here/fill.c" -o "$tmp/fill" -L"$lib" -lOSMesa -lm
fi
# count FRAMES CASE ENV...: the instructions callgrind collected over the run.
count() {
  n=$1 c=$2; shift 2
  env "$@" valgrind --tool=callgrind --smc-check=all-non-file --callgrind-out-file="$tmp/cg.out" \
    "$tmp/fill" "$c" "$n" >"$tmp/out" 2>"$tmp/err" || { cat "$tmp/out" "$tmp/err" >&2; return 1; }
  awk '/Collected :/ { print $NF }' "$tmp/err"
}
for c in $cases; do
  case $c in
    fill | depth | fog) frags=16777216 ;;
    quads200) frags=209715200 ;;
    *) frags=0 ;;
  esac
  for v in softgl llvmpipe; do
    if [ $v = softgl ]; then set -- SOFTGL_THREADS=1 SOFTGL_JIT_TIER=optimized LD_LIBRARY_PATH="$lib"
    elif [ $mesa = 1 ]; then set -- LP_NUM_THREADS=1 MESA_SHADER_CACHE_DISABLE=true
    else continue; fi
    one=$(count 1 "$c" "$@"); three=$(count 3 "$c" "$@")
    awk -v v=$v -v c="$c" -v a="$one" -v b="$three" -v f="$frags" 'BEGIN {
      d = (b - a) / 2
      if (f > 0) printf "%-8s %-8s %6.1f instructions per fragment (%.3f G a frame: (%.0f - %.0f) / 2 frames, %.0f fragments a frame)\n", v, c, d / f, d / 1e9, b, a, f
      else printf "%-8s %-8s %.3f G instructions a frame ((%.0f - %.0f) / 2 frames)\n", v, c, d / 1e9, b, a }'
  done
done
