// lcm_url_problem: one line saying why LCM cannot open a URL, and nothing of what LCM
// prints itself. Only URLs that touch no network here (memq, files, a refused connection
// to loopback, bad spellings); multicast ones are tried in tests/match/test_cli.py, inside
// a network namespace.
#include "touchline/lcm/lcm_url.hpp"

#include <gtest/gtest.h>

#include <string>

namespace touchline::transport {
namespace {

TEST(LcmUrl, AnOpenableUrlHasNoProblem) { EXPECT_EQ(lcm_url_problem("memq://"), std::nullopt); }

TEST(LcmUrl, ProblemsAreOneLineAndLcmsOwnOutputIsNotShown) {
  struct Case {
    const char* url;
    const char* problem;
  };
  for (const Case& c : {
           Case{"bogus://x", "LCM provider \"bogus\" not found"},
           Case{"udpm://8.8.8.8:7667", "not a multicast group address: 8.8.8.8 (udpm needs 224.0.0.0 to 239.255.255.255)"},
           Case{"udpm://239.255.76.67:99999", "Bad multicast port \"99999\""},
           Case{"udpm://foo", "Bad multicast IP address \"foo\""},
           Case{"file:///nonexistent/match.lcmlog", "Failed to open /nonexistent/match.lcmlog: No such file or directory"},
           // LCM returned an lcm_t without a descriptor here, which later aborted in select().
           Case{"tcpq://127.0.0.1:1", "lcm_tcpq connect: Connection refused"},
       }) {
    testing::internal::CaptureStderr();
    const auto problem = lcm_url_problem(c.url);
    const std::string printed = testing::internal::GetCapturedStderr();
    EXPECT_EQ(problem.value_or("(none)"), c.problem) << c.url;
    EXPECT_EQ(printed, "") << c.url;
  }
}

} // namespace
} // namespace touchline::transport
