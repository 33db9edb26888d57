/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// The command line: FOAM_CASE and FOAM_CASENAME set from the case, as
// OpenFOAM's argList does, so that dictionaries can include through them;
// word-list and number options; warnings given once when asked.

#include "argList.H"
#include "progressEstimate.H"
#include "dictionary.H"
#include "error.H"
#include "../testTools.H"

#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace sphvcpm;
using test::catchFatal;
using test::expectMessage;
using test::scratchDir;

namespace fs = std::filesystem;

namespace
{

// Parses words as a command line of testApp.
bool parse(argList& args, std::vector<std::string> words)
{
    words.insert(words.begin(), "testApp");
    std::vector<char*> argv;
    for (auto& w : words)
    {
        argv.push_back(w.data());
    }
    argv.push_back(nullptr);
    return args.parse(int(words.size()), argv.data());
}

std::string env(const char* name)
{
    const char* v = std::getenv(name);
    return v ? v : "<unset>";
}

// Restores the environment variable of its name when it goes.
class savedEnv
{
public:
    explicit savedEnv(const char* name)
    :
        name_(name),
        had_(std::getenv(name) != nullptr),
        value_(had_ ? std::getenv(name) : "")
    {}
    ~savedEnv()
    {
        if (had_)
        {
            ::setenv(name_, value_.c_str(), 1);
        }
        else
        {
            ::unsetenv(name_);
        }
    }

private:
    const char* name_;
    bool had_;
    std::string value_;
};

} // End anonymous namespace


TEST(argList, setsFoamCaseForIncludes)
{
    const savedEnv foamCase("FOAM_CASE");
    const savedEnv foamCaseName("FOAM_CASENAME");
    scratchDir dir("argList");
    dir.write("damBreak/system/caseParams", "H 0.2;\n");
    const fs::path caseDir = dir.path()/"damBreak";

    // Inherited from another case: the case being run wins.
    ::setenv("FOAM_CASE", "/some/other/case", 1);
    ::setenv("FOAM_CASENAME", "case", 1);
    argList args("testApp", "test");
    ASSERT_TRUE(parse(args, {"-case", caseDir.string() + "/"}));
    EXPECT_EQ(env("FOAM_CASE"), caseDir.string());
    EXPECT_EQ(env("FOAM_CASENAME"), "damBreak");

    const auto d = dictionary::fromString
    (
        "#include \"$FOAM_CASE/system/caseParams\"\nL $H;\n",
        "elsewhere/someDict"
    );
    EXPECT_EQ(d.get<double>("L"), 0.2);
    EXPECT_NO_THROW(d.checkKeywords({"L"}));

    // Without -case: the working directory.
    const fs::path cwd = fs::current_path();
    fs::current_path(caseDir/"system");
    argList here("testApp", "test");
    const bool parsed = parse(here, {});
    fs::current_path(cwd);
    ASSERT_TRUE(parsed);
    EXPECT_EQ(env("FOAM_CASE"), here.casePath().string());
    EXPECT_EQ(env("FOAM_CASENAME"), "system");
}


// -case given a file (system/controlDict, say) is told apart from a
// missing directory.
TEST(argList, caseMustBeADirectory)
{
    const savedEnv foamCase("FOAM_CASE");
    const savedEnv foamCaseName("FOAM_CASENAME");
    scratchDir dir("argListCase");
    const fs::path file = dir.write("damBreak/system/controlDict", "a 1;\n");

    argList args("testApp", "test");
    const FatalError err = catchFatal([&]
    {
        parse(args, {"-case", file.string()});
    });
    expectMessage(err, {"Case directory " + file.string()
        + " (given by -case) exists but is not a directory"});
    EXPECT_EQ(err.message().find("does not exist"), std::string::npos)
        << err.message();

    argList missing("testApp", "test");
    expectMessage(catchFatal([&]
    {
        parse(missing, {"-case", (dir.path()/"none").string()});
    }), {"Case directory " + (dir.path()/"none").string()
         + " does not exist (given by -case)"});
}


TEST(argList, parseWordList)
{
    using words = std::vector<std::string>;
    EXPECT_EQ(argList::parseWordList("(rho U)", "-fields"),
              (words{"rho", "U"}));
    EXPECT_EQ(argList::parseWordList(" ( rho  ) ", "-fields"),
              (words{"rho"}));
    EXPECT_EQ(argList::parseWordList("rho,U p", "-fields"),
              (words{"rho", "U", "p"}));
    EXPECT_EQ(argList::parseWordList("()", "-fields"), words{});
    for (const std::string bad : {"(rho U", "(rho (U))", "\"rho\"", "rho;"})
    {
        const FatalError err = catchFatal([&]()
        {
            argList::parseWordList(bad, "-fields");
        });
        expectMessage(err,
            {"Invalid -fields '" + bad + "'", "(name1 name2)"});
    }
}


TEST(argList, numberOptions)
{
    const scratchDir scratch("numberOptions");
    auto make = [](argList& args)
    {
        args.addOption("level", "value", "a number");
        args.addOption("refine", "n", "a whole number");
    };
    {
        argList args("testApp", "numbers");
        make(args);
        ASSERT_TRUE(parse(args, {"-case", scratch.path().string(),
                                 "-level", "2.5e-1", "-refine", "3"}));
        EXPECT_EQ(args.numberOption("level", 9), 0.25);
        EXPECT_EQ(args.integerOption("refine", 9), 3);
    }
    {
        argList args("testApp", "defaults");
        make(args);
        ASSERT_TRUE(parse(args, {"-case", scratch.path().string()}));
        EXPECT_EQ(args.numberOption("level", 0.5), 0.5);
        EXPECT_EQ(args.integerOption("refine", 2), 2);
    }
    for (const char* bad : {"x", "1.5x", "nan", "inf", "1e999", ""})
    {
        argList args("testApp", "bad");
        make(args);
        ASSERT_TRUE(parse(args, {"-case", scratch.path().string(),
                                 "-level", bad}));
        expectMessage(catchFatal([&] { args.numberOption("level", 0); }),
                      {"Option -level expects a number, not '"
                       + std::string(bad) + "'"});
    }
    {
        argList args("testApp", "not whole");
        make(args);
        ASSERT_TRUE(parse(args, {"-case", scratch.path().string(),
                                 "-refine", "1.5"}));
        expectMessage(catchFatal([&] { args.integerOption("refine", 0); }),
                      {"Option -refine expects a whole number, not '1.5'"});
    }
}


TEST(warning, onlyOnceWhenAsked)
{
    // What sphVcpmFsi -postProcess uses: it reads the case once per time.
    std::ostringstream captured;
    std::streambuf* const old = std::cerr.rdbuf(captured.rdbuf());
    warning("the same", "a/file", 3);
    warning("the same", "a/file", 3);
    warnOnlyOnce(true);
    warning("once", "a/file", 3);
    warning("once", "a/file", 3);
    warning("once", "a/file", 4);       // another line: another warning
    warning("the same", "a/file", 3);   // given before, but not remembered
    warning("the same", "a/file", 3);
    warnOnlyOnce(false);
    warning("once", "a/file", 3);
    std::cerr.rdbuf(old);

    const std::string text = captured.str();
    const auto count = [&](const std::string& what)
    {
        std::size_t n = 0;
        for (auto at = text.find(what); at != std::string::npos;
             at = text.find(what, at + 1)) ++n;
        return n;
    };
    EXPECT_EQ(count("SPHVCPM Warning"), 6u) << text;
    EXPECT_EQ(count("the same\nfile: a/file at line 3"), 3u) << text;
    EXPECT_EQ(count("once\nfile: a/file at line 3"), 2u) << text;
    EXPECT_EQ(count("once\nfile: a/file at line 4"), 1u) << text;
}


// The log's time left: the simulated time to go at the pace between two
// reports, in words; none at the first report or at endTime.
TEST(progressEstimate, timeLeft)
{
    // 0.01 s simulated in 2 s of wall clock, 0.3 s to go: 60 s.
    EXPECT_DOUBLE_EQ(progressEstimate::secondsLeft(0.01, 2, 0.1, 0.4), 60);
    EXPECT_LT(progressEstimate::secondsLeft(0, 2, 0.1, 0.4), 0);
    EXPECT_LT(progressEstimate::secondsLeft(0.01, 2, 0.4, 0.4), 0);
    EXPECT_LT(progressEstimate::secondsLeft(0.01, 2, 0.5, 0.4), 0);
    EXPECT_EQ(progressEstimate::durationText(45.4), "45 s");
    EXPECT_EQ(progressEstimate::durationText(320), "5 min 20 s");
    EXPECT_EQ(progressEstimate::durationText(7385), "2 h 3 min");

    progressEstimate p;
    EXPECT_EQ(p.line(0.1, 0.4), "");            // the first report
    const std::string second = p.line(0.2, 0.4);
    EXPECT_EQ(second.rfind("Time left = about ", 0), 0u) << second;
    EXPECT_NE(second.find(" to endTime 0.4\n"), std::string::npos) << second;
    EXPECT_EQ(p.line(0.4, 0.4), "");            // at endTime
}
