#!/usr/bin/env bash
# A file-size limit reached while a maze session logs (`ulimit -f`, as a quota or a small disk
# would stop it; docs/hardening.md, "Faults"): the session stops at once with one line naming the
# file and the error, exit 1, not killed by SIGXFSZ; its session log is whole lines (every line
# JSON), and `maze --resume` (the limit lifted) finishes the session.
# Usage: maze_file_limit.sh PSEUDOSHADOW WORKDIR
set -u
exe=$1 work=$2
rm -rf "${work}" && mkdir -p "${work}" || exit 1
cd "${work}" || exit 1
"${exe}" maze script --seed 9 --out p.traj > /dev/null || { echo "FAIL: maze script"; exit 1; }
# 8 KiB: the session log's first lines fit, the device stream (~40 B a tick) fills it in 0.2 s.
( ulimit -f 8; "${exe}" maze -q --participant L1 --seed 9 --cues on --device trajectory:p.traj --out s ) > out.txt 2>&1
rc=$?
cat out.txt
[ "${rc}" -eq 1 ] || { echo "FAIL: exit ${rc}, expected 1 (153 is SIGXFSZ: killed without a word)"; exit 1; }
grep -q "^pseudoshadow maze: s/device.log.partial: cannot write device log: File too large" out.txt ||
  { echo "FAIL: no line naming the file and the error"; exit 1; }
python3 - s/session.jsonl <<'PY' || { echo "FAIL: the session log is not whole JSON lines"; exit 1; }
import json, sys
text = open(sys.argv[1]).read()
assert text.endswith("\n"), "the last line is cut"
lines = text.splitlines()
assert json.loads(lines[0])["type"] == "session_start"
for l in lines:
    json.loads(l)
print(f"session log: {len(lines)} whole lines")
PY
"${exe}" maze --resume s -q || { echo "FAIL: --resume after the limit"; exit 1; }
tail -n 1 s/session.jsonl | grep -q '"type":"session_end","reason":"criterion"' ||
  { echo "FAIL: the resumed session did not end by the criterion"; exit 1; }
echo "ok: stopped with one line at the file-size limit, resumed to the end"
