// The guard in front of toml++ (scene/toml_text.h): text that would make toml++ 3.3.0 reach
// __builtin_unreachable() is refused with its line; every other document parses as before.
// Under the sanitizer build, UBSan makes the undefined behaviour fatal, so the cases that
// reach toml++ here also show the guard lets nothing through that trips it.
#include <gtest/gtest.h>

#include <string>

#include "scene/toml_text.h"

namespace ps {
namespace {

std::string utf8(char32_t c) {
  std::string out;
  if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
  } else {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
  }
  out += static_cast<char>(0x80 | (c & 0x3F));
  return out;
}

TEST(TomlTextTest, TheFuzzersFindingsAreRefusedWithTheirLine) {
  const Result<toml::table> after_key = parse_toml("a = 1\naeud\xC2\xA7V d", "m.toml");
  ASSERT_FALSE(after_key);
  EXPECT_EQ(after_key.error().message,
            "m.toml:2: syntax error: a non-ASCII character (byte 0xC2) outside a string or comment; "
            "TOML allows them only inside strings and comments");
  const Result<toml::table> backslash = parse_toml("s = \"\"\"\\\n  \xC2\xA7\"\"\"\n", "s.toml");
  ASSERT_FALSE(backslash);
  EXPECT_NE(backslash.error().message.find("s.toml:2: syntax error: a non-ASCII character (byte 0xC2) right after "
                                           "a line-ending backslash"),
            std::string::npos)
      << backslash.error().message;
}

// Every code point from U+0080 to U+33FF (the ranges toml++'s whitespace table covers) inside a
// basic, literal and multi-line string and a comment: passes the guard and parses to itself.
TEST(TomlTextTest, NonAsciiInsideStringsAndCommentsParsesUnchanged) {
  for (char32_t c = 0x80; c < 0x3400; ++c) {
    if (c >= 0xD800 && c <= 0xDFFF) continue;
    const std::string ch = utf8(c);
    const std::string doc = "a = \"x" + ch + "\"\nb = 'x" + ch + "'\nc = \"\"\"\nx" + ch + "\"\"\"\n# " + ch + "\n";
    Result<toml::table> t = parse_toml(doc, "u.toml");
    ASSERT_TRUE(t) << "U+" << std::hex << static_cast<unsigned>(c) << ": " << t.error().message;
    EXPECT_EQ((*t)["a"].value<std::string>().value_or(""), "x" + ch);
    EXPECT_EQ((*t)["c"].value<std::string>().value_or(""), "x" + ch);
  }
}

TEST(TomlTextTest, QuotesAndEscapesDoNotConfuseTheStates) {
  // An escaped quote, a multi-line string closed by four quotes (one belongs to the text), a
  // literal string holding a '#': the text after each is still outside a string.
  EXPECT_TRUE(parse_toml("a = \"q\\\"\xC3\xA9\"\nb = \"\"\"x\"\"\"\"\nc = '#'\n", "q.toml"));
  EXPECT_FALSE(parse_toml("a = \"q\\\"\"\nb = \xC3\xA9\n", "q.toml"));
  EXPECT_FALSE(parse_toml("b = \"\"\"x\"\"\"\"\nc = \xC3\xA9\n", "q.toml"));
  EXPECT_FALSE(parse_toml("c = '#'\nd = 1 \xC3\xA9\n", "q.toml"));
}

TEST(TomlTextTest, AByteOrderMarkIsAccepted) {
  Result<toml::table> t = parse_toml("\xEF\xBB\xBFx = 1\n", "bom.toml");
  ASSERT_TRUE(t) << t.error().message;
  EXPECT_EQ((*t)["x"].value<int>().value_or(0), 1);
}

TEST(TomlTextTest, SyntaxErrorsKeepTheirFormat) {
  const Result<toml::table> t = parse_toml("[a\n", "e.toml");
  ASSERT_FALSE(t);
  EXPECT_EQ(t.error().message.rfind("e.toml:1: syntax error: ", 0), 0u) << t.error().message;
}

}  // namespace
}  // namespace ps
