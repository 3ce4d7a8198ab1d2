#!/usr/bin/env bash
# `pseudoshadow doctor` as a newcomer meets it (README.md, "When something does not work"): without a display it
# says the headless path works (EGL and OSMesa ok here), marks the display missing with the way
# to a window, and exits 0; a copy of the program without its shared data says what is missing,
# how to fix it, and exits 1. Usage: doctor.sh PSEUDOSHADOW
set -uo pipefail
exe="$1"
fail() { echo "doctor test: $*" >&2; exit 1; }

out="$(env -u DISPLAY -u WAYLAND_DISPLAY "${exe}" doctor 2>&1)"
status=$?
echo "${out}"
[ "${status}" -eq 0 ] || fail "exit ${status} with a working headless path (expected 0)"
for line in '^ok +shared data ' '^ok +EGL +.*OpenGL 4\.[5-9]' '^ok +OSMesa +.*OpenGL 4\.[5-9]' \
            '^missing +display +DISPLAY is not set' 'fix: .*xvfb-run -a' '^missing +window +not tried' \
            '^(ok|note) +audio output ' '^(ok|note) +gamepads +[0-9]+ joystick' '^(ok|note) +real-time ' \
            '^the headless path works'; do
  grep -Eq "${line}" <<<"${out}" || fail "no line matching '${line}'"
done

# The program alone, in a temporary folder (no ancestor holds share/pseudoshadow, which the
# program looks for up to four folders above itself): the data line is missing, exit 1.
work="$(mktemp -d)" && mkdir -p "${work}/bin" || fail "cannot make a temporary folder"
trap 'rm -rf "${work}"' EXIT
cp "${exe}" "${work}/bin/" || fail "cannot copy the program"
out="$(env -u DISPLAY "${work}/bin/$(basename "${exe}")" doctor 2>&1)"
status=$?
echo "${out}"
[ "${status}" -eq 1 ] || fail "exit ${status} without the shared data (expected 1)"
grep -Eq '^missing +shared data +.*lacks glsl/surface.frag' <<<"${out}" || fail "the missing data is not named"
grep -Eq 'fix: .*cmake --install' <<<"${out}" || fail "no fix for the missing data"
grep -q 'the headless path does not work' <<<"${out}" || fail "no closing line saying the headless path fails"
echo "doctor test: ok"
