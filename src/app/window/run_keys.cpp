#include "app/window/run_keys.h"

#include <algorithm>
#include <cassert>
#include <cstring>
#include <vector>

namespace ps {

namespace {

// Mouse first (what a person tries first), then the keys. Actions stay short: the help overlay
// shows the table in two columns in a 512-pixel window beside the shadow and the panel.
constexpr RunKey kRunKeys[] = {
    {"mouse", "move probe"},
    {"scroll", "probe height"},
    {"PgUp / PgDn", "height 0.5 mm"},
    {"right drag", "orbit camera"},
    {"Shift+scroll", "zoom"},
    {"C, Shift+C", "charge +/-"},
    {"1-3 / Shift", "4D xy xz xw"},
    {"4-6 / Shift", "4D yz yw zw"},
    {"Bksp", "back a scene"},
    {"Home", "view home"},
    {"M", "grab mouse"},
    {"P / D", "probe / hand"},
    {"S", "screenshot"},
    {"F1", "panel"},
    {"H, ?", "this help"},
    {"Esc, Q", "quit"},
};

constexpr const char* kShadowLegend[] = {
    "The shadow: darker = closer, solid = touching;",
    "its texture shows while the probe moves.",
};

// Rows as "KEYS  action" cells: keys padded to the widest key plus `gap` spaces, cells padded
// to the widest cell.
std::vector<std::string> cells(std::span<const RunKey> rows, size_t gap) {
  size_t keys = 0, width = 0;
  for (const RunKey& k : rows) keys = std::max(keys, std::strlen(k.keys));
  std::vector<std::string> out;
  for (const RunKey& k : rows) {
    std::string c = k.keys;
    c.append(keys - c.size() + gap, ' ');
    out.push_back(c + k.action);
    width = std::max(width, out.back().size());
  }
  for (std::string& c : out) c.resize(width, ' ');
  return out;
}

}  // namespace

std::span<const RunKey> run_keys() { return kRunKeys; }

std::span<const char* const> shadow_legend() { return kShadowLegend; }

std::string run_keys_text(const std::string& indent, int columns) {
  assert(columns >= 1 && "run_keys_text: at least one column");
  const std::span<const RunKey> all = kRunKeys;
  const size_t per = (all.size() + columns - 1) / columns;
  // One column has room for two spaces after the keys; two columns must fit beside the panel.
  const size_t gap = columns == 1 ? 2 : 1;
  std::vector<std::vector<std::string>> cols;
  for (size_t i = 0; i < all.size(); i += per)
    cols.push_back(cells(all.subspan(i, std::min(per, all.size() - i)), gap));
  std::string out;
  for (size_t row = 0; row < per; ++row) {
    std::string line = indent;
    for (size_t c = 0; c < cols.size(); ++c)
      if (row < cols[c].size()) line += (c ? "  " : "") + cols[c][row];
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out += line + "\n";
  }
  return out;
}

}  // namespace ps
