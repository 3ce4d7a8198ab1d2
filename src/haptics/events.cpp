#include "haptics/events.h"

#include <algorithm>
#include <cstdio>

namespace ps {

std::string_view event_name(EventKind kind) {
  switch (kind) {
    case EventKind::contact_start: return "contact_start";
    case EventKind::contact_end: return "contact_end";
    case EventKind::button_fired: return "button_fired";
    case EventKind::body_impact: return "body_impact";
    case EventKind::charge_added: return "charge_added";
    case EventKind::charge_removed: return "charge_removed";
    case EventKind::scene_switched: return "scene_switched";
    case EventKind::flag_toggled: return "flag_toggled";
    case EventKind::sheet_crossing: return "sheet_crossing";
    case EventKind::tick_stall: return "tick_stall";
  }
  return "unknown";
}

void HapticEvent::set_label(std::string_view s) {
  label.fill('\0');
  const std::size_t n = std::min(s.size(), label.size() - 1);
  std::copy_n(s.data(), n, label.data());
}

std::string_view HapticEvent::label_view() const {
  return std::string_view(label.data(), std::find(label.begin(), label.end(), '\0') - label.begin());
}

namespace {
void append_double(std::string& out, double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  out += buf;
}
void append_string(std::string& out, std::string_view s) {
  out += '"';
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
      out += buf;
    } else {
      out += c;
    }
  }
  out += '"';
}
}  // namespace

HapticEvent make_event(EventKind kind, std::uint64_t tick, double time_s) {
  HapticEvent e;
  e.kind = kind;
  e.tick = tick;
  e.time_s = time_s;
  return e;
}

std::string event_json(const HapticEvent& e) {
  std::string out = "{\"t\":";
  append_double(out, e.time_s);
  out += ",\"tick\":" + std::to_string(e.tick) + ",\"event\":";
  append_string(out, event_name(e.kind));
  out += ",\"surface\":" + std::to_string(e.surface) + ",\"index\":" + std::to_string(e.index) + ",\"value\":";
  append_double(out, e.value);
  out += ",\"pos\":[";
  for (int i = 0; i < 3; ++i) {
    if (i) out += ',';
    append_double(out, e.position_mm[i]);
  }
  out += "],\"label\":";
  append_string(out, e.label_view());
  out += '}';
  return out;
}

EventQueue::EventQueue(std::size_t capacity) : ring_(std::max<std::size_t>(capacity, 1)) {}

bool EventQueue::push(const HapticEvent& e) {
  const std::size_t head = head_.load(std::memory_order_relaxed);
  if (head - tail_.load(std::memory_order_acquire) >= ring_.size()) {
    dropped_.fetch_add(1, std::memory_order_relaxed);
    return false;
  }
  ring_[head % ring_.size()] = e;
  head_.store(head + 1, std::memory_order_release);
  return true;
}

}  // namespace ps
