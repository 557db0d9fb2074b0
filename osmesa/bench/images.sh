#!/bin/sh
# The last frame of each case of osmesa/bench/fill.c (after one untimed frame
# and one timed) on softgl with 1 and 2 threads and on Mesa llvmpipe with 1,
# written as RGBA PAM and compared byte by byte: per case the pixels that
# differ and the largest difference of one channel, for softgl-1 against
# llvmpipe and softgl-2 against softgl-1 (threads must not change an image).
# Depth and stencil are not compared. Exits non-zero if a run fails (a GL
# error included). Not a test.
#   cargo build --release -p softgl-osmesa && sh osmesa/bench/images.sh [CASES...]
#   SOFTGL_LIB=DIR names the directory holding softgl's libOSMesa.so.8;
#   KEEP=DIR keeps the images there.
set -e
here=$(cd "$(dirname "$0")" && pwd)
lib=${SOFTGL_LIB:-$here/../../target/release/osmesa}
cases=${*:-fill quads200 depth fog tris ops xor thrash tex lit litlist clear clearall}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
out=${KEEP:-$tmp}; mkdir -p "$out"
if [ ! -e /usr/lib/x86_64-linux-gnu/libOSMesa.so.8 ] || ! cc -O2 "$here/fill.c" -o "$tmp/fill" -lOSMesa -lGLU -lm; then
  echo "SKIPPED images against llvmpipe: apt-get install libosmesa6-dev libglu1-mesa-dev"; exit 0
fi
# diff A B: "PIXELS MAX" over the RGBA bytes after the header (cmp -l prints
# each differing byte's 1-based offset and both values in octal).
diff() {
  hdr=$(( $(wc -c <"$1") - 1024 * 1024 * 4 ))
  cmp -l "$1" "$2" | awk -v h="$hdr" '
    function oct(s,  v, i) { v = 0; for (i = 1; i <= length(s); i++) v = v * 8 + substr(s, i, 1); return v }
    { p = int(($1 - 1 - h) / 4); if (p != last) { n++; last = p }
      d = oct($2) - oct($3); if (d < 0) d = -d; if (d > m) m = d }
    BEGIN { last = -1 } END { print n + 0, m + 0 }' || true
}
failed=0
printf '%-9s %26s %26s\n' case "softgl-1 vs llvmpipe-1" "softgl-2 vs softgl-1"
printf '%-9s %13s %12s %13s %12s\n' "" "pixels" "max" "pixels" "max"
for c in $cases; do
  for v in s1 s2 l1; do
    case $v in
      s1) set -- SOFTGL_THREADS=1 LD_LIBRARY_PATH="$lib" ;;
      s2) set -- SOFTGL_THREADS=2 LD_LIBRARY_PATH="$lib" ;;
      l1) set -- LP_NUM_THREADS=1 ;;
    esac
    env "$@" "$tmp/fill" "$c" 1 -o "$out/$c.$v.pam" >/dev/null 2>"$tmp/err" ||
      { echo "FAILED $v $c: $(tr '\n' ' ' <"$tmp/err")" >&2; failed=1; }
  done
  [ -e "$out/$c.s1.pam" ] && [ -e "$out/$c.l1.pam" ] && a=$(diff "$out/$c.s1.pam" "$out/$c.l1.pam") || a="- -"
  [ -e "$out/$c.s1.pam" ] && [ -e "$out/$c.s2.pam" ] && b=$(diff "$out/$c.s2.pam" "$out/$c.s1.pam") || b="- -"
  echo "$c $a $b" | awk '{ printf "%-9s %13s %12s %13s %12s\n", $1, $2, $3, $4, $5 }'
done
exit $failed
