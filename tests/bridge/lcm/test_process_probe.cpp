// process_probe: what /proc says of real processes, children of this test made for it.
#include "touchline/lcm/process_probe.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <string>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

using touchline::transport::process_runs;

namespace {

/// A child that names itself `name` and waits for a signal; its pid once it has.
pid_t named_child(const char* name) {
  int ready[2];
  if (pipe(ready) != 0) return -1;
  const pid_t pid = fork();
  if (pid == 0) { // only async-signal-safe calls here
    prctl(PR_SET_NAME, name);
    const char byte = 1;
    (void)!write(ready[1], &byte, 1);
    for (;;) pause();
  }
  char byte = 0;
  const bool named = pid > 0 && read(ready[0], &byte, 1) == 1;
  close(ready[0]);
  close(ready[1]);
  return named ? pid : -1;
}

} // namespace

TEST(ProcessProbe, ThisProcessRunsUnderItsOwnNameOnly) {
  std::ifstream comm("/proc/self/comm");
  std::string name;
  std::getline(comm, name);
  ASSERT_FALSE(name.empty());
  EXPECT_TRUE(process_runs(getpid(), name));
  EXPECT_FALSE(process_runs(getpid(), "robot_shim"));
}

TEST(ProcessProbe, AShimRunsWhileStoppedAndNoLongerOnceItExited) {
  const pid_t shim = named_child("robot_shim");
  ASSERT_GT(shim, 0);
  EXPECT_TRUE(process_runs(shim, "robot_shim"));
  ASSERT_EQ(kill(shim, SIGSTOP), 0); // a debugger's breakpoint, or a machine too busy to run it
  int status = 0;
  ASSERT_EQ(waitpid(shim, &status, WUNTRACED), shim);
  EXPECT_TRUE(process_runs(shim, "robot_shim"));
  ASSERT_EQ(kill(shim, SIGKILL), 0);
  siginfo_t info{};
  ASSERT_EQ(waitid(P_PID, static_cast<id_t>(shim), &info, WEXITED | WNOWAIT), 0); // dead, not reaped
  EXPECT_FALSE(process_runs(shim, "robot_shim")); // a zombie
  ASSERT_EQ(waitpid(shim, &status, 0), shim);
  EXPECT_FALSE(process_runs(shim, "robot_shim")); // gone
}

TEST(ProcessProbe, TheNameIsComparedAsTheKernelKeepsIt) {
  const pid_t child = named_child("a_very_long_program_name");
  ASSERT_GT(child, 0);
  EXPECT_TRUE(process_runs(child, "a_very_long_program_name")); // both cut to 15 characters
  EXPECT_FALSE(process_runs(child, "a_very_long"));
  kill(child, SIGKILL);
  int status = 0;
  waitpid(child, &status, 0);
}

TEST(ProcessProbe, NoPidRuns) {
  EXPECT_FALSE(process_runs(0, "robot_shim"));
  EXPECT_FALSE(process_runs(-1, "robot_shim"));
}
