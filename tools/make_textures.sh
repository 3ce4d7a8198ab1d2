#!/usr/bin/env bash
# Regenerates textures/*.png (albedo textures and the height-field image used by scenes/).
# Needs python3 (standard library only) and oiiotool (Debian: openimageio-tools).
# The output is deterministic (fixed seeds), so re-running leaves the committed PNGs unchanged.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
python3 "$root/tools/make_textures.py" "$tmp"
mkdir -p "$root/textures"
for f in "$tmp"/*.ppm "$tmp"/*.pgm; do
  name="$(basename "${f%.*}")"
  # --nosoftwareattrib: no command line (with this machine's paths) in the PNG's metadata
  oiiotool --nosoftwareattrib "$f" -d uint8 -o "$root/textures/$name.png"
  echo "wrote textures/$name.png"
done
