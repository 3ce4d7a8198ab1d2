#!/usr/bin/env bash
# Byte identity of a refactoring: what the program draws and logs, before and after.
#   tools/byte_identity.sh render DIR     renders every shipped scene (256x256, 2 frames), replays
#                                         every shipped walk (frames + event log + recording) and
#                                         runs two scripted maze participants headless, into DIR
#   tools/byte_identity.sh compare A B    compares two such directories: every image with
#                                         `compare --fail 0`, every other file with cmp; exit 1
#                                         on the first kind of difference, listing them all
# The binary is build/pseudoshadow of this tree (PS_BIN overrides it).
set -uo pipefail

repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="${PS_BIN:-${repo_root}/build/pseudoshadow}"

die() { echo "byte_identity: error: $*" >&2; exit 2; }

# name | scene (empty: the default) | log | extra replay options. The walks' fps keeps each replay
# to at most ~60 frames (128x128: the pointer log's window); --show-* draw the world view (probe, device ghost, 4D path) too.
readonly kWalks=(
  "hover_centre||trajectory:tests/app/data/hover_centre.traj|--fps 1"
  "hover_right||trajectory:tests/app/data/hover_right.traj|--fps 1 --show-probe"
  "monkey_head|scenes/table5_1_monkey_head.toml|trajectory:tests/app/data/monkey_head.traj|--fps 1"
  "sweep_ptr||pointer:tests/devices/data/sweep.ptr|--show-device"
  "flat_torus_roll|scenes/fourd/flat_torus_rolling.toml|trajectory:tests/fourd/data/flat_torus_roll.traj|--fps 12 --show-path --show-device"
  "flat_torus_stroke|scenes/fourd/flat_torus.toml|trajectory:tests/fourd/data/flat_torus_stroke.traj|--fps 12 --show-path"
  "roman_crossing|scenes/fourd/roman.toml|trajectory:tests/fourd/data/roman_crossing.traj|--fps 20 --show-path"
  "roman_stroke|scenes/fourd/roman.toml|trajectory:tests/fourd/data/roman_stroke.traj|--fps 12"
  "spun_trefoil|scenes/fourd/spun_trefoil.toml|trajectory:tests/fourd/data/spun_trefoil_stroke.traj|--fps 12 --show-path"
  "twist_spun_trefoil|scenes/fourd/twist_spun_trefoil.toml|trajectory:tests/fourd/data/twist_spun_trefoil_stroke.traj|--fps 12"
  "press_buttons|scenes/buttons_demo.toml|trajectory:tests/haptics/data/press_buttons.traj|--fps 15"
  "stroke||trajectory:tests/haptics/data/stroke.traj|--fps 30 --show-probe --show-device"
  "field_navigate|scenes/universe/field.toml|trajectory:tests/haptics/data/universe_field_navigate.traj|--fps 20"
  "field_points|scenes/universe/field.toml|trajectory:tests/haptics/data/universe_field_points.traj|--fps 20"
  "illusion_slide|scenes/universe/illusion.toml|trajectory:tests/haptics/data/universe_illusion_slide.traj|--fps 20 --show-probe"
  "poly_press|scenes/universe/poly.toml|trajectory:tests/haptics/data/universe_poly_press.traj|--fps 20"
  "to_weight|scenes/universe/panel.toml|trajectory:tests/haptics/data/universe_to_weight.traj|--fps 30"
  "weight_drop|scenes/universe/weight.toml|trajectory:tests/haptics/data/universe_weight_drop.traj|--fps 20"
  "stroke_r25|scenes/table4_1_a.toml|trajectory:tests/vibration/data/stroke_r25.traj|--fps 15"
)

render_all() {
  local out="$1" f name
  [ -x "${bin}" ] || die "no ${bin}: build the pseudoshadow target first"
  rm -rf "${out}" && mkdir -p "${out}/scenes" "${out}/walks" "${out}/maze" || die "cannot make ${out}"
  cd "${repo_root}" || die "no ${repo_root}"
  # A cold picture cache: button pictures and field maps are made by this binary, not found.
  PSEUDOSHADOW_CACHE_DIR="$(mktemp -d)" || die "no temporary directory"
  export PSEUDOSHADOW_CACHE_DIR
  for f in scenes/*.toml scenes/universe/*.toml scenes/fourd/*.toml; do
    name="$(echo "${f%.toml}" | sed 's|^scenes/||; s|/|_|g')"
    "${bin}" render --scene "${f}" --size 256x256 --frames 2 --out "${out}/scenes/${name}.png" \
      --stats "${out}/scenes/${name}.stats.json" -q > "${out}/scenes/${name}.txt" 2>&1 ||
      echo "render ${f}: failed (see ${out}/scenes/${name}.txt)"
  done
  local walk scene log extra
  for walk in "${kWalks[@]}"; do
    IFS='|' read -r name scene log extra <<< "${walk}"
    local -a scene_opt=()
    [ -n "${scene}" ] && scene_opt=(--scene "${scene}")
    # shellcheck disable=SC2086  # extra: several options
    "${bin}" replay "${scene_opt[@]}" --log "${log}" --size 128x128 --out "${out}/walks/${name}" ${extra} \
      --record "${out}/walks/${name}.record.log" -q > "${out}/walks/${name}.txt" 2>&1 ||
      echo "replay ${name}: failed (see ${out}/walks/${name}.txt)"
  done
  local maze=scenes/maze/maze.toml
  "${bin}" maze script --maze "${maze}" --seed 7 --errors 2 --out "${out}/maze/p01.traj" > /dev/null 2>&1 &&
    "${bin}" maze --maze "${maze}" --participant P01 --seed 7 --cues on --device "trajectory:${out}/maze/p01.traj" \
      --out "${out}/maze/p01" --every 30 > "${out}/maze/p01.txt" 2>&1 ||
    echo "maze P01: failed (see ${out}/maze/p01.txt)"
  "${bin}" maze script --maze "${maze}" --seed 8 --errors 1 --passes 3 --out "${out}/maze/p02.traj" > /dev/null 2>&1 &&
    "${bin}" maze --maze "${maze}" --participant P02 --seed 8 --cues off --device "trajectory:${out}/maze/p02.traj" \
      --out "${out}/maze/p02" --every 45 > "${out}/maze/p02.txt" 2>&1 ||
    echo "maze P02: failed (see ${out}/maze/p02.txt)"
  rm -rf "${PSEUDOSHADOW_CACHE_DIR}"
  echo "byte_identity: $(find "${out}" -name '*.png' | wc -l) images, $(find "${out}" -type f ! -name '*.png' | wc -l) other files in ${out}"
}

# What carries the machine rather than the program: times in the stats (every "*_ms" member and
# the timing tables), the wall-clock time a maze session started (session_start's started_at) and
# the output directory's own path (in logs and messages). How many pixels
# a frame drew (drawn_pixels, incremental) says how, not what: incremental frames draw the same
# bytes.
normalise() {
  local file="$1" dir="$2"
  case "${file}" in
    *.stats.json)
      python3 -c 'import json, sys
def keep(v):
    if isinstance(v, dict):
        return {k: keep(x) for k, x in v.items() if not (k.endswith("_ms") or k.endswith("timings_lag") or k in ("drawn_pixels", "incremental"))}
    return [keep(x) for x in v] if isinstance(v, list) else v
print(json.dumps(keep(json.load(open(sys.argv[1]))), indent=1, sort_keys=True))' "${file}" ;;
    *.jsonl) sed "s|${dir}|DIR|g; s|\"started_at\":\"[^\"]*\"|\"started_at\":\"TIME\"|g" "${file}" ;;
    *) sed "s|${dir}|DIR|g" "${file}" ;;
  esac
}

compare_dirs() {
  local a="$1" b="$2" rel images=0 others=0 bad=0
  [ -d "${a}" ] && [ -d "${b}" ] || die "compare needs two directories (got '${a}', '${b}')"
  [ -x "${bin}" ] || die "no ${bin}"
  while IFS= read -r rel; do
    if [ ! -e "${b}/${rel}" ]; then echo "missing in ${b}: ${rel}"; bad=$((bad + 1)); continue; fi
    if [[ "${rel}" == *.png ]]; then
      images=$((images + 1))
      "${bin}" compare --fail 0 "${a}/${rel}" "${b}/${rel}" > /dev/null 2>&1 || { echo "image differs: ${rel}"; bad=$((bad + 1)); }
    else
      others=$((others + 1))
      cmp -s <(normalise "${a}/${rel}" "${a}") <(normalise "${b}/${rel}" "${b}") || { echo "file differs: ${rel}"; bad=$((bad + 1)); }
    fi
  done < <(cd "${a}" && find . -type f | sed 's|^\./||' | sort)
  while IFS= read -r rel; do
    [ -e "${a}/${rel}" ] || { echo "extra in ${b}: ${rel}"; bad=$((bad + 1)); }
  done < <(cd "${b}" && find . -type f | sed 's|^\./||' | sort)
  echo "byte_identity: ${images} images (compare --fail 0), ${others} other files (cmp); ${bad} differ"
  [ "${bad}" -eq 0 ]
}

case "${1:-}" in
  render) [ $# -eq 2 ] || die "usage: $0 render DIR"; render_all "$2" ;;
  compare) [ $# -eq 3 ] || die "usage: $0 compare A B"; compare_dirs "$2" "$3" ;;
  *) die "usage: $0 render DIR | $0 compare A B" ;;
esac
