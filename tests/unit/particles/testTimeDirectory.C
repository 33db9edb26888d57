/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Time directories: round trips of several bodies, finding times, atomic
// writes (an interrupted write is never seen, an existing time is
// replaced), uniform/time, and OpenFOAM's foamDictionary reading what we
// write.

#include "timeDirectory.H"
#include "dictionary.H"
#include "testParticleTools.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sys/wait.h>

using namespace sphvcpm;
using test::catchFatal;
using test::expectMessage;
using test::readText;
using test::scratchDir;
using test::writeText;

namespace fs = std::filesystem;

namespace
{

// A fluid, a wall and a 2D solid, some particles removed so that ids have
// gaps, and the fluid reordered.
std::vector<particleBody> threeBodies(bool anyBits)
{
    std::vector<particleBody> bodies;
    bodies.push_back(test::randomBody("water", bodyType::fluid, 3, 1000, 1,
                                      anyBits));
    bodies.push_back(test::randomBody("tank", bodyType::wall, 3, 300, 2,
                                      anyBits));
    bodies.push_back(test::randomBody("gate", bodyType::solid, 2, 120, 3,
                                      anyBits));
    bodies[0].addScalarField("p", 101325);
    std::vector<char> flags(1000, 0);
    flags[999] = flags[998] = flags[10] = 1;
    bodies[0].remove(flags);
    std::vector<label> order(997);
    for (label i = 0; i < 997; ++i)
    {
        order[i] = (i*7) % 997;
    }
    bodies[0].reorder(order);
    return bodies;
}


// Bodies come back in alphabetical order of name.
void expectSameBodies(std::vector<particleBody> written,
                      const std::vector<particleBody>& read)
{
    std::sort(written.begin(), written.end(),
        [](const particleBody& a, const particleBody& b)
        {
            return a.name() < b.name();
        });
    ASSERT_EQ(written.size(), read.size());
    for (std::size_t i = 0; i < read.size(); ++i)
    {
        test::expectSameBody(written[i], read[i]);
    }
}


timeState stateAt(const std::string& name, label index = 0)
{
    timeState s;
    s.name = name;
    s.value = std::stod(name);
    s.index = index;
    s.deltaT = 1e-4;
    s.deltaT0 = 1e-4;
    return s;
}


std::vector<std::string> namesOf(const std::vector<timeInstant>& times)
{
    std::vector<std::string> names;
    for (const auto& t : times)
    {
        names.push_back(t.name);
    }
    return names;
}


// Entries of caseDir whose name starts with '.'.
std::vector<std::string> hiddenEntries(const fs::path& caseDir)
{
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(caseDir))
    {
        const std::string name = e.path().filename().string();
        if (name[0] == '.')
        {
            names.push_back(name);
        }
    }
    std::sort(names.begin(), names.end());
    return names;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Round trips * * * * * * * * * * * * * * //

TEST(timeDirectory, binaryRoundTripIsBitExact)
{
    scratchDir dir;
    const auto bodies = threeBodies(true);
    writeTimeDirectory(dir.path(), stateAt("0.25", 25), bodies,
                       writeFormat::binary);
    const auto read = readTimeDirectory(dir.path(), "0.25");
    expectSameBodies(bodies, read);
    // nextId is one past the largest id read, whatever was removed.
    EXPECT_EQ(read[2].name(), "water");
    EXPECT_EQ(read[2].nextId(), 998);
    EXPECT_EQ(read[0].name(), "gate");
    EXPECT_EQ(read[0].nDimensions(), 2);
    EXPECT_EQ(read[0].type(), bodyType::solid);
}


TEST(timeDirectory, asciiRoundTripIsExactAt17Digits)
{
    scratchDir dir;
    const auto bodies = threeBodies(true);
    writeTimeDirectory(dir.path(), stateAt("0"), bodies, writeFormat::ascii,
                       17);
    expectSameBodies(bodies, readTimeDirectory(dir.path(), "0"));
}


TEST(timeDirectory, layout)
{
    scratchDir dir;
    const auto bodies = threeBodies(false);
    writeTimeDirectory(dir.path(), stateAt("0.5"), bodies);
    const fs::path t = dir.path()/"0.5";
    for (const char* f :
        {"uniform/time", "water/bodyProperties", "water/position", "water/id",
         "water/U", "water/rho", "water/p", "water/cell", "tank/position",
         "gate/bodyProperties"})
    {
        EXPECT_TRUE(fs::is_regular_file(t/f)) << f;
    }
    const std::string position = readText(t/"water"/"position");
    EXPECT_NE(position.find("location    \"0.5/water\";"), std::string::npos);
    EXPECT_NE(position.find("object      position;"), std::string::npos);
    EXPECT_NE(readText(t/"uniform"/"time").find("location    \"0.5/uniform\";"),
              std::string::npos);

    const dictionary props = dictionary::fromFile(t/"gate"/"bodyProperties");
    EXPECT_EQ(props.keys(),
        (std::vector<std::string>{"type", "nDimensions", "dp"}));
    EXPECT_EQ(props.get<std::string>("type"), "solid");
    EXPECT_EQ(props.get<label>("nDimensions"), 2);
    EXPECT_EQ(props.get<scalar>("dp"), bodies[2].dp());
    // Nothing hidden is left behind.
    EXPECT_TRUE(hiddenEntries(dir.path()).empty());
}


TEST(timeDirectory, readSkipsHiddenAndBackupFiles)
{
    scratchDir dir;
    const auto bodies = threeBodies(false);
    writeTimeDirectory(dir.path(), stateAt("0"), bodies, writeFormat::binary);
    const fs::path water = dir.path()/"0"/"water";
    writeText(water/".rho.swp", "junk");
    writeText(water/"rho~", "junk");
    writeText(dir.path()/"0"/".hidden"/"x", "junk");
    writeText(dir.path()/"0"/"notes.txt", "a file next to the bodies");
    expectSameBodies(bodies, readTimeDirectory(dir.path(), "0"));
}


// * * * * * * * * * * * * * * * Finding times  * * * * * * * * * * * * * * //

TEST(timeDirectory, findTimesSortsNumericDirectories)
{
    scratchDir dir;
    const auto bodies = threeBodies(false);
    for (const char* t : {"0", "0.5", "1e-05", "10", "2", "0.05"})
    {
        writeTimeDirectory(dir.path(), stateAt(t), bodies,
                           writeFormat::binary);
    }
    for (const char* d : {"constant", "system", "0.orig", "VTK", "-x"})
    {
        fs::create_directories(dir.path()/d);
    }
    writeText(dir.path()/"3", "a file, not a time directory");
    writeText(dir.path()/"log.sphVcpmFsi", "");

    const auto times = findTimes(dir.path());
    EXPECT_EQ(namesOf(times),
        (std::vector<std::string>{"0", "1e-05", "0.05", "0.5", "2", "10"}));
    EXPECT_EQ(times[1].value, 1e-05);
    EXPECT_EQ(times[5].value, 10);

    expectMessage(catchFatal([&]{ findTimes(dir.path()/"none"); }),
        {"Cannot find case directory"});
}


// * * * * * * * * * * * * * * * Atomic writes  * * * * * * * * * * * * * * //

TEST(timeDirectory, interruptedWriteIsIgnored)
{
    scratchDir dir;
    const auto bodies = threeBodies(false);
    writeTimeDirectory(dir.path(), stateAt("0"), bodies, writeFormat::binary);

    // What a write killed half-way leaves: a hidden temporary directory
    // with a half-written field and no uniform/time.
    const fs::path tmp = dir.path()/".0.5.tmp.123";
    fs::copy(dir.path()/"0", tmp, fs::copy_options::recursive);
    fs::remove_all(tmp/"uniform");
    const std::string rho = readText(tmp/"water"/"rho");
    writeText(tmp/"water"/"rho", rho.substr(0, rho.size()/2));
    // ... and one that was moved aside while replacing a time.
    fs::copy(dir.path()/"0", dir.path()/".0.old.77",
             fs::copy_options::recursive);

    EXPECT_EQ(namesOf(findTimes(dir.path())), std::vector<std::string>{"0"});
    expectSameBodies(bodies, readTimeDirectory(dir.path(), "0"));
    const FatalError err =
        catchFatal([&]{ readTimeDirectory(dir.path(), "0.5"); });
    expectMessage(err, {"Cannot find time directory", "Times in the case: 0"});

    // The time can still be written; the leftovers stay hidden.
    const auto later = threeBodies(true);
    writeTimeDirectory(dir.path(), stateAt("0.5"), later, writeFormat::binary);
    EXPECT_EQ(namesOf(findTimes(dir.path())),
        (std::vector<std::string>{"0", "0.5"}));
    expectSameBodies(later, readTimeDirectory(dir.path(), "0.5"));
    EXPECT_EQ(hiddenEntries(dir.path()),
        (std::vector<std::string>{".0.5.tmp.123", ".0.old.77"}));
}


TEST(timeDirectory, overwritesAnExistingTime)
{
    scratchDir dir;
    const auto first = threeBodies(false);
    writeTimeDirectory(dir.path(), stateAt("0.5", 50), first);
    writeText(dir.path()/"0.5"/"stale"/"bodyProperties", "from before");

    // Fewer bodies, other sizes, other format.
    particleBody only = test::randomBody("water", bodyType::fluid, 3, 5, 9);
    writeTimeDirectory(dir.path(), stateAt("0.5", 51), {only},
                       writeFormat::binary);
    const auto read = readTimeDirectory(dir.path(), "0.5");
    ASSERT_EQ(read.size(), 1u);
    test::expectSameBody(only, read[0]);
    EXPECT_EQ(readTimeState(dir.path(), "0.5").index, 51);
    EXPECT_FALSE(fs::exists(dir.path()/"0.5"/"stale"));
    EXPECT_TRUE(hiddenEntries(dir.path()).empty());
}


TEST(timeDirectory, failedWriteLeavesNoTrace)
{
    scratchDir dir;
    const auto bodies = threeBodies(false);
    writeTimeDirectory(dir.path(), stateAt("1"), bodies, writeFormat::binary);

    // A field resized on its own makes the write fail half-way.
    std::vector<particleBody> bad = threeBodies(false);
    bad[1].scalarField("rho").pop_back();
    const FatalError err =
        catchFatal([&]{ writeTimeDirectory(dir.path(), stateAt("1"), bad); });
    expectMessage(err, {"Field 'rho' of body 'tank' has 299 values but the "
        "body has 300 particles"});
    // The old time is intact and no temporary directory is left.
    expectSameBodies(bodies, readTimeDirectory(dir.path(), "1"));
    EXPECT_TRUE(hiddenEntries(dir.path()).empty());

    catchFatal([&]{ writeTimeDirectory(dir.path(), stateAt("2"), bad); });
    EXPECT_FALSE(fs::exists(dir.path()/"2"));
    EXPECT_TRUE(hiddenEntries(dir.path()).empty());
}


TEST(timeDirectory, badWrites)
{
    scratchDir dir;
    const auto bodies = threeBodies(false);
    timeState s = stateAt("0");
    s.name = "zero";
    expectMessage(catchFatal([&]{ writeTimeDirectory(dir.path(), s, bodies); }),
        {"Invalid time name 'zero'"});
    s.name = ".0";
    expectMessage(catchFatal([&]{ writeTimeDirectory(dir.path(), s, bodies); }),
        {"Invalid time name '.0'"});

    std::vector<particleBody> twice = {bodies[0], bodies[0]};
    expectMessage
    (
        catchFatal([&]{ writeTimeDirectory(dir.path(), stateAt("0"), twice); }),
        {"Two bodies are called 'water'"}
    );
    expectMessage
    (
        catchFatal([&]
        {
            writeTimeDirectory(dir.path(), stateAt("0"), bodies,
                               writeFormat::ascii, 0);
        }),
        {"writePrecision 0 is out of range"}
    );
    EXPECT_TRUE(findTimes(dir.path()).empty());
    EXPECT_TRUE(hiddenEntries(dir.path()).empty());

    EXPECT_EQ(writeFormatFromName("ascii"), writeFormat::ascii);
    EXPECT_EQ(writeFormatFromName("binary"), writeFormat::binary);
    expectMessage(catchFatal([]{ writeFormatFromName("hdf5"); }),
        {"Unknown writeFormat 'hdf5'", "ascii binary"});
}


TEST(timeDirectory, writesIntoANewCaseDirectory)
{
    scratchDir dir;
    const fs::path caseDir = dir.path()/"new"/"case";
    writeTimeDirectory(caseDir, stateAt("0"), threeBodies(false));
    EXPECT_EQ(namesOf(findTimes(caseDir)), std::vector<std::string>{"0"});
}


// * * * * * * * * * * * * * * * * uniform/time  * * * * * * * * * * * * * //

TEST(timeDirectory, uniformTimeRoundTrip)
{
    scratchDir dir;
    timeState s;
    s.value = 0.1 + 0.2;
    s.name = "0.3";
    s.index = 4242;
    s.deltaT = 1e-5/3;
    s.deltaT0 = 0.9*s.deltaT;
    s.beginTime = 0.1;
    writeTimeDirectory(dir.path(), s, {});

    const timeState r = readTimeState(dir.path(), "0.3");
    EXPECT_EQ(r.value, s.value);
    EXPECT_EQ(r.name, "0.3");
    EXPECT_EQ(r.index, 4242);
    EXPECT_EQ(r.deltaT, s.deltaT);
    EXPECT_EQ(r.deltaT0, s.deltaT0);
    EXPECT_EQ(r.beginTime, 0.1);
    EXPECT_TRUE(readTimeDirectory(dir.path(), "0.3").empty());

    const dictionary d =
        dictionary::fromFile(dir.path()/"0.3"/"uniform"/"time");
    EXPECT_EQ(d.keys(), (std::vector<std::string>{"beginTime", "value", "name",
        "index", "deltaT", "deltaT0"}));
    EXPECT_EQ(d.get<std::string>("name"), "0.3");
    EXPECT_NE(readText(dir.path()/"0.3"/"uniform"/"time").find("\"0.3\""),
              std::string::npos);
}


TEST(timeDirectory, timeStateWithoutUniformTime)
{
    // 0/ as generateParticles writes it, without uniform/time.
    scratchDir dir;
    writeTimeDirectory(dir.path(), stateAt("1e-05", 7), threeBodies(false));
    fs::remove_all(dir.path()/"1e-05"/"uniform");
    const timeState r = readTimeState(dir.path(), "1e-05");
    EXPECT_EQ(r.value, 1e-05);
    EXPECT_EQ(r.name, "1e-05");
    EXPECT_EQ(r.index, 0);
    EXPECT_EQ(r.deltaT, 0);
    EXPECT_EQ(readTimeDirectory(dir.path(), "1e-05").size(), 3u);

    expectMessage(catchFatal([&]{ readTimeState(dir.path(), "2"); }),
        {"Cannot find time directory", "Times in the case: 1e-05"});
}


// * * * * * * * * * * * * * * * foamDictionary * * * * * * * * * * * * * * //

namespace
{

// Runs OpenFOAM's foamDictionary on file; returns its exit status and
// puts what it printed in output.
int foamDictionary(const fs::path& file, const std::string& args,
                   std::string& output)
{
    const std::string command = "bash -c 'source /usr/share/openfoam/etc/bashrc"
        " >/dev/null 2>&1; foamDictionary " + args + " \"" + file.string()
        + "\"' 2>&1";
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe)
    {
        return -1;
    }
    output.clear();
    char buf[4096];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof(buf), pipe)) > 0)
    {
        output.append(buf, n);
    }
    const int status = ::pclose(pipe);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

} // End anonymous namespace


TEST(timeDirectory, openFOAMReadsWhatWeWrite)
{
    if (!fs::exists("/usr/bin/foamDictionary")
     || !fs::exists("/usr/share/openfoam/etc/bashrc"))
    {
        GTEST_SKIP() << "OpenFOAM's foamDictionary is not installed";
    }
    scratchDir dir;
    particleBody body("water", bodyType::fluid, 3, 0.0125);
    body.resize(3);
    body.position() = {{0, 0, 0}, {0.1, -0.2, 3e-7}, {1, 2, 3}};
    body.addScalarField("rho") = {1000, 1000.5, 999.25};
    body.addLabelField("cell") = {4, -5, 6};
    timeState s = stateAt("0.5", 50);
    s.deltaT0 = 1e-4/3;
    writeTimeDirectory(dir.path(), s, {body}, writeFormat::ascii, 8);
    const fs::path t = dir.path()/"0.5";

    std::string out;
    EXPECT_EQ(foamDictionary(t/"water"/"rho", "-entry value -value", out), 0)
        << out;
    EXPECT_NE(out.find("List<scalar> 3(1000 1000.5 999.25)"),
              std::string::npos) << out;

    EXPECT_EQ(foamDictionary(t/"water"/"position", "-entry value -value", out),
              0) << out;
    EXPECT_NE(out.find("List<vector> 3((0 0 0) (0.1 -0.2 3e-07) (1 2 3))"),
              std::string::npos) << out;

    EXPECT_EQ(foamDictionary(t/"water"/"cell", "-entry value -value", out), 0)
        << out;
    EXPECT_NE(out.find("List<label> 3(4 -5 6)"), std::string::npos) << out;

    EXPECT_EQ(foamDictionary(t/"water"/"id", "", out), 0) << out;

    EXPECT_EQ(foamDictionary(t/"water"/"bodyProperties", "-keywords", out), 0)
        << out;
    EXPECT_EQ(out, "FoamFile\ntype\nnDimensions\ndp\n");
    EXPECT_EQ(foamDictionary(t/"water"/"bodyProperties", "-entry dp -value",
                             out), 0) << out;
    EXPECT_EQ(out, "0.0125\n");

    EXPECT_EQ(foamDictionary(t/"uniform"/"time", "-keywords", out), 0) << out;
    EXPECT_EQ(out,
        "FoamFile\nbeginTime\nvalue\nname\nindex\ndeltaT\ndeltaT0\n");
    EXPECT_EQ(foamDictionary(t/"uniform"/"time", "-entry index -value", out),
              0) << out;
    EXPECT_EQ(out, "50\n");
    EXPECT_EQ(foamDictionary(t/"uniform"/"time", "-entry name -value", out),
              0) << out;
    EXPECT_EQ(out, "\"0.5\"\n");

    // A broken field is refused by OpenFOAM as well (the check works).
    writeText(t/"water"/"broken", "FoamFile { format ascii; class "
        "scalarField; object broken; }\nvalue nonuniform List<scalar> 3(1 2;");
    EXPECT_NE(foamDictionary(t/"water"/"broken", "", out), 0) << out;
}
