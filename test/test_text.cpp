// Message text (eaci/io/text.hpp): one line, and numbers without trailing zeros.
#include <gtest/gtest.h>

#include <string>

#include "eaci/io/text.hpp"

namespace eaci {
namespace {

TEST(Text, OneLineTurnsBreaksAndTabsIntoSingleSpaces) {
  EXPECT_EQ(oneLine("cannot open a.pgm:\nNo such file"), "cannot open a.pgm: No such file");
  EXPECT_EQ(oneLine("a\r\n\tb   c"), "a b c");
  EXPECT_EQ(oneLine("  \n padded \t\n"), "padded");
  EXPECT_EQ(oneLine(""), "");
  EXPECT_EQ(oneLine(" \n\t\r"), "");
}

TEST(Text, FormatNumberDropsTrailingZeros) {
  EXPECT_EQ(formatNumber(0.05), "0.05");
  EXPECT_EQ(formatNumber(20.0), "20");
  EXPECT_EQ(formatNumber(33.31370849898476), "33.3137");
  EXPECT_EQ(formatNumber(33.31370849898476, 2), "33.31");
  EXPECT_EQ(formatNumber(899.6, 0), "900");
  EXPECT_EQ(formatNumber(-2.5), "-2.5");
  EXPECT_EQ(formatNumber(0.196, 6), "0.196");
  EXPECT_EQ(formatNumber(1e9, 6), "1000000000");
}

}  // namespace
}  // namespace eaci
