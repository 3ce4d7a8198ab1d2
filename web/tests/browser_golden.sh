#!/usr/bin/env bash
# ctest browser.golden (tests/browser/CMakeLists.txt): builds the page (target web_page) and runs
# web/tests/golden_in_browser.mjs on it. Exit 77 (skipped) when a tool it needs is missing.
#   bash web/tests/browser_golden.sh BUILD_DIR
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="${1:?usage: browser_golden.sh BUILD_DIR}"
missing=()
command -v em++ > /dev/null || missing+=("em++ (apt-get install emscripten)")
command -v "${PSEUDOSHADOW_CHROMIUM:-chromium}" > /dev/null || missing+=("chromium (apt-get install chromium)")
command -v node > /dev/null || missing+=("node (apt-get install nodejs)")
[[ -d "$root/web/node_modules/puppeteer-core" ]] || missing+=("web/node_modules (npm ci --prefix web)")
if (( ${#missing[@]} > 0 )); then
  echo "browser.golden: skipped: missing ${missing[*]}"
  exit 77
fi
cmake --build "$build" --target web_page
node "$root/web/tests/golden_in_browser.mjs" "$build/web" "$build/web_golden_out"
