/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// The .vtp byte layout (parsed back here: header attributes, offsets,
// appended block sizes, bit-exact values), the .vtp.series JSON, the time
// selection of post-processing tools and the case conversion.

#include "error.H"
#include "../testPrecision.H"
#include "../testTools.H"
#include "timeSelection.H"
#include "vtkCaseConverter.H"
#include "vtpWriter.H"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

using namespace sphvcpm;
namespace fs = std::filesystem;

namespace
{

using test::catchFatal;
using test::expectMessage;
using test::scratchDir;
using test::readText;

// A .vtp read back by hand, trusting nothing but the format's rules.
struct parsedArray
{
    std::string section;    // FieldData, PointData, Points, Verts, Lines,
                            // Polys
    std::string type;
    std::string name;
    int nComponents = 1;
    std::uint64_t offset = 0;
    std::uint64_t nBytes = 0;
    std::string bytes;      // the values
};

struct parsedVtp
{
    std::string header;     // up to and including '_'
    std::map<std::string, std::string> piece;   // Piece attributes
    std::vector<parsedArray> arrays;            // in header order
    std::string tail;       // after the last block

    const parsedArray& operator[](const std::string& name) const
    {
        for (const auto& a : arrays)
        {
            if (a.name == name)
            {
                return a;
            }
        }
        throw std::runtime_error("no array " + name);
    }
    bool has(const std::string& name) const
    {
        for (const auto& a : arrays)
        {
            if (a.name == name)
            {
                return true;
            }
        }
        return false;
    }
};

std::string attribute(const std::string& tag, const std::string& name)
{
    std::smatch m;
    if (std::regex_search(tag, m, std::regex(" " + name + "=\"([^\"]*)\"")))
    {
        return m[1];
    }
    return "";
}

parsedVtp parseVtp(const fs::path& file)
{
    const std::string s = readText(file);
    parsedVtp vtp;
    const std::string marker = "<AppendedData encoding=\"raw\">";
    const std::size_t appended = s.find(marker);
    EXPECT_NE(appended, std::string::npos);
    const std::size_t underscore = s.find('_', appended + marker.size());
    EXPECT_NE(underscore, std::string::npos);
    // Only blanks between the tag and '_'.
    EXPECT_EQ(s.substr(appended + marker.size(),
        underscore - appended - marker.size()).find_first_not_of(" \n"),
        std::string::npos);
    vtp.header = s.substr(0, underscore + 1);
    const std::size_t base = underscore + 1;

    std::smatch m;
    EXPECT_TRUE(std::regex_search(vtp.header, m, std::regex("<Piece [^>]*>")));
    for (const char* a : {"NumberOfPoints", "NumberOfVerts", "NumberOfLines",
                          "NumberOfStrips", "NumberOfPolys"})
    {
        vtp.piece[a] = attribute(m.str(), a);
    }

    // Each DataArray tag with the section it sits in.
    const std::regex tagRe("<(FieldData|PointData|Points|Verts|Lines|Polys)"
                           "( [^>]*)?>|<DataArray [^>]*/>");
    std::string section;
    std::uint64_t expectedOffset = 0;
    for (auto it = std::sregex_iterator(vtp.header.begin(),
             vtp.header.end(), tagRe);
         it != std::sregex_iterator(); ++it)
    {
        if ((*it)[1].matched)
        {
            section = (*it)[1];
            continue;
        }
        const std::string tag = it->str();
        parsedArray a;
        a.section = section;
        a.type = attribute(tag, "type");
        a.name = attribute(tag, "Name");
        EXPECT_EQ(attribute(tag, "format"), "appended") << tag;
        const std::string nc = attribute(tag, "NumberOfComponents");
        a.nComponents = nc.empty() ? 1 : std::stoi(nc);
        a.offset = std::stoull(attribute(tag, "offset"));
        // Blocks follow each other in header order without gaps.
        EXPECT_EQ(a.offset, expectedOffset) << a.name;
        EXPECT_LE(base + a.offset + 8, s.size());
        std::memcpy(&a.nBytes, s.data() + base + a.offset, 8);
        EXPECT_LE(base + a.offset + 8 + a.nBytes, s.size());
        a.bytes = s.substr(base + a.offset + 8, a.nBytes);
        expectedOffset = a.offset + 8 + a.nBytes;
        vtp.arrays.push_back(a);
    }
    vtp.tail = s.substr(base + expectedOffset);
    return vtp;
}

template<class T>
std::string bytesOf(const std::vector<T>& v)
{
    return std::string(reinterpret_cast<const char*>(v.data()),
                       v.size()*sizeof(T));
}

// A body with every kind of field and values that are not round in binary.
particleBody makeBody(int nDim, label n)
{
    particleBody body(nDim == 2 ? "plate" : "water",
                      nDim == 2 ? bodyType::solid : bodyType::fluid, nDim,
                      0.01);
    body.resize(n);
    auto& rho = body.addScalarField("rho");
    auto& U = body.addVectorField("U");
    auto& cellIndex = body.addLabelField("cellIndex");
    auto& position = body.position();
    auto& id = body.id();
    for (label i = 0; i < n; ++i)
    {
        position[i] = {0.1*i, std::sqrt(2.0)*i, nDim == 3 ? 1.0/(i + 3) : 0};
        rho[i] = 1000 + std::exp(-0.1*i);
        U[i] = {1.0/3 + i, -std::cbrt(i + 0.5), nDim == 3 ? M_PI*i : 0};
        cellIndex[i] = -7 + 3*i;
        id[i] = 100 + 2*i;
    }
    return body;
}

} // End anonymous namespace


TEST(vtp, layout3D)
{
    // Checks Float64 bytes (a single build writes Float32).
    SPHVCPM_DOUBLE_ONLY();
    scratchDir dir;
    const particleBody body = makeBody(3, 17);
    const fs::path file = dir.path()/"water_3.vtp";
    writeVtp(file, body, {}, 0.125);

    const parsedVtp vtp = parseVtp(file);
    EXPECT_EQ(vtp.header.rfind("<?xml version=\"1.0\"?>\n", 0), 0u);
    EXPECT_NE(vtp.header.find("<VTKFile type=\"PolyData\" version=\"1.0\""
        " byte_order=\"LittleEndian\" header_type=\"UInt64\">"),
        std::string::npos);
    EXPECT_EQ(vtp.piece.at("NumberOfPoints"), "17");
    EXPECT_EQ(vtp.piece.at("NumberOfVerts"), "17");
    EXPECT_EQ(vtp.piece.at("NumberOfPolys"), "0");
    EXPECT_EQ(vtp.tail, "\n  </AppendedData>\n</VTKFile>\n");

    // Every field but position (the Points) as PointData, sorted by name.
    std::vector<std::string> names;
    for (const auto& a : vtp.arrays)
    {
        names.push_back(a.section + "/" + a.name + "/" + a.type + "/"
            + std::to_string(a.nComponents));
    }
    EXPECT_EQ(names, (std::vector<std::string>{
        "FieldData/TimeValue/Float64/1",
        "PointData/U/Float64/3",
        "PointData/cellIndex/Int32/1",
        "PointData/id/Int32/1",
        "PointData/rho/Float64/1",
        "Points/Points/Float64/3",
        "Verts/connectivity/Int64/1",
        "Verts/offsets/Int64/1"}));

    // Sizes and bit-exact values.
    EXPECT_EQ(vtp["TimeValue"].bytes, bytesOf(std::vector<double>{0.125}));
    EXPECT_EQ(vtp["U"].nBytes, 17u*3*8);
    EXPECT_EQ(vtp["U"].bytes, bytesOf(body.vectorField("U")));
    EXPECT_EQ(vtp["rho"].nBytes, 17u*8);
    EXPECT_EQ(vtp["rho"].bytes, bytesOf(body.scalarField("rho")));
    EXPECT_EQ(vtp["cellIndex"].nBytes, 17u*4);
    EXPECT_EQ(vtp["cellIndex"].bytes, bytesOf(body.labelField("cellIndex")));
    EXPECT_EQ(vtp["id"].bytes, bytesOf(body.id()));
    EXPECT_EQ(vtp["Points"].bytes, bytesOf(body.position()));

    std::vector<std::int64_t> connectivity(17), offsets(17);
    for (int i = 0; i < 17; ++i)
    {
        connectivity[i] = i;
        offsets[i] = i + 1;
    }
    EXPECT_EQ(vtp["connectivity"].bytes, bytesOf(connectivity));
    EXPECT_EQ(vtp["offsets"].bytes, bytesOf(offsets));

    // Written atomically: no temporary file is left beside it.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()),
                            fs::directory_iterator()), 1);
}


TEST(vtp, planarBodyHasZeroZ)
{
    scratchDir dir;
    particleBody body = makeBody(2, 9);
    // Whatever z holds in memory, a 2D body is drawn in the x-y plane.
    body.position()[4].z = 42;
    const fs::path file = dir.path()/"plate_0.vtp";
    writeVtp(file, body);

    const parsedVtp vtp = parseVtp(file);
    EXPECT_FALSE(vtp.has("TimeValue"));
    std::vector<point> expected = body.position();
    for (auto& p : expected)
    {
        p.z = 0;
    }
    EXPECT_EQ(vtp["Points"].bytes, bytesOf(expected));
    EXPECT_EQ(vtp["Points"].nComponents, 3);
    // Vector fields keep three components in 2D.
    EXPECT_EQ(vtp["U"].nComponents, 3);
    EXPECT_EQ(vtp["U"].bytes, bytesOf(body.vectorField("U")));
}


TEST(vtp, selectedFieldsInGivenOrder)
{
    scratchDir dir;
    const particleBody body = makeBody(3, 5);
    const fs::path file = dir.path()/"water_1.vtp";
    writeVtp(file, body, {"rho", "id", "position", "notThere", "rho"});

    const parsedVtp vtp = parseVtp(file);
    std::vector<std::string> names;
    for (const auto& a : vtp.arrays)
    {
        names.push_back(a.name);
    }
    EXPECT_EQ(names, (std::vector<std::string>{"rho", "id", "Points",
        "connectivity", "offsets"}));
    EXPECT_EQ(vtp["rho"].bytes, bytesOf(body.scalarField("rho")));
}


TEST(vtp, emptyBodyAndLargeBody)
{
    // Checks Float64 bytes (a single build writes Float32).
    SPHVCPM_DOUBLE_ONLY();
    scratchDir dir;
    const particleBody empty = makeBody(3, 0);
    writeVtp(dir.path()/"empty.vtp", empty);
    const parsedVtp vtp = parseVtp(dir.path()/"empty.vtp");
    EXPECT_EQ(vtp.piece.at("NumberOfPoints"), "0");
    for (const auto& a : vtp.arrays)
    {
        EXPECT_EQ(a.nBytes, 0u) << a.name;
    }

    // More particles than one write chunk (131072): generated arrays stay
    // continuous across chunks.
    const label n = 300001;
    particleBody big("big", bodyType::fluid, 2, 0.01);
    big.resize(n);
    for (label i = 0; i < n; ++i)
    {
        big.position()[i] = {double(i), -double(i), 5.0};
    }
    writeVtp(dir.path()/"big.vtp", big);
    const parsedVtp bigVtp = parseVtp(dir.path()/"big.vtp");
    ASSERT_EQ(bigVtp["offsets"].nBytes, std::uint64_t(n)*8);
    ASSERT_EQ(bigVtp["Points"].nBytes, std::uint64_t(n)*24);
    const char* offsets = bigVtp["offsets"].bytes.data();
    const char* points = bigVtp["Points"].bytes.data();
    for (label i = 0; i < n; i += 997)
    {
        std::int64_t o;
        std::memcpy(&o, offsets + 8*i, 8);
        ASSERT_EQ(o, i + 1);
        double p[3];
        std::memcpy(p, points + 24*i, 24);
        ASSERT_EQ(p[0], double(i));
        ASSERT_EQ(p[2], 0.0);
    }
}


TEST(vtp, unwritableDirectoryIsFatal)
{
    scratchDir dir;
    const FatalError err = catchFatal([&]()
    {
        writeVtp(dir.path()/"missing"/"x.vtp", makeBody(2, 3));
    });
    expectMessage(err, {"Cannot open", "missing"});
}


// Surfaces and outlines (the free surface): Polys or Lines with offsets
// every nodesPerCell, the normals named on PointData, no Verts.
TEST(vtp, meshesOfTrianglesAndSegments)
{
    const scratchDir scratch("vtpMesh");
    const fs::path& dir = scratch.path();
    vtpMesh m;
    m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0.5}};
    m.connectivity = {0, 1, 2, 1, 3, 2};
    m.scalarFields.push_back({"p", {1.5, 2.5, 3.5, 4.5}});
    m.vectorFields.push_back({"Normals", std::vector<vec3>(4, {0, 0, 1})});
    m.normals = "Normals";
    writeVtpMesh(dir/"tri.vtp", m, 0.25);
    const parsedVtp tri = parseVtp(dir/"tri.vtp");
    EXPECT_EQ(tri.piece.at("NumberOfPoints"), "4");
    EXPECT_EQ(tri.piece.at("NumberOfPolys"), "2");
    EXPECT_EQ(tri.piece.at("NumberOfVerts"), "0");
    EXPECT_EQ(tri.piece.at("NumberOfLines"), "0");
    EXPECT_NE(tri.header.find("<PointData Normals=\"Normals\">"),
              std::string::npos);
    EXPECT_EQ(tri["connectivity"].section, "Polys");
    EXPECT_EQ(tri["connectivity"].bytes, bytesOf(m.connectivity));
    EXPECT_EQ(tri["offsets"].bytes, bytesOf(std::vector<std::int64_t>{3, 6}));
    EXPECT_EQ(tri["p"].bytes, bytesOf(m.scalarFields[0].second));
    EXPECT_EQ(tri["Normals"].nComponents, 3);
    EXPECT_EQ(tri["Points"].bytes, bytesOf(m.points));
    EXPECT_EQ(tri["TimeValue"].bytes, bytesOf(std::vector<double>{0.25}));
    EXPECT_NE(tri.tail.find("</VTKFile>"), std::string::npos);

    vtpMesh lines;
    lines.nodesPerCell = 2;
    lines.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
    lines.connectivity = {0, 1, 1, 2, 2, 0};
    writeVtpMesh(dir/"lines.vtp", lines);
    const parsedVtp seg = parseVtp(dir/"lines.vtp");
    EXPECT_EQ(seg.piece.at("NumberOfLines"), "3");
    EXPECT_EQ(seg.piece.at("NumberOfPolys"), "0");
    EXPECT_EQ(seg["offsets"].section, "Lines");
    EXPECT_EQ(seg["offsets"].bytes,
              bytesOf(std::vector<std::int64_t>{2, 4, 6}));
    EXPECT_FALSE(seg.has("TimeValue"));
    EXPECT_EQ(seg.header.find("Normals="), std::string::npos);

    // An empty surface (no fluid) is still a valid file.
    writeVtpMesh(dir/"empty.vtp", vtpMesh{});
    const parsedVtp empty = parseVtp(dir/"empty.vtp");
    EXPECT_EQ(empty.piece.at("NumberOfPoints"), "0");
    EXPECT_EQ(empty.piece.at("NumberOfPolys"), "0");

    vtpMesh odd = lines;
    odd.connectivity.pop_back();
    expectMessage(catchFatal([&] { writeVtpMesh(dir/"odd.vtp", odd); }),
                  {"5 connectivity entries for cells of 2 points"});
}


TEST(vtpSeries, json)
{
    scratchDir dir;
    const fs::path file = dir.path()/"water.vtp.series";
    writeVtpSeries(file, {
        {"water/water_0.vtp", 0},
        {"water/water_100.vtp", 0.1},
        {"water/water_300.vtp", 0.1 + 0.2},
        {"water/water_5.vtp", 1e-05},
        {"water/water_7.vtp", 12345.678901234567}});
    EXPECT_EQ(readText(file),
        "{\n"
        "  \"file-series-version\" : \"1.0\",\n"
        "  \"files\" : [\n"
        "    { \"name\" : \"water/water_0.vtp\", \"time\" : 0 },\n"
        "    { \"name\" : \"water/water_100.vtp\", \"time\" : 0.1 },\n"
        "    { \"name\" : \"water/water_300.vtp\", \"time\" :"
        " 0.30000000000000004 },\n"
        "    { \"name\" : \"water/water_5.vtp\", \"time\" : 1e-05 },\n"
        "    { \"name\" : \"water/water_7.vtp\", \"time\" :"
        " 12345.678901234567 }\n"
        "  ]\n"
        "}\n");

    writeVtpSeries(file, {});
    EXPECT_EQ(readText(file),
        "{\n  \"file-series-version\" : \"1.0\",\n  \"files\" : [\n  ]\n}\n");

    const FatalError err = catchFatal([&]()
    {
        writeVtpSeries(file, {{"a.vtp", std::nan("")}});
    });
    expectMessage(err, {"a.vtp", "not a finite number"});
}


TEST(vtpSeries, exactNumberRoundTrips)
{
    for (double x : {0.0, 0.1, 1.0/3, 2e-7, 1e300, -4.5, 5e-324})
    {
        // strtod: stod refuses the denormal 5e-324
        EXPECT_EQ(std::strtod(exactNumber(x).c_str(), nullptr), x)
            << exactNumber(x);
    }
    EXPECT_EQ(exactNumber(0.2), "0.2");
    EXPECT_EQ(exactNumber(3), "3");
}


namespace
{

std::vector<timeInstant> instants(const std::vector<std::string>& names)
{
    std::vector<timeInstant> times;
    for (const auto& n : names)
    {
        times.push_back({std::stod(n), n});
    }
    return times;
}

std::string selected(const std::string& ranges, bool latest = false,
                     bool noZero = false)
{
    const auto times = instants({"0", "0.1", "0.2", "0.3", "0.5", "1"});
    std::string s;
    for (const auto& t : timeSelection(ranges, latest, noZero).select(times))
    {
        s += (s.empty() ? "" : " ") + t.name;
    }
    return s;
}

} // End anonymous namespace


TEST(timeSelection, rangesAndLists)
{
    EXPECT_EQ(selected(""), "0 0.1 0.2 0.3 0.5 1");
    EXPECT_EQ(selected("0.2"), "0.2");
    EXPECT_EQ(selected("0:0.2"), "0 0.1 0.2");
    EXPECT_EQ(selected(":0.2"), "0 0.1 0.2");
    EXPECT_EQ(selected("0.3:"), "0.3 0.5 1");
    EXPECT_EQ(selected(":"), "0 0.1 0.2 0.3 0.5 1");
    EXPECT_EQ(selected("0.1:0.1"), "0.1");
    EXPECT_EQ(selected("0.11:0.19"), "");
    EXPECT_EQ(selected("0,0.5:"), "0 0.5 1");
    EXPECT_EQ(selected("1, 0.1"), "0.1 1");
    EXPECT_EQ(selected("0.1 0.3"), "0.1 0.3");
    EXPECT_EQ(selected(" 0.2 : 0.3 ;1 "), "0.2 0.3 1");
    EXPECT_EQ(selected("1e-1:2E-1"), "0.1 0.2");
    EXPECT_EQ(selected("+0.5"), "0.5");
    // A single value takes the nearest time, as OpenFOAM's timeSelector.
    EXPECT_EQ(selected("0.26"), "0.3");
    EXPECT_EQ(selected("7"), "1");
    EXPECT_EQ(selected("-1"), "0");
}


TEST(timeSelection, latestTimeAndNoZero)
{
    EXPECT_EQ(selected("", true), "1");
    EXPECT_EQ(selected("", false, true), "0.1 0.2 0.3 0.5 1");
    EXPECT_EQ(selected("0:0.2", false, true), "0.1 0.2");
    EXPECT_EQ(selected("0", false, true), "0.1");

    const auto onlyZero = instants({"0"});
    EXPECT_TRUE(timeSelection("", true, true).select(onlyZero).empty());
    EXPECT_TRUE(timeSelection().select({}).empty());
}


TEST(timeSelection, badSyntaxNamesTheOption)
{
    for (const std::string bad : {"abc", "0.1:x", "y:0.1", "0:1:2",
         "0.5:0.1", "", " , ", "1..2", "nan", "inf:", "0.1s", "(0 0.1)"})
    {
        const FatalError err = catchFatal([&]()
        {
            // Through the same path as -time: an empty value is an error.
            timeSelection sel(bad.empty() ? std::string(" ") : bad, false,
                              false);
        });
        expectMessage(err, {"-time '", "Expected a time"});
        EXPECT_FALSE(err.isIOError());
    }
    const FatalError err = catchFatal([]()
    {
        timeSelection("0.5:0.1", false, false);
    });
    expectMessage(err, {"Invalid -time '0.5:0.1'", "is empty"});
}


TEST(timeSelection, latestTimeWithTimeIsAnError)
{
    // They contradict each other: neither may win silently.
    const FatalError err = catchFatal([]()
    {
        timeSelection("0.1", true, false);
    });
    expectMessage(err, {"Options -time '0.1' and -latestTime conflict",
                        "Give one of them"});
    EXPECT_FALSE(err.isIOError());
}


TEST(timeSelection, nearestNotes)
{
    const auto times = instants({"0", "0.1", "0.6"});
    const auto notes = [&](const std::string& ranges, bool noZero = false)
    {
        std::string s;
        for (const auto& n : timeSelection(ranges, false, noZero)
                                 .nearestNotes(times))
        {
            s += (s.empty() ? "" : "|") + n;
        }
        return s;
    };
    EXPECT_EQ(notes("0.7"), "-time 0.7: the nearest time written is 0.6");
    EXPECT_EQ(notes("0.6"), "");
    EXPECT_EQ(notes("6e-1, 0.1:0.6"), "");
    EXPECT_EQ(notes("0.04,0.7"),
              "-time 0.04: the nearest time written is 0|"
              "-time 0.7: the nearest time written is 0.6");
    EXPECT_EQ(notes("0", true), "-time 0: the nearest time written is 0.1");
    EXPECT_EQ(notes(""), "");
    EXPECT_TRUE(timeSelection("0.7", false, false).nearestNotes({}).empty());
}


TEST(timeSelection, describe)
{
    EXPECT_EQ(timeSelection("0:1", false, true).describe(),
              "-time '0:1' -noZero");
    EXPECT_EQ(timeSelection("", true, true).describe(),
              "-latestTime -noZero");
    EXPECT_EQ(timeSelection().describe(), "the default (all times)");
}


namespace
{

void writeCaseTime(const fs::path& caseDir, const std::string& name,
                   label index, label n)
{
    timeState state;
    state.name = name;
    state.value = std::stod(name);
    state.index = index;
    particleBody body = makeBody(3, n);
    body.scalarField("rho")[0] = state.value;
    particleBody wall("wall", bodyType::wall, 3, 0.01);
    wall.resize(2);
    writeTimeDirectory(caseDir, state, {body, wall}, writeFormat::binary);
}

} // End anonymous namespace


TEST(vtkCaseConverter, convertsAndKeepsSeries)
{
    scratchDir dir;
    const fs::path& caseDir = dir.path();
    writeCaseTime(caseDir, "0", 0, 4);
    writeCaseTime(caseDir, "0.25", 25, 6);

    {
        vtkCaseConverter conv(caseDir);
        ASSERT_EQ(conv.times().size(), 2u);
        const auto out = conv.convert(conv.times()[0]);
        ASSERT_EQ(out.size(), 2u);
        EXPECT_EQ(out[1].body, "water");
        EXPECT_EQ(out[1].nParticles, 4);
        EXPECT_EQ(out[1].file.generic_string(), "VTK/water/water_0.vtp");
        conv.writeSeries();
    }
    EXPECT_EQ(readText(caseDir/"VTK"/"water.vtp.series"),
        "{\n  \"file-series-version\" : \"1.0\",\n  \"files\" : [\n"
        "    { \"name\" : \"water/water_0.vtp\", \"time\" : 0 }\n  ]\n}\n");

    // A later conversion of the latest time adds to the series.
    {
        vtkCaseConverter conv(caseDir);
        const auto out = conv.convert(conv.times()[1]);
        EXPECT_EQ(out[1].file.generic_string(), "VTK/water/water_25.vtp");
        conv.writeSeries();
    }
    EXPECT_EQ(readText(caseDir/"VTK"/"water.vtp.series"),
        "{\n  \"file-series-version\" : \"1.0\",\n  \"files\" : [\n"
        "    { \"name\" : \"water/water_0.vtp\", \"time\" : 0 },\n"
        "    { \"name\" : \"water/water_25.vtp\", \"time\" : 0.25 }\n"
        "  ]\n}\n");
    const parsedVtp vtp = parseVtp(caseDir/"VTK"/"water"/"water_25.vtp");
    EXPECT_EQ(vtp.piece.at("NumberOfPoints"), "6");
    EXPECT_EQ(vtp["TimeValue"].bytes, bytesOf(std::vector<double>{0.25}));
    std::vector<scalar> rho = makeBody(3, 6).scalarField("rho");
    rho[0] = 0.25;
    EXPECT_EQ(vtp["rho"].bytes, bytesOf(rho));
    EXPECT_TRUE(fs::exists(caseDir/"VTK"/"wall.vtp.series"));
}


TEST(vtkCaseConverter, restrictedFields)
{
    scratchDir dir;
    writeCaseTime(dir.path(), "0", 0, 3);
    vtkCaseConverter conv(dir.path());
    conv.restrictFields({"U"}, conv.times());
    conv.convert(conv.times()[0]);
    const parsedVtp vtp = parseVtp(dir.path()/"VTK"/"water"/"water_0.vtp");
    std::vector<std::string> names;
    for (const auto& a : vtp.arrays)
    {
        names.push_back(a.name);
    }
    EXPECT_EQ(names, (std::vector<std::string>{"TimeValue", "U", "id",
        "Points", "connectivity", "offsets"}));

    const FatalError err = catchFatal([&]()
    {
        conv.restrictFields({"rho", "bogus"}, conv.times());
    });
    expectMessage(err, {"'bogus'", "-fields", "Fields there:", " U ",
                        " rho"});
}


TEST(vtkCaseConverter, sameIndexTwiceIsFatalForThoseTimes)
{
    // A copied time directory (0.2 with 0.1's index 3): converting either
    // is an error naming both; the other times convert, and the series
    // leave the two out (their files cannot be told apart).
    scratchDir dir;
    writeCaseTime(dir.path(), "0.1", 3, 2);
    writeCaseTime(dir.path(), "0.2", 3, 2);
    writeCaseTime(dir.path(), "0.3", 5, 2);
    testing::internal::CaptureStderr();
    vtkCaseConverter conv(dir.path());
    const std::string warned = testing::internal::GetCapturedStderr();
    EXPECT_NE(warned.find("Times 0.1 and 0.2"), std::string::npos) << warned;
    EXPECT_NE(warned.find("neither can be converted"), std::string::npos);
    for (const char* shared : {"0.1", "0.2"})
    {
        const FatalError err = catchFatal([&]()
        {
            conv.convert(conv.times()[std::string(shared) == "0.1" ? 0 : 1]);
        });
        expectMessage(err, {"Times 0.1 and 0.2", "same time index 3",
                            "choose them with -time"});
    }
    ASSERT_EQ(conv.times()[2].name, "0.3");
    EXPECT_FALSE(conv.convert(conv.times()[2]).empty());
    conv.writeSeries();
    std::ifstream series(dir.path()/"VTK"/"water.vtp.series");
    const std::string text((std::istreambuf_iterator<char>(series)),
                           std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("water_5.vtp"), std::string::npos) << text;
    EXPECT_EQ(text.find("water_3.vtp"), std::string::npos) << text;
}


TEST(vtkCaseConverter, noTimesIsFatal)
{
    scratchDir dir;
    vtkCaseConverter conv(dir.path());
    EXPECT_TRUE(conv.times().empty());
    const FatalError err = catchFatal([&]()
    {
        timeSelection().selectOrFail(dir.path(), conv.times());
    });
    expectMessage(err, {"No time directories", dir.path().string()});

    writeCaseTime(dir.path(), "0.1", 1, 2);
    const FatalError err2 = catchFatal([&]()
    {
        timeSelection("5:6", false, false).selectCase(dir.path());
    });
    expectMessage(err2, {"No time of case", "-time '5:6'",
                         "The case has times: 0.1"});
}
