// Text written into another language stays text (core/text_escape.h): each sink's literal holds
// any string, and what it shows a terminal has no control character in it.
#include "core/text_escape.h"

#include <gtest/gtest.h>

#include <string>

namespace beverloo {
namespace {
using namespace std::string_literals;

TEST(TerminalSafe, PlainTextIsUnchanged) {
  EXPECT_EQ(terminal_safe("Fig. 2 SP, w = 4..10 (lambda=inf)"), "Fig. 2 SP, w = 4..10 (lambda=inf)");
  EXPECT_EQ(terminal_safe("Öl in Wasser, 45° — β"), "Öl in Wasser, 45° — β");  // UTF-8 text is text
}

TEST(TerminalSafe, ControlCharactersBecomeVisibleEscapes) {
  EXPECT_EQ(terminal_safe("a\x1b[31mb"), "a\\x1B[31mb");
  EXPECT_EQ(terminal_safe("a\rb\nc\td"), "a\\x0Db\\x0Ac\\x09d");
  EXPECT_EQ(terminal_safe("a\0b"s), "a\\x00b");
  EXPECT_EQ(terminal_safe("del\x7f"), "del\\x7F");
  EXPECT_EQ(terminal_safe("c1 \u009b"), "c1 \\u{009B}");            // CSI as one code point
  EXPECT_EQ(terminal_safe("bidi \u202e"), "bidi \\u{202E}");        // right-to-left override
  EXPECT_EQ(terminal_safe("\xff\xc0\xaf"), "\\xFF\\xC0\\xAF");        // not UTF-8 (and an overlong '/')
  EXPECT_EQ(terminal_safe("\xed\xa0\x80"), "\\xED\\xA0\\x80");        // a surrogate is not UTF-8
  EXPECT_EQ(terminal_safe("trunc \xe2\x82"), "trunc \\xE2\\x82");      // a sequence cut short
}

TEST(TerminalSafe, DifferentNamesNeverPrintAlike) {
  // the escape's own backslash is escaped: a name that spells an escape prints otherwise
  EXPECT_NE(terminal_safe("a\\x1Bb"), terminal_safe("a\x1b" "b"));
  EXPECT_EQ(terminal_safe("a\\b"), "a\\\\b");
}

TEST(GnuplotString, SingleQuotedWithQuotesDoubled) {
  EXPECT_EQ(gnuplot_string("plain"), "'plain'");
  EXPECT_EQ(gnuplot_string("it's"), "'it''s'");
  // the payloads stay inside the literal: backquotes and @ are not expanded in single quotes
  EXPECT_EQ(gnuplot_string("s\"; system(\"touch X\"); print \""), "'s\"; system(\"touch X\"); print \"'");
  EXPECT_EQ(gnuplot_string("`touch X` @m"), "'`touch X` @m'");
  // a line break would end the command: it becomes visible text
  EXPECT_EQ(gnuplot_string("a\n!touch X"), "'a\\x0A!touch X'");
}

TEST(CsvField, QuotedOnlyWhereRfc4180NeedsIt) {
  EXPECT_EQ(csv_field("1.25"), "1.25");
  EXPECT_EQ(csv_field("a|b,c\"d"), "\"a|b,c\"\"d\"");
  EXPECT_EQ(csv_field("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(csv_field(" padded"), "\" padded\"");
  EXPECT_EQ(csv_field(""), "");
}

TEST(MarkdownCell, PipesEscapedOneLine) {
  EXPECT_EQ(markdown_cell("a|b"), "a\\|b");
  EXPECT_EQ(markdown_cell("a\n| x |"), "a\\x0A\\| x \\|");
}

TEST(HtmlEscape, MarkupBecomesText) {
  EXPECT_EQ(html_escape("<script>alert('x')</script> & \""), "&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt; &amp; &quot;");
}

}  // namespace
}  // namespace beverloo
