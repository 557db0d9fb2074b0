#!/bin/sh
# softgl's libOSMesa.so.8 against Mesa's llvmpipe (1 and 2 threads), the same
# client (osmesa/bench/fill.c; `tex` is the textured frame of issue 12),
# interleaved round by round; prints the median of
# the rounds' medians per case and the ratio softgl / llvmpipe. Not a test.
#   cargo build --release -p softgl-osmesa && sh osmesa/bench/compare.sh [ROUNDS] [CASES...]
# (The cost of one attribute call, glColor3f, glVertex3f, ...: osmesa/bench/calls.c, run as its header says.)
set -e
here=$(cd "$(dirname "$0")" && pwd)
lib=${SOFTGL_LIB:-$here/../../target/release/osmesa}
rounds=${1:-3}; [ $# -gt 0 ] && shift
cases=${*:-fill depth tris lit tex}
bin=$(mktemp -d)/fill
cc -O2 "$here/fill.c" -o "$bin" -lOSMesa -lGLU -lm
median() { sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
printf '%-6s %12s %12s %12s %10s %10s\n' case softgl llvmpipe-1 llvmpipe-2 ratio-1 ratio-2
for c in $cases; do
  s=""; l1=""; l2=""
  for r in $(seq "$rounds"); do
    s="$s $(LD_LIBRARY_PATH=$lib "$bin" "$c" 5 | awk '{print $2}')"
    l1="$l1 $(LP_NUM_THREADS=1 "$bin" "$c" 5 | awk '{print $2}')"
    l2="$l2 $(LP_NUM_THREADS=2 "$bin" "$c" 5 | awk '{print $2}')"
  done
  ms=$(echo $s | tr ' ' '\n' | median); m1=$(echo $l1 | tr ' ' '\n' | median); m2=$(echo $l2 | tr ' ' '\n' | median)
  awk -v c="$c" -v s="$ms" -v a="$m1" -v b="$m2" \
    'BEGIN { printf "%-6s %9.2f ms %9.2f ms %9.2f ms %9.2fx %9.2fx\n", c, s, a, b, s / a, s / b }'
done
