#!/bin/bash
# Runs RtkitTest.* against a real rtkit-daemon: a private system bus (dbus-daemon with a config of
# its own, so the machine's bus is not touched) and rtkit-daemon on it, found through
# DBUS_SYSTEM_BUS_ADDRESS. rtkit-daemon must start as root (it chroots and drops to its user);
# elsewhere, or without dbus-daemon / rtkit-daemon, the test is skipped. rtkit-daemon asks
# PolicyKit before granting; FAKE_POLKIT stands in for it on the private bus and says yes.
# Usage: rtkit_check.sh RTKIT_TEST FAKE_POLKIT
set -u
test_bin="$1"
fake_polkit="$2"
daemon=/usr/libexec/rtkit-daemon
if [ "$(id -u)" != 0 ] || ! command -v dbus-daemon > /dev/null || [ ! -x "${daemon}" ]; then
  echo "SKIPPED: needs root, dbus-daemon and ${daemon} (Debian packages dbus, rtkit)"
  exit 0
fi
work="$(mktemp -d)"
trap 'kill ${bus_pid:-} ${rtkit_pid:-} ${polkit_pid:-} 2> /dev/null; rm -rf "${work}"' EXIT
cat > "${work}/bus.conf" << CONF
<!DOCTYPE busconfig PUBLIC "-//freedesktop//DTD D-BUS Bus Configuration 1.0//EN"
 "http://www.freedesktop.org/standards/dbus/1.0/busconfig.dtd">
<busconfig>
  <type>system</type>
  <listen>unix:path=${work}/bus</listen>
  <auth>EXTERNAL</auth>
  <policy context="default"><allow user="*"/><allow own="*"/><allow send_destination="*"/><allow receive_sender="*"/></policy>
</busconfig>
CONF
# To a file, not $(...): the forked daemon would hold the substitution's pipe open.
dbus-daemon --config-file="${work}/bus.conf" --fork --print-pid > "${work}/bus.pid" || exit 1
bus_pid="$(cat "${work}/bus.pid")"
export DBUS_SYSTEM_BUS_ADDRESS="unix:path=${work}/bus"
"${fake_polkit}" &
polkit_pid=$!
# rtkit-daemon limits its own file size to 0: its log goes through a pipe, never to a file.
"${daemon}" --stderr --no-canary 2>&1 < /dev/null | cat > "${work}/rtkit.log" &
for _ in $(seq 50); do
  timeout 2 dbus-send --system --print-reply --dest=org.freedesktop.DBus /org/freedesktop/DBus \
    org.freedesktop.DBus.ListNames 2> /dev/null | grep -q RealtimeKit1 && break
  sleep 0.1
done
rtkit_pid="$(pgrep -f -n "${daemon}")"
PS_TEST_RTKIT=1 "${test_bin}" --gtest_filter='RtkitTest.*'
status=$?
[ ${status} = 0 ] || cat "${work}/rtkit.log"
exit ${status}
