// parse_number: what config files and command lines accept as a number, and what not
// (boost::lexical_cast, used before, wrapped "-1" into an unsigned and read "inf" and "nan").
#include "touchline/parse_number.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>

namespace touchline {
namespace {

TEST(ParseNumber, ReadsWholeNumbersWithinTheirType) {
  EXPECT_EQ(parse_number<int>("42"), 42);
  EXPECT_EQ(parse_number<int>(" -7 "), -7); // blanks around, as an INI value may carry
  EXPECT_EQ(parse_number<int>("+3"), 3);
  EXPECT_EQ(parse_number<uint64_t>("18446744073709551615"), std::numeric_limits<uint64_t>::max());
  EXPECT_EQ(parse_number<int64_t>("-9223372036854775808"), std::numeric_limits<int64_t>::min());
}

TEST(ParseNumber, RefusesWhatDoesNotFitOrIsNotAWholeNumber) {
  EXPECT_EQ(parse_number<uint64_t>("-1"), std::nullopt); // lexical_cast gave 2^64 - 1
  EXPECT_EQ(parse_number<unsigned>("-0"), std::nullopt);
  EXPECT_EQ(parse_number<uint64_t>("18446744073709551616"), std::nullopt);
  EXPECT_EQ(parse_number<int>("99999999999"), std::nullopt);
  EXPECT_EQ(parse_number<int>("2.5"), std::nullopt);
  EXPECT_EQ(parse_number<int>("1e3"), std::nullopt);
  EXPECT_EQ(parse_number<int>("7x"), std::nullopt);
  EXPECT_EQ(parse_number<int>("0x10"), std::nullopt);
  EXPECT_EQ(parse_number<int>(""), std::nullopt);
  EXPECT_EQ(parse_number<int>("  "), std::nullopt);
  EXPECT_EQ(parse_number<int>("+-1"), std::nullopt);
  EXPECT_EQ(parse_number<int>("++1"), std::nullopt);
}

TEST(ParseNumber, ReadsFiniteFloats) {
  EXPECT_EQ(parse_number<float>("0.055"), 0.055f);
  EXPECT_EQ(parse_number<double>("1e-3"), 1e-3);
  EXPECT_EQ(parse_number<double>("-6000"), -6000.0);
  EXPECT_EQ(parse_number<float>("+1.5"), 1.5f);
  EXPECT_EQ(parse_number<double>("1e308"), 1e308); // finite: ranges are the caller's to check
}

TEST(ParseNumber, RefusesNonFiniteAndOverflowingFloats) {
  for (const char* text : {"inf", "-inf", "INF", "infinity", "nan", "-nan", "NaN", "1e39"})
    EXPECT_EQ(parse_number<float>(text), std::nullopt) << text;
  EXPECT_EQ(parse_number<double>("1e309"), std::nullopt);
  EXPECT_EQ(parse_number<double>("1.5 m"), std::nullopt);
  EXPECT_EQ(parse_number<double>("fast"), std::nullopt);
}

TEST(FormatNumber, WritesWholeNumbersInFullAndFractionsShort) {
  EXPECT_EQ(format_number(1e6f), "1000000");
  EXPECT_EQ(format_number(0.1f), "0.1");
  EXPECT_EQ(format_number(0.01), "0.01");
  EXPECT_EQ(format_number(std::numeric_limits<uint64_t>::max()), "18446744073709551615");
  EXPECT_EQ(format_number(int8_t{5}), "5");
}

} // namespace
} // namespace touchline
