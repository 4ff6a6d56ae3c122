// Text from files and paths in messages (core/support/quoted_text.h): escaped, quoted and cut.
#include "core/support/quoted_text.h"

#include <gtest/gtest.h>

#include <string>

namespace gps {
namespace {

TEST(QuotedText, EscapesControlBytesAndBytesThatAreNotUtf8) {
  EXPECT_EQ(escaped("plain/path to.ply"), "plain/path to.ply");
  EXPECT_EQ(escaped("±Σ…é"), "±Σ…é");
  EXPECT_EQ(escaped("a\nb"), "a\\x0Ab");
  EXPECT_EQ(escaped("\x1b[31mred"), "\\x1B[31mred");
  EXPECT_EQ(escaped(std::string("a\0b", 3)), "a\\x00b");
  EXPECT_EQ(escaped("\x7f\t\r"), "\\x7F\\x09\\x0D");
  EXPECT_EQ(escaped("\xc2\x9b"), "\\xC2\\x9B");                      // C1 control (CSI)
  EXPECT_EQ(escaped("\xff\xfe"), "\\xFF\\xFE");                      // never UTF-8
  EXPECT_EQ(escaped("\xc0\xaf"), "\\xC0\\xAF");                      // overlong '/'
  EXPECT_EQ(escaped("\xed\xa0\x80"), "\\xED\\xA0\\x80");             // a surrogate
  EXPECT_EQ(escaped("x\xe2\x82"), "x\\xE2\\x82");                    // cut short at the end
  EXPECT_EQ(escaped("\xf0\x9f\x98\x80 ok"), "\xf0\x9f\x98\x80 ok");  // four bytes, valid
  const std::string hostile = "a\x1b]0;title\x07\n\xff";
  EXPECT_EQ(escaped(escaped(hostile)), escaped(hostile));  // escaping twice changes nothing
}

TEST(QuotedText, QuotesAndCutsLongTokens) {
  EXPECT_EQ(quoted_token("abc"), "'abc'");
  EXPECT_EQ(quoted_token("a\x1b"), "'a\\x1B'");
  const std::string forty(kMaxQuotedCharacters, 'x');
  EXPECT_EQ(quoted_token(forty), "'" + forty + "'");
  EXPECT_EQ(quoted_token(forty + "y"), "'" + forty + "…'");
  EXPECT_EQ(quoted_token(std::string(10'000'000, 'z')), "'" + std::string(kMaxQuotedCharacters, 'z') + "…'");
  // Cut by characters, never inside a UTF-8 sequence.
  std::string accents;
  for (size_t i = 0; i < kMaxQuotedCharacters + 5; ++i) accents += "é";
  EXPECT_EQ(quoted_token(accents), "'" + accents.substr(0, 2 * kMaxQuotedCharacters) + "…'");
}

}  // namespace
}  // namespace gps
