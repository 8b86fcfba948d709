// User text on its way to a terminal: controls escaped, printable UTF-8 kept, long text cut with a count.
#include "base/terminal_text.h"

#include <gtest/gtest.h>

#include <string>

namespace tcsb {
namespace {

TEST(TerminalText, ControlsAreEscaped) {
  EXPECT_EQ(terminal_safe("plain text"), "plain text");
  EXPECT_EQ(terminal_safe("\x1b[2Jx"), "\\x1b[2Jx");
  EXPECT_EQ(terminal_safe(std::string("a\0b", 3)), "a\\x00b");
  EXPECT_EQ(terminal_safe("tab\there\x7f"), "tab\\x09here\\x7f");
  EXPECT_EQ(terminal_safe("\xc2\x9b"
                          "31m"),
            "\\u009b31m");  // C1 CSI, which some terminals obey like ESC [
}

TEST(TerminalText, Utf8IsKeptAndInvalidBytesEscaped) {
  const std::string printable = "Kr\xc3\xb6mker \xe2\x80\x94 \xf0\x9f\x99\x82";  // o-umlaut, em dash, emoji
  EXPECT_EQ(terminal_safe(printable), printable);
  EXPECT_EQ(terminal_safe("\xff\xc3"), "\\xff\\xc3");  // a stray byte, a truncated sequence
  EXPECT_EQ(terminal_safe("\xc0\xaf"), "\\xc0\\xaf");  // overlong '/'
}

TEST(TerminalText, LongTextIsCutWithACount) {
  const std::string text(1000, 'k');
  const std::string cut = terminal_safe(text, 500);
  std::string expected(500, 'k');  // appended, not std::string(500, 'k') + "...": GCC 12 at -O1 warns falsely on that
  expected += "… (500 more bytes)";
  EXPECT_EQ(cut, expected);
  EXPECT_EQ(terminal_safe(text, 1000), text);
  // Never inside an escape or a character: "\x1b" is 4 bytes, an o-umlaut 2.
  EXPECT_EQ(terminal_safe("ab\x1b", 4), "ab… (1 more bytes)");
  EXPECT_EQ(terminal_safe("abc\xc3\xb6", 4), "abc… (2 more bytes)");
}

}  // namespace
}  // namespace tcsb
