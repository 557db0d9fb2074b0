#!/bin/sh
# softgl's libOSMesa.so.8 with 1 and 2 threads (SOFTGL_THREADS) against Mesa's
# llvmpipe with 1 and 2 (LP_NUM_THREADS), the same client (osmesa/bench/fill.c,
# whose header describes the cases), interleaved round by round: each round
# runs softgl-1, softgl-2, llvmpipe-1, llvmpipe-2 once, each run a fresh
# process printing the median of its frames (5; `create` 20 samples). Prints
# per figure the median of the rounds' medians in the four columns and the
# ratios softgl-1 / llvmpipe-1 and softgl-2 / llvmpipe-2 (below 1: softgl is
# faster), and where the work is known the four rates. `thrash-first` is the
# first frame of each process (one sample a run): llvmpipe runs with
# MESA_SHADER_CACHE_DISABLE=true so that its shaders are compiled cold
# (softgl has no disk cache). Without Mesa's libOSMesa the llvmpipe columns are
# skipped with one loud line and softgl still runs. Not a test.
#   cargo build --release -p softgl-osmesa && sh osmesa/bench/compare.sh [ROUNDS] [CASES...]
#   SOFTGL_LIB=DIR names the directory holding softgl's libOSMesa.so.8.
# (The cost of one attribute call, glColor3f, glVertex3f, ...: osmesa/bench/calls.c, run as its header says.)
set -e
here=$(cd "$(dirname "$0")" && pwd)
lib=${SOFTGL_LIB:-$here/../../target/release/osmesa}
rounds=${1:-3}; [ $# -gt 0 ] && shift
cases=${*:-fill quads200 tris ops xor thrash tex lit litlist lit16 lit16list clear clearall create}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
bin=$tmp/fill
[ -e "$lib/libOSMesa.so.8" ] || { echo "no softgl library at $lib/libOSMesa.so.8 (cargo build --release -p softgl-osmesa, or SOFTGL_LIB=DIR)" >&2; exit 1; }
mesa=1
if [ -e /usr/lib/x86_64-linux-gnu/libOSMesa.so.8 ] && cc -O2 "$here/fill.c" -o "$bin" -lOSMesa -lGLU -lm 2>"$tmp/cc.err"; then :; else
  mesa=0
  echo "SKIPPED llvmpipe columns: apt-get install libosmesa6-dev libglu1-mesa-dev"
  # The client against softgl's library alone, with GLU or without.
  cc -O2 "$here/fill.c" -o "$bin" -L"$lib" -lOSMesa -lGLU -lm 2>>"$tmp/cc.err" ||
    cc -O2 -DNO_GLU "$here/fill.c" -o "$bin" -L"$lib" -lOSMesa -lm 2>>"$tmp/cc.err" ||
    { cat "$tmp/cc.err" >&2; echo "cannot build osmesa/bench/fill.c (needs GL/gl.h: apt-get install libgl-dev)" >&2; exit 1; }
fi
failed=0
# run COLUMN CASE SAMPLES ENV...: one process; its lines go to $tmp/COLUMN.
run() {
  col=$1 c=$2 n=$3; shift 3
  if env "$@" "$bin" "$c" "$n" >"$tmp/out" 2>"$tmp/err"; then cat "$tmp/out" >>"$tmp/$col"
  else echo "FAILED $col $c: $(cat "$tmp/out" "$tmp/err" | tr '\n' ' ')" >&2; failed=1; fi
}
# med COLUMN ROW: the median of ROW's samples in COLUMN, or - without any.
med() {
  awk -v r="$2" '$1 == r { print $2 }' "$tmp/$1" 2>/dev/null | sort -n |
    awk '{ a[NR] = $1 } END { if (NR) print a[int((NR + 1) / 2)]; else print "-" }'
}
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg); rounds: $rounds"
printf '%-13s %11s %11s %11s %11s %8s %8s\n' case softgl-1 softgl-2 llvmpipe-1 llvmpipe-2 s1/l1 s2/l2
for c in $cases; do
  n=5; [ "$c" = create ] && n=20
  rm -f "$tmp/s1" "$tmp/s2" "$tmp/l1" "$tmp/l2"
  for r in $(seq "$rounds"); do
    run s1 "$c" $n SOFTGL_THREADS=1 LD_LIBRARY_PATH="$lib"
    run s2 "$c" $n SOFTGL_THREADS=2 LD_LIBRARY_PATH="$lib"
    if [ $mesa = 1 ]; then
      run l1 "$c" $n LP_NUM_THREADS=1 MESA_SHADER_CACHE_DISABLE=true
      run l2 "$c" $n LP_NUM_THREADS=2 MESA_SHADER_CACHE_DISABLE=true
    fi
  done
  # Rows in the order the client prints them (thrash-first before thrash).
  for row in $(cat "$tmp/s1" "$tmp/l1" 2>/dev/null | awk '!seen[$1]++ { print $1 }'); do
    # The work a frame does (ms x rate), when the client prints a rate.
    work=$(cat "$tmp/s1" "$tmp/l1" 2>/dev/null | awk -v r="$row" '$1 == r && NF >= 5 { print $2 * $4 " " $5; exit }')
    awk -v c="$row" -v a="$(med s1 "$row")" -v b="$(med s2 "$row")" -v x="$(med l1 "$row")" -v y="$(med l2 "$row")" -v w="$work" '
      function ms(v) { return v == "-" ? sprintf("%11s", "-") : sprintf("%8.2f ms", v) }
      function ratio(p, q) { return (p == "-" || q == "-" || q == 0) ? sprintf("%8s", "-") : sprintf("%7.2fx", p / q) }
      function rate(v) { return v == "-" ? " -" : sprintf(" %.1f", f[1] / v) }
      BEGIN {
        printf "%-13s %s %s %s %s %s %s", c, ms(a), ms(b), ms(x), ms(y), ratio(a, x), ratio(b, y)
        if (split(w, f, " ") == 2) printf "   %s:%s%s%s%s", f[2], rate(a), rate(b), rate(x), rate(y)
        printf "\n"
      }'
  done
done
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
[ $mesa = 1 ] || echo "SKIPPED llvmpipe columns: apt-get install libosmesa6-dev libglu1-mesa-dev"
exit $failed
