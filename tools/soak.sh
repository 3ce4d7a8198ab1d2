#!/usr/bin/env bash
# Hours of running (issue 33 §2, docs/hardening.md "Hours of running"): every shipped world live in
# the real window under Xvfb, explored by a scripted person (tools/soak/*.loop) for a chosen time;
# reports RSS after warm-up and at the end, the haptic rate and jitter p99 and the frame times in
# the first and the last tenth, and the proxy's drift between closed loops of the script.
#
#   tools/soak.sh [--minutes M] [--parallel N] [--out DIR] [--run-arg ARG ...] [SCENE ...]
#   tools/soak.sh --tour [--minutes M] [--out DIR]
#
# --tour: the Virtual Universe toured as a person does it, for the whole time: the loop is the
# window test's walk tests/window/walks/universe_tour.walk (panel -> each world by its button,
# the world used -> back by its own back button pressed with the pointer), and at every return
# it checks the panel at home, the shadow under the pointer and the panel's first buttons at
# their places (result.json `returns_failed`; one failure fails the soak).
#
# Defaults: 60 minutes a world, one world at a time (parallel worlds share the CPUs, so their
# rates say less), DIR soak_out, the worlds: the default scene, the Virtual Universe's panel (its
# loop presses all four world buttons and comes back) and each of its worlds, the bodies demo and
# the 4D surfaces. Writes DIR/<world>/ (readouts.jsonl, rss.csv, result.json, soak.svg) and
# DIR/soak.md, one table; exit 0 when every world meets the targets, 1 when one misses, 77 when
# xvfb-run or xdotool is missing. The binary is build/pseudoshadow (PS_BIN overrides it).
# --run-arg ARG passes one more argument to every `pseudoshadow run` (repeatable): many worlds
# at once on few cores want `--run-arg --spare-cpu --run-arg off`, or every one of them keeps to
# the same CPU (docs/hardening.md). With --parallel, the worlds start 3 s apart, so that their
# `xvfb-run -a` do not pick the same display number.
set -uo pipefail
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="${PS_BIN:-${repo_root}/build/pseudoshadow}"
minutes=60 parallel=1 out=soak_out scenes=() run_args=() loop_args=()
while (($#)); do
  case "$1" in
    --minutes) minutes="$2"; shift 2 ;;
    --parallel) parallel="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --run-arg) run_args+=("--run-arg=$2"); shift 2 ;;
    --tour) scenes=("${repo_root}/scenes/universe/panel.toml")
            loop_args=("--loop" "${repo_root}/tests/window/walks/universe_tour.walk"); shift ;;
    -h|--help) sed -n '2,25p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "soak.sh: unknown option '$1' (--minutes, --parallel, --out, --run-arg, --tour)" >&2; exit 2 ;;
    *) scenes+=("$1"); shift ;;
  esac
done
if ((${#scenes[@]} == 0)); then
  s="${repo_root}/scenes"
  scenes=("$s/default.toml" "$s/universe/panel.toml" "$s/universe/illusion.toml" "$s/universe/weight.toml"
          "$s/universe/field.toml" "$s/universe/poly.toml" "$s/fields_bodies_demo.toml"
          "$s/fourd/flat_torus.toml" "$s/fourd/flat_torus_rolling.toml" "$s/fourd/roman.toml"
          "$s/fourd/spun_trefoil.toml" "$s/fourd/twist_spun_trefoil.toml")
fi
[[ -x "$bin" ]] || { echo "soak.sh: no program at $bin: build first (README.md)" >&2; exit 2; }
# Checked here, not only in soak.py: xargs reports any child's non-zero status as 123, so a
# skipped world (77) would read as a failed one.
for tool in Xvfb xdotool; do
  command -v "$tool" > /dev/null || { echo "soak.sh: skipped, $tool is not installed (tools/bootstrap.sh installs it)"; exit 77; }
done
mkdir -p "$out"
echo "soak: ${#scenes[@]} worlds, ${minutes} min each, ${parallel} at a time, into ${out}"
# Each line "DELAY SCENE": the i-th world of a parallel batch waits 3*i s before it starts.
for i in "${!scenes[@]}"; do echo "$(( parallel > 1 ? (i % parallel) * 3 : 0 )) ${scenes[$i]}"; done |
  xargs -P "$parallel" -I{} bash -c 'sleep "${1%% *}"; exec python3 "${@:2}" "${1#* }"' soak {} \
    "${repo_root}/tools/soak.py" --exe "$bin" --minutes "$minutes" --out "$out" --progress "${run_args[@]}" "${loop_args[@]}"
rc=$?
# One table from every world's result.json (each soak.py run wrote a table of its own world).
python3 "${repo_root}/tools/soak.py" --table "$out" "${loop_args[@]}" "${scenes[@]}" || true
exit $(( rc == 0 ? 0 : 1 ))
