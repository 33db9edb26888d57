/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// The write schedule of both solvers' loops (libsrc/core/timeControl.H):
// write times as multiples of writeInterval from any start (negative ones
// too) at their decimal values, the next write after a changed interval,
// the name of a second write at one time, purgeWrite, the
// writeInterval checks of each writeControl and the range checks of
// controlDict's other entries.

#include "timeControl.H"
#include "../testTools.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

using namespace sphvcpm;
using test::catchFatal;
using test::scratchDir;

namespace
{

timeControl readControl(const scratchDir& dir, const std::string& entries)
{
    dir.write("system/controlDict",
        "FoamFile { format ascii; class dictionary; object controlDict; }\n"
        "endTime 1;\ndeltaT 0.001;\n" + entries);
    return timeControl::read(dir.path());
}

// Runs the schedule from start to endTime with steps of at most dt, as the
// solvers' loops do; returns the names written.
std::vector<std::string> writtenNames(const timeControl& control,
                                      double start, double dt)
{
    writeSchedule schedule(control, start);
    std::vector<std::string> names;
    double t = start;
    label index = 0;
    while (t < control.endTime*(1 - 1e-12))
    {
        const double step = schedule.limitStep(t, dt);
        t = schedule.landed() ? schedule.landingTime() : t + step;
        ++index;
        if (schedule.due(t, index))
        {
            const std::string name = schedule.writeName(t);
            names.push_back(name);
            schedule.written(t, name, "", "");
        }
    }
    return names;
}

// What the case directory holds besides system/, sorted.
std::vector<std::string> entriesBesideSystem(const scratchDir& dir)
{
    std::vector<std::string> left;
    for (const auto& e : std::filesystem::directory_iterator(dir.path()))
    {
        if (e.path().filename() != "system")
        {
            left.push_back(e.path().filename().string());
        }
    }
    std::sort(left.begin(), left.end());
    return left;
}

} // End anonymous namespace


TEST(writeSchedule, landsOnMultiplesOfTheIntervalFromANegativeStart)
{
    // A sum of intervals from -1 drifted: its zero was named -1.38778e-16.
    scratchDir dir("schedule");
    timeControl control = readControl(dir, "writeInterval 0.1;\n");
    control.endTime = 0.3;
    const std::vector<std::string> names = writtenNames(control, -1, 0.03);
    const std::vector<std::string> expected{"-0.9", "-0.8", "-0.7", "-0.6",
        "-0.5", "-0.4", "-0.3", "-0.2", "-0.1", "0", "0.1", "0.2", "0.3"};
    EXPECT_EQ(names, expected);
}


TEST(writeSchedule, aSecondWriteAtTheSameTimeHasTheSameName)
{
    // The last good state of a run that blew up right after a write is
    // that write: the same directory, not a new name at a raised precision.
    scratchDir dir("schedule");
    const timeControl control = readControl(dir, "writeInterval 0.1;\n");
    writeSchedule schedule(control, 0);
    const double t = 0.1 + 0.2;     // 0.30000000000000004
    const std::string first = schedule.writeName(t);
    schedule.written(t, first, "", "");
    EXPECT_EQ(first, "0.3");
    EXPECT_EQ(schedule.writeName(t), "0.3");
    EXPECT_EQ(schedule.name(t), "0.3") << "the precision was raised";
    EXPECT_EQ(schedule.lastWriteTime(), t);
    EXPECT_EQ(schedule.lastWriteName(), "0.3");
}


TEST(writeSchedule, runTimeBelowTheStepWritesEveryStep)
{
    // runTime writes after the step that passes a write time: an interval
    // far below the step writes every step, and moves on at once (no loop
    // over the interval's multiples in between).
    scratchDir dir("schedule");
    timeControl control =
        readControl(dir, "writeControl runTime;\nwriteInterval 1e-300;\n");
    control.endTime = 0.01;
    const std::vector<std::string> names = writtenNames(control, 0, 0.001);
    ASSERT_EQ(names.size(), 10u);
    EXPECT_EQ(names.front(), "0.001");
    EXPECT_EQ(names.back(), "0.01");

    // From t = 1 the interval's count overflows (1/1e-310): still every
    // step, not never.
    timeControl subnormal =
        readControl(dir, "writeControl runTime;\nwriteInterval 1e-310;\n");
    subnormal.endTime = 1.01;
    const std::vector<std::string> late = writtenNames(subnormal, 1, 0.001);
    ASSERT_EQ(late.size(), 10u);
    EXPECT_EQ(late.front(), "1.001");
    EXPECT_EQ(late.back(), "1.01");

    // adjustableRunTime lands on each write time: below minDeltaT every
    // step would be below the floor the run stops at.
    const FatalError err = catchFatal([&]
    {
        readControl(dir, "writeInterval 1e-300;\n");
    });
    test::expectMessage(err, {"writeInterval 1e-300 s is below minDeltaT"});
}


TEST(writeSchedule, writeTimesAreTheirDecimalValues)
{
    // 3*0.05 is 0.15000000000000002 in binary: the write lands on 0.15.
    scratchDir dir;
    const timeControl control =
        readControl(dir, "writeInterval 0.05;\nendTime 0.3;\n");
    writeSchedule schedule(control, 0);
    double t = 0;
    std::vector<double> landed;
    while (t < control.endTime*(1 - 1e-12))
    {
        const double step = schedule.limitStep(t, 0.007);
        t = schedule.landed() ? schedule.landingTime() : t + step;
        if (schedule.due(t, 0))
        {
            landed.push_back(t);
            schedule.written(t, schedule.writeName(t), "", "");
        }
    }
    EXPECT_EQ(landed, (std::vector<double>{0.05, 0.1, 0.15, 0.2, 0.25, 0.3}));
}


TEST(writeSchedule, restartFindsTheNextWriteOfAChangedInterval)
{
    // controlDict read again at t = 0.23 with writeInterval 0.1 -> 0.04:
    // the next write is 0.24, not 0.3.
    scratchDir dir;
    timeControl control = readControl(dir, "writeInterval 0.1;\n");
    writeSchedule schedule(control, 0.2);   // written at 0.2: next 0.3
    EXPECT_DOUBLE_EQ(schedule.limitStep(0.23, 1), 0.3 - 0.23);
    control.writeInterval = 0.04;
    schedule.restart(0.23);
    EXPECT_DOUBLE_EQ(schedule.limitStep(0.23, 1), 0.24 - 0.23);
    EXPECT_TRUE(schedule.landed());
    EXPECT_EQ(schedule.landingTime(), 0.24);
}


TEST(writeSchedule, aChangedIntervalKeepsAWriteAtThatStep)
{
    // writeInterval 0.1 -> 0.05 read at t = 0.2, just landed on: the
    // write of 0.2 is kept (restart at that time, atTimeToo).
    scratchDir dir;
    timeControl control = readControl(dir, "writeInterval 0.1;\n");
    writeSchedule schedule(control, 0.1);
    schedule.limitStep(0.15, 0.05);
    ASSERT_TRUE(schedule.landed());
    control.writeInterval = 0.05;
    schedule.restart(0.2, true);
    EXPECT_TRUE(schedule.due(0.2, 7));
    schedule.written(0.2, "0.2", "", "");
    EXPECT_DOUBLE_EQ(schedule.limitStep(0.2, 1), 0.05);
}


TEST(timeControl, outOfRangeEntriesAreErrorsNamingTheKeyword)
{
    scratchDir dir("schedule");
    const std::vector<std::pair<std::string, std::string>> cases{
        {"writeControl timeStep;\nwriteInterval 2.5;\n",
         "a whole number of steps as writeInterval"},
        {"writeInterval 0.1;\npurgeWrite -1;\n", "purgeWrite must be >= 0"},
        {"writeInterval 0.1;\nwritePrecision 0;\n",
         "writePrecision must be in [1, 17]"},
        {"writeInterval 0.1;\ntimePrecision 18;\n",
         "timePrecision must be in [1, 17]"},
        {"writeInterval 0.1;\nlogInterval 0;\n", "logInterval must be >= 1"}};
    for (const auto& [entries, message] : cases)
    {
        SCOPED_TRACE(entries);
        const FatalError err = catchFatal([&, e = entries]
        {
            readControl(dir, e);
        });
        test::expectMessage(err, {message});
        EXPECT_EQ(err.file(), (dir.path()/"system/controlDict").string());
        EXPECT_GT(err.line(), 0);
    }
}


TEST(writeSchedule, purgeWriteKeepsTheLastWritesAndTheStart)
{
    // purgeWrite 2: of the writes, only the last two stay; the start time
    // is never removed (a restart from it keeps its input).
    scratchDir dir("schedule");
    timeControl control =
        readControl(dir, "writeInterval 0.1;\npurgeWrite 2;\n");
    control.endTime = 0.5;
    writeSchedule schedule(control, 0);
    std::filesystem::create_directories(dir.path()/"0");
    for (const std::string name : {"0.1", "0.2", "0.3", "0.4", "0.5"})
    {
        std::filesystem::create_directories(dir.path()/name);
        schedule.written(std::stod(name), name, dir.path(), "0");
    }
    const std::vector<std::string> left = entriesBesideSystem(dir);
    EXPECT_EQ(left, (std::vector<std::string>{"0", "0.4", "0.5"}));
}


TEST(writeSchedule, purgeWriteCountsTheWritesBeforeARestart)
{
    // A run killed after writing 0.1 to 0.4 (purgeWrite 2 had left 0.3 and
    // 0.4) and one that went on from 0.4 with a stale 0.2 of an earlier
    // try: with the earlier writes counted, two more writes leave the
    // initial time and the last two, as a run never stopped would.
    scratchDir dir("schedule");
    timeControl control =
        readControl(dir, "writeInterval 0.1;\npurgeWrite 2;\n");
    control.endTime = 0.6;
    writeSchedule schedule(control, 0.4);
    for (const std::string name : {"0", "0.2", "0.3", "0.4"})
    {
        std::filesystem::create_directories(dir.path()/name);
    }
    schedule.countEarlierWrites({"0.2", "0.3", "0.4"});
    for (const std::string name : {"0.5", "0.6"})
    {
        std::filesystem::create_directories(dir.path()/name);
        schedule.written(std::stod(name), name, dir.path(), "0.4");
    }
    const std::vector<std::string> left = entriesBesideSystem(dir);
    EXPECT_EQ(left, (std::vector<std::string>{"0", "0.5", "0.6"}));
}
