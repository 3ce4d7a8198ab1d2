# Sourced by the tools/*_xvfb.sh checks: starts Xvfb on a free-looking display number, exports
# DISPLAY and kills the server when the calling script exits.
display=":$(( 90 + RANDOM % 100 ))"
Xvfb "${display}" -screen 0 1024x768x24 >/dev/null 2>&1 &
xvfb_pid=$!
trap 'kill ${xvfb_pid} 2>/dev/null || true' EXIT
export DISPLAY="${display}"
sleep 1
