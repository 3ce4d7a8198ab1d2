#include "scene/toml_text.h"

#include <algorithm>
#include <cstdio>

namespace ps {

namespace {

constexpr std::string_view kMultiBasicQuote = R"(""")";
constexpr std::string_view kMultiLiteralQuote = R"(''')";

enum class State { kNormal, kComment, kBasic, kLiteral, kMultiBasic, kMultiLiteral };

bool starts(std::string_view text, std::size_t i, std::string_view what) { return text.substr(i, what.size()) == what; }

// After a closing """ or ''', TOML allows one or two more quotes of the string's own.
std::size_t close_multi(std::string_view text, std::size_t i, char quote) {
  std::size_t end = i + 3;
  while (end < text.size() && text[end] == quote && end < i + 5) ++end;
  return end;
}

// Where a multi-line basic string's line-ending backslash at `i` stops skipping: the first
// character that is not a space, tab or line break (text.size() if none).
std::size_t after_line_ending_backslash(std::string_view text, std::size_t i) {
  std::size_t j = i + 1;
  while (j < text.size() && (text[j] == ' ' || text[j] == '\t')) ++j;
  if (j >= text.size() || (text[j] != '\n' && text[j] != '\r')) return std::string_view::npos;
  while (j < text.size() && (text[j] == ' ' || text[j] == '\t' || text[j] == '\n' || text[j] == '\r')) ++j;
  return j;
}

Status refuse(std::string_view text, std::size_t at, const std::string& source_name, const char* where) {
  const long line = 1 + static_cast<long>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
  char hex[8];
  std::snprintf(hex, sizeof hex, "%02X", static_cast<unsigned char>(text[at]));
  return make_error(source_name + ":" + std::to_string(line) + ": syntax error: a non-ASCII character (byte 0x" +
                    hex + ") " + where + "; TOML allows them only inside strings and comments");
}

}  // namespace

// One state machine over the text, whole: its states read together (split, each would need
// the others' transitions).
Status check_toml_text(std::string_view text, const std::string& source_name) {
  State s = State::kNormal;
  const std::size_t bom = text.starts_with("\xEF\xBB\xBF") ? 3 : 0;  // toml++ skips a UTF-8 BOM
  for (std::size_t i = bom; i < text.size(); ++i) {
    const char c = text[i];
    switch (s) {
      case State::kNormal:
        if (static_cast<unsigned char>(c) >= 0x80) return refuse(text, i, source_name, "outside a string or comment");
        if (c == '#') {
          s = State::kComment;
        } else if (starts(text, i, kMultiBasicQuote)) {
          s = State::kMultiBasic;
          i += 2;
        } else if (starts(text, i, kMultiLiteralQuote)) {
          s = State::kMultiLiteral;
          i += 2;
        } else if (c == '"') {
          s = State::kBasic;
        } else if (c == '\'') {
          s = State::kLiteral;
        }
        break;
      case State::kComment:
        if (c == '\n') s = State::kNormal;
        break;
      case State::kBasic:
        if (c == '\\') ++i;
        else if (c == '"' || c == '\n') s = State::kNormal;
        break;
      case State::kLiteral:
        if (c == '\'' || c == '\n') s = State::kNormal;
        break;
      case State::kMultiBasic:
        if (c == '\\') {
          const std::size_t next = after_line_ending_backslash(text, i);
          if (next == std::string_view::npos) {  // an escape: skip the escaped character
            ++i;
            break;
          }
          if (next < text.size() && static_cast<unsigned char>(text[next]) >= 0x80)
            return refuse(text, next, source_name, "right after a line-ending backslash");
          i = next - 1;
        } else if (starts(text, i, kMultiBasicQuote)) {
          i = close_multi(text, i, '"') - 1;
          s = State::kNormal;
        }
        break;
      case State::kMultiLiteral:
        if (starts(text, i, kMultiLiteralQuote)) {
          i = close_multi(text, i, '\'') - 1;
          s = State::kNormal;
        }
        break;
    }
  }
  return ok_status();
}

Result<toml::table> parse_toml(std::string_view text, const std::string& source_name) {
  if (Status s = check_toml_text(text, source_name); !s) return s.error();
  try {
    return toml::parse(text, source_name);
  } catch (const toml::parse_error& e) {
    const auto line = std::max<long>(1, static_cast<long>(e.source().begin.line));
    return make_error(source_name + ":" + std::to_string(line) + ": syntax error: " + std::string(e.description()));
  }
}

}  // namespace ps
