// The stop signals every session command shares (app/cli/stop_signal.h): SIGTERM, SIGINT and
// SIGHUP are recorded, not fatal, while a StopSignals lives; the first one is kept; a second
// signal of a kind ends the process (SA_RESETHAND); the handlers before are put back. And the
// resume line's command: the arguments given, the option replaced, shell words quoted.
#include <gtest/gtest.h>

#include <csignal>
#include <sys/wait.h>
#include <unistd.h>

#include "app/cli/stop_signal.h"

namespace ps::cli {
namespace {

TEST(StopSignalTest, ASignalIsRecordedAndTheFirstOneKept) {
  const StopSignals stop;
  const auto asked = stop.predicate();
  EXPECT_FALSE(stop.requested());
  EXPECT_FALSE(asked());
  ASSERT_EQ(raise(SIGTERM), 0);  // the handler runs before raise returns
  EXPECT_TRUE(asked());
  EXPECT_EQ(stop.received(), SIGTERM);
  EXPECT_EQ(stop.exit_code(), 143);
  ASSERT_EQ(raise(SIGHUP), 0);
  EXPECT_EQ(stop.received(), SIGTERM) << "the first signal is the one reported";
}

TEST(StopSignalTest, TheHandlersBeforeArePutBack) {
  struct sigaction before {};
  sigaction(SIGINT, nullptr, &before);
  {
    const StopSignals stop;
    struct sigaction during {};
    sigaction(SIGINT, nullptr, &during);
    EXPECT_NE(during.sa_handler, before.sa_handler);
  }
  struct sigaction after {};
  sigaction(SIGINT, nullptr, &after);
  EXPECT_EQ(after.sa_handler, before.sa_handler);
}

// In a child: the first SIGINT is a request, the second one ends the process as SIGINT does.
TEST(StopSignalTest, ASecondSignalEndsTheProcess) {
  const pid_t pid = fork();
  if (pid == 0) {
    const StopSignals stop;
    raise(SIGINT);
    if (stop.received() != SIGINT) _exit(3);
    raise(SIGINT);
    _exit(4);  // not reached when the second signal has its default action again
  }
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFSIGNALED(status)) << "exit " << WEXITSTATUS(status);
  EXPECT_EQ(WTERMSIG(status), SIGINT);
}

TEST(StopSignalTest, TheLineSaysWhatWasFlushedAndWhatNext) {
  EXPECT_EQ(stop_line("maze", SIGTERM, "log", "s/P01/session.jsonl", "resume with: pseudoshadow maze --resume s/P01"),
            "maze: terminated by SIGTERM; log flushed to s/P01/session.jsonl; resume with: pseudoshadow maze --resume s/P01");
  EXPECT_EQ(stop_line("run", SIGHUP, "", "", ""), "run: terminated by SIGHUP");
  EXPECT_EQ(signal_name(SIGINT), "SIGINT");
}

TEST(StopSignalTest, TheResumeCommandIsTheOneGivenWithTheOptionReplaced) {
  EXPECT_EQ(command_with("calibrate", {"--curve", "distance", "--out", "my table.lut", "--resume", "old.csv", "-q"}, "--resume",
                         "my table.trials.csv"),
            "pseudoshadow calibrate --curve distance --out 'my table.lut' -q --resume 'my table.trials.csv'");
  EXPECT_EQ(command_with("calibrate", {"--resume=old.csv", "--seed", "5"}, "--resume", "it's.csv"),
            "pseudoshadow calibrate --seed 5 --resume 'it'\\''s.csv'");
}

}  // namespace
}  // namespace ps::cli
