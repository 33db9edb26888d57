/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// The signals of stopControl (libsrc/core/stopControl.H), delivered
// synchronously with raise(): a stop signal asks for writeNow, the same
// request delivered twice at once (timeout signals the child, then its
// group) is one request, and a signal a second later ends the process.

#include "stopControl.H"
#include "timeControl.H"
#include "../testTools.H"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <sstream>
#include <string>
#include <thread>

using namespace sphvcpm;
using test::scratchDir;

namespace
{

timeControl readControl(const scratchDir& dir)
{
    dir.write("system/controlDict",
        "FoamFile { format ascii; class dictionary; object controlDict; }\n"
        "endTime 1;\ndeltaT 0.001;\nwriteInterval 0.1;\n");
    return timeControl::read(dir.path());
}

} // End anonymous namespace


TEST(stopControl, aStopSignalTwiceAtOnceIsOneRequest)
{
    scratchDir dir;
    timeControl control = readControl(dir);
    writeSchedule schedule(control, 0);
    std::ostringstream log;
    stopControl stop(control, schedule, dir.path(), log);
    EXPECT_EQ(stop.afterStep(0.001), stopAction::none);
    // The handler writes to file descriptor 2 itself.
    testing::internal::CaptureStderr();
    std::raise(SIGTERM);
    std::raise(SIGTERM);    // handled, not the default action: no exit
    std::raise(SIGINT);     // within the second: the same request
    const std::string said = testing::internal::GetCapturedStderr();
    EXPECT_EQ(stopControl::caughtSignal(), SIGTERM);
    EXPECT_EQ(stop.afterStep(0.002), stopAction::writeNow);
    // Acknowledged at once, once, long before the step ends.
    const std::string ack = "--> Stop requested (SIGTERM): the step in"
        " progress finishes, its state is written and the run stops;"
        " signal again, a second or more from now, to end at once";
    EXPECT_NE(said.find(ack), std::string::npos) << said;
    EXPECT_EQ(said.find("Stop requested", said.find(ack) + ack.size()),
              std::string::npos) << said;
}


TEST(stopControl, aHangupAsksForAStopUnlessIgnoredAtTheStart)
{
    scratchDir dir;
    timeControl control = readControl(dir);
    writeSchedule schedule(control, 0);
    std::ostringstream log;
    struct sigaction before{};
    sigaction(SIGHUP, nullptr, &before);
    // As under nohup: ignored before the run, so ignored in it.
    std::signal(SIGHUP, SIG_IGN);
    {
        stopControl stop(control, schedule, dir.path(), log);
        std::raise(SIGHUP);
        EXPECT_EQ(stopControl::caughtSignal(), 0);
        EXPECT_EQ(stop.afterStep(0.001), stopAction::none);
    }
    // A terminal that closes: the same stop as SIGTERM's.
    std::signal(SIGHUP, SIG_DFL);
    {
        stopControl stop(control, schedule, dir.path(), log);
        testing::internal::CaptureStderr();
        std::raise(SIGHUP);
        const std::string said = testing::internal::GetCapturedStderr();
        EXPECT_EQ(stopControl::caughtSignal(), SIGHUP);
        EXPECT_EQ(stop.afterStep(0.001), stopAction::writeNow);
        EXPECT_NE(said.find("--> Stop requested (SIGHUP): the step in"
            " progress finishes"), std::string::npos) << said;
    }
    // Given back as it was found.
    struct sigaction after{};
    sigaction(SIGHUP, nullptr, &after);
    EXPECT_EQ(after.sa_handler, SIG_DFL);
    sigaction(SIGHUP, &before, nullptr);
}


TEST(stopControlDeathTest, aStopSignalASecondLaterEndsTheProcess)
{
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_EXIT(
    {
        scratchDir dir;
        timeControl control = readControl(dir);
        writeSchedule schedule(control, 0);
        std::ostringstream log;
        stopControl stop(control, schedule, dir.path(), log);
        std::raise(SIGTERM);
        std::this_thread::sleep_for(std::chrono::milliseconds(1200));
        std::raise(SIGTERM);
        std::exit(0);       // not reached: the second ends it
    }, testing::KilledBySignal(SIGTERM), "");
}
