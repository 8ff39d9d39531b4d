#!/usr/bin/env bash
# Tries the Dzhanibekov window as a user would, under a virtual X server:
# opens it, takes screenshots, presses the keys, checks that they act, quits.
# Not part of CI (it needs an X server); run it by hand after changing the
# window code, and look at the screenshots it leaves.
#
# Needs (Debian): apt-get install -y xvfb xdotool x11-apps imagemagick
# Usage, from anywhere: bash examples/dzhanibekov/xvfb_check.sh [OUT_DIR]
# (default OUT_DIR: target/xvfb_check)
set -euo pipefail
cd "$(dirname "$0")/../.."
out=${1:-target/xvfb_check}
mkdir -p "$out"
cargo build --release --example dzhanibekov

number=77
while [ -e "/tmp/.X11-unix/X$number" ]; do number=$((number + 1)); done
export DISPLAY=":$number"
Xvfb "$DISPLAY" -screen 0 1280x720x24 >"$out/xvfb.log" 2>&1 &
xvfb=$!
demo=""
trap 'kill $demo $xvfb 2>/dev/null || true' EXIT
for _ in $(seq 50); do [ -e "/tmp/.X11-unix/X$number" ] && break; sleep 0.1; done

fail() { echo "xvfb_check: FAILED: $*" >&2; exit 1; }
# minifb sees a key only if it is down across one of its frames: hold it.
press() { xdotool keydown "$1"; sleep 0.15; xdotool keyup "$1"; sleep 0.3; }
shot() { xwd -root -silent >"$out/$1.xwd"; convert "xwd:$out/$1.xwd" "$out/$1.png"; }

target/release/examples/dzhanibekov >"$out/stdout.txt" 2>&1 &
demo=$!
window=$(timeout 20 xdotool search --sync --name "Dzhanibekov" | head -1) ||
  fail "no window opened"
xdotool windowfocus "$window"
sleep 4
shot running

press space
sleep 0.5
shot paused_a
sleep 1.5
shot paused_b
cmp -s "$out/paused_a.xwd" "$out/paused_b.xwd" || fail "space did not pause"
press space
sleep 1
shot resumed
cmp -s "$out/paused_b.xwd" "$out/resumed.xwd" && fail "space did not resume"

press 3
sleep 3
shot major
grep -q "spin: .* about the major axis" "$out/stdout.txt" || fail "3 did not restart about the major axis"
press equal
press equal
sleep 1
shot faster
press 2
sleep 2
press r
sleep 1
press q
for _ in $(seq 50); do kill -0 "$demo" 2>/dev/null || break; sleep 0.1; done
kill -0 "$demo" 2>/dev/null && fail "q did not quit"
wait "$demo" || fail "the demo exited with an error"
[ "$(grep -c '^restart$' "$out/stdout.txt")" = 3 ] || fail "expected 3 restarts (keys 3, 2, r)"
grep -q "^flip period: predicted .* s, simulated .* s" "$out/stdout.txt" || fail "no flip period line"
echo "xvfb_check: window opened, space paused and resumed, 3/2/r restarted, q quit."
echo "screenshots: $out/{running,paused_a,major,faster}.png; output: $out/stdout.txt"
