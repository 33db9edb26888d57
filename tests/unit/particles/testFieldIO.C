/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Field files: their ascii and binary layout, round trips (binary bit for
// bit, ascii exact at 17 digits and rounded as printf at fewer), and the
// forms OpenFOAM writes that we also read. Malformed files are in
// testFieldErrors.C. The disabled test fieldIO.DISABLED_speed measures
// reading and writing a million particles (run it with
// --gtest_also_run_disabled_tests).

#include "timeDirectory.H"
#include "foamFile.H"
#include "testParticleTools.H"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <random>

using namespace sphvcpm;
using test::readText;
using test::scratchDir;
using test::writeText;

namespace fs = std::filesystem;

namespace
{

// Writes every field of body to dir in format, reads them back into a
// fresh body of the same properties.
particleBody roundTrip(const particleBody& body, const fs::path& dir,
                       writeFormat format, int precision)
{
    fs::create_directories(dir);
    particleBody back(body.name(), body.type(), body.nDimensions(), body.dp());
    for (const auto& f : body.fieldNames())
    {
        writeField(dir/f, body, f, format, precision, "0/" + body.name());
    }
    for (const auto& f : body.fieldNames())
    {
        readField(dir/f, back);
    }
    return back;
}


std::string header(const std::string& format, const std::string& cls,
                   const std::string& location, const std::string& object)
{
    std::ostringstream os;
    foamFileHeader h;
    h.format = format;
    h.className = cls;
    h.location = location;
    h.object = object;
    writeFoamFileHeader(os, h);
    return os.str();
}


std::string end()
{
    std::ostringstream os;
    writeFoamFileEnd(os);
    return os.str();
}


std::string printfG(scalar v, int precision)
{
    char buf[64];
    std::snprintf(buf, sizeof(buf), "%.*g", precision, v);
    return buf;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * Layout  * * * * * * * * * * * * * * * //

TEST(fieldIO, asciiLayout)
{
    scratchDir dir;
    particleBody body("water", bodyType::fluid, 3, 0.01);
    body.resize(3);
    body.position()[1] = {0.1, -0.2, 3e-7};
    auto& rho = body.addScalarField("rho", 1000);
    rho = {1000, 1000.5, -2};
    body.addLabelField("cell")[2] = -7;

    writeField(dir.path()/"rho", body, "rho", writeFormat::ascii, 6,
               "0.5/water");
    EXPECT_EQ(readText(dir.path()/"rho"),
        header("ascii", "scalarField", "0.5/water", "rho")
      + "value           nonuniform List<scalar> \n3\n(\n1000\n1000.5\n-2\n)\n;"
      + end());

    writeField(dir.path()/"position", body, "position", writeFormat::ascii, 6,
               "0.5/water");
    EXPECT_EQ(readText(dir.path()/"position"),
        header("ascii", "vectorField", "0.5/water", "position")
      + "value           nonuniform List<vector> \n3\n(\n(0 0 0)\n"
        "(0.1 -0.2 3e-07)\n(0 0 0)\n)\n;" + end());

    writeField(dir.path()/"cell", body, "cell", writeFormat::ascii, 6);
    EXPECT_EQ(readText(dir.path()/"cell"),
        header("ascii", "labelField", "", "cell")
      + "value           nonuniform List<label> \n3\n(\n0\n0\n-7\n)\n;"
      + end());
}


TEST(fieldIO, binaryLayout)
{
    scratchDir dir;
    particleBody body("gate", bodyType::solid, 2, 0.01);
    body.resize(2);
    body.position() = {{0.1, 0.2, 0}, {-1, 1e-300, 0}};
    writeField(dir.path()/"position", body, "position", writeFormat::binary, 6,
               "1/gate");
    writeField(dir.path()/"id", body, "id", writeFormat::binary, 6, "1/gate");

    std::ostringstream os;
    foamFileHeader h;
    h.format = "binary";
    h.className = "vectorField";
    h.location = "1/gate";
    h.object = "position";
    writeFoamFileHeader(os, h);
    // 64-bit scalars on disk in every build (a single build widens).
    std::vector<double> wide;
    for (const point& x : body.position())
    {
        wide.insert(wide.end(), {double(x.x), double(x.y), double(x.z)});
    }
    const std::string raw(reinterpret_cast<const char*>(wide.data()),
                          wide.size()*sizeof(double));
    const std::string text = readText(dir.path()/"position");
    EXPECT_EQ(text, os.str() + "value           nonuniform List<vector> 2("
        + raw + ");" + end());
    EXPECT_NE(text.find("arch        \"" + archString() + "\";"),
              std::string::npos);
    EXPECT_EQ(archString(), "LSB;label=32;scalar=64");

    const std::string ids = readText(dir.path()/"id");
    EXPECT_NE(ids.find(std::string("List<label> 2(\0\0\0\0\1\0\0\0);", 24)),
              std::string::npos);
}


// * * * * * * * * * * * * * * * * Round trips * * * * * * * * * * * * * * //

TEST(fieldIO, binaryRoundTripIsBitExact)
{
    scratchDir dir;
    for (int nDim : {2, 3})
    {
        // Any finite bit pattern: denormals, -0, the extremes.
        particleBody body = test::randomBody("b", bodyType::fluid, nDim,
                                             2000, 7 + nDim, true);
        body.scalarField("rho")[0] = -0.0;
        body.scalarField("rho")[1] = std::numeric_limits<scalar>::denorm_min();
        body.scalarField("rho")[2] = std::numeric_limits<scalar>::max();
        body.labelField("cell")[0] = std::numeric_limits<label>::min();
        const particleBody back = roundTrip(body,
            dir.path()/std::to_string(nDim), writeFormat::binary, 6);
        test::expectSameBody(body, back);
        EXPECT_EQ(back.nextId(), 2000);
        EXPECT_TRUE(std::signbit(back.scalarField("rho")[0]));
    }
}


TEST(fieldIO, asciiRoundTripExactAt17Digits)
{
    scratchDir dir;
    for (int nDim : {2, 3})
    {
        particleBody body = test::randomBody("b", bodyType::wall, nDim,
                                             3000, 3 + nDim, true);
        auto& rho = body.scalarField("rho");
        rho[0] = -0.0;
        rho[1] = std::numeric_limits<scalar>::denorm_min();
        rho[2] = std::numeric_limits<scalar>::max();
        rho[3] = -std::numeric_limits<scalar>::min();
        rho[4] = 0.1 + 0.2;
        body.labelField("cell")[0] = std::numeric_limits<label>::min();
        body.labelField("cell")[1] = std::numeric_limits<label>::max();
        const particleBody back = roundTrip(body,
            dir.path()/std::to_string(nDim), writeFormat::ascii, 17);
        test::expectSameBody(body, back);
    }
}


TEST(fieldIO, asciiWritesTheRequestedPrecision)
{
    scratchDir dir;
    particleBody body = test::randomBody("b", bodyType::fluid, 3, 500, 1);
    for (int precision : {1, 3, 6, 10, 15})
    {
        const fs::path sub = dir.path()/std::to_string(precision);
        const particleBody back =
            roundTrip(body, sub, writeFormat::ascii, precision);
        const std::string text = readText(sub/"rho");
        for (label i = 0; i < body.size(); ++i)
        {
            // What printf("%.*g") gives, which reads back as the same.
            const std::string s = printfG(body.scalarField("rho")[i],
                                          precision);
            EXPECT_NE(text.find("\n" + s + "\n"), std::string::npos) << s;
            EXPECT_EQ(back.scalarField("rho")[i],
                      scalar(std::strtod(s.c_str(), 0)));
            const point& p = body.position()[i];
            const std::string v = "(" + printfG(p.x, precision) + " "
                + printfG(p.y, precision) + " " + printfG(p.z, precision)
                + ")";
            EXPECT_NE(readText(sub/"position").find("\n" + v + "\n"),
                      std::string::npos) << v;
        }
        // Ids and labels are exact whatever the precision.
        EXPECT_EQ(back.labelField("cell"), body.labelField("cell"));
        EXPECT_EQ(back.id(), body.id());
    }
}


TEST(fieldIO, emptyFields)
{
    scratchDir dir;
    const particleBody body("none", bodyType::wall, 3, 0.1);
    for (writeFormat f : {writeFormat::ascii, writeFormat::binary})
    {
        const fs::path sub = dir.path()/(f == writeFormat::ascii ? "a" : "b");
        const particleBody back = roundTrip(body, sub, f, 6);
        EXPECT_EQ(back.size(), 0);
        EXPECT_EQ(back.nextId(), 0);
    }
}


TEST(fieldIO, largeFieldAcrossChunks)
{
    // More values than one formatting chunk (32768) and batch.
    scratchDir dir;
    particleBody body = test::randomBody("big", bodyType::fluid, 3, 1100000,
                                         2);
    for (const char* f : {"position", "rho", "cell", "id"})
    {
        writeField(dir.path()/f, body, f, writeFormat::ascii, 17);
    }
    particleBody back("big", bodyType::fluid, 3, body.dp());
    for (const char* f : {"position", "rho", "cell", "id"})
    {
        readField(dir.path()/f, back);
    }
    EXPECT_EQ(back.position(), body.position());
    EXPECT_EQ(back.scalarField("rho"), body.scalarField("rho"));
    EXPECT_EQ(back.labelField("cell"), body.labelField("cell"));
    EXPECT_EQ(back.id(), body.id());
}


// * * * * * * * * * * * * * * * Other layouts  * * * * * * * * * * * * * * //

TEST(fieldIO, readsOpenFOAMsOtherAsciiForms)
{
    // One line, comments, N{v} (OpenFOAM's form of a uniform list), a
    // leading '+', CRLF line ends, no trailing divider.
    scratchDir dir;
    const std::string top = header("ascii", "scalarField", "", "rho");
    writeText(dir.path()/"rho", top
        + "// a comment\nvalue nonuniform /* inline */ List<scalar> "
          "4(1 +2.5 -3e2\r\n4);\r\n// end\n");
    writeText(dir.path()/"position",
        header("ascii", "vectorField", "", "position")
      + "value nonuniform List<vector> 4{( 1 2 3 )};");
    writeText(dir.path()/"cell", header("ascii", "labelField", "", "cell")
      + "value nonuniform List<label> 4{-7};");
    writeText(dir.path()/"id", header("ascii", "labelField", "", "id")
      + "value nonuniform List<label>\n4\n(\n3 1\n0 9\n)\n;\n");

    particleBody body("b", bodyType::fluid, 3, 0.1);
    for (const char* f : {"rho", "position", "cell", "id"})
    {
        readField(dir.path()/f, body);
    }
    EXPECT_EQ(body.scalarField("rho"), (std::vector<scalar>{1, 2.5, -300, 4}));
    EXPECT_EQ(body.position(), std::vector<point>(4, point{1, 2, 3}));
    EXPECT_EQ(body.labelField("cell"), std::vector<label>(4, -7));
    EXPECT_EQ(body.id(), (std::vector<label>{3, 1, 0, 9}));
    // Reading ids restores the next id: one past the largest.
    EXPECT_EQ(body.nextId(), 10);
    body.append({0, 0, 0});
    EXPECT_EQ(body.id().back(), 10);
}


TEST(fieldIO, readsUniformValues)
{
    // 'value uniform v;' as an OpenFOAM user writes it in 0/<body>/: every
    // particle of the body (its size from position, read first) gets v.
    scratchDir dir;
    const fs::path bodyDir = dir.path()/"0"/"water";
    writeTimeDirectory(dir.path(), timeState(),
                       {test::randomBody("water", bodyType::fluid, 3, 5, 7)});
    writeText(bodyDir/"U", header("ascii", "vectorField", "0/water", "U")
      + "value           uniform (0.5 -1 2e-3);\n" + end());
    writeText(bodyDir/"rho", header("ascii", "scalarField", "0/water", "rho")
      + "value uniform 1000; // fresh water\n" + end());
    writeText(bodyDir/"cell", header("ascii", "labelField", "0/water",
                                     "cell")
      + "value uniform\n    -3\n;\n");

    const std::vector<particleBody> bodies =
        readTimeDirectory(dir.path(), "0");
    ASSERT_EQ(bodies.size(), 1u);
    const particleBody& water = bodies[0];
    ASSERT_EQ(water.size(), 5);
    EXPECT_EQ(water.vectorField("U"),
              std::vector<vec3>(5, vec3{0.5, -1, scalar(2e-3)}));
    EXPECT_EQ(water.scalarField("rho"), std::vector<scalar>(5, 1000));
    EXPECT_EQ(water.labelField("cell"), std::vector<label>(5, -3));

    // Also in a body read field by field, and in a binary-format file
    // (OpenFOAM writes uniform values as text there too).
    particleBody body = test::randomBody("b", bodyType::fluid, 3, 4, 2);
    writeText(dir.path()/"p", header("binary", "scalarField", "", "p")
      + "value uniform 0;\n");
    readField(dir.path()/"p", body);
    EXPECT_EQ(body.scalarField("p"), std::vector<scalar>(4, 0));
}


TEST(fieldIO, readIntoBodyOfTheSameSize)
{
    scratchDir dir;
    particleBody body = test::randomBody("b", bodyType::fluid, 3, 10, 4);
    writeField(dir.path()/"rho", body, "rho", writeFormat::binary, 6);
    particleBody other = test::randomBody("b", bodyType::fluid, 3, 10, 5);
    readField(dir.path()/"rho", other);
    EXPECT_EQ(other.scalarField("rho"), body.scalarField("rho"));
    // A field the body did not have is added.
    other.removeField("rho");
    readField(dir.path()/"rho", other);
    EXPECT_EQ(other.scalarField("rho"), body.scalarField("rho"));
}


// * * * * * * * * * * * * * * * * * Speed * * * * * * * * * * * * * * * * //

TEST(fieldIO, DISABLED_speed)
{
    scratchDir dir;
    const label n = 1000000;
    const particleBody body =
        test::randomBody("water", bodyType::fluid, 3, n, 9);
    const std::vector<std::string> fields = {"position", "U", "rho", "id"};
    using clock = std::chrono::steady_clock;
    for (writeFormat f : {writeFormat::ascii, writeFormat::binary})
    {
        for (int precision : {6, 17})
        {
            if (f == writeFormat::binary && precision == 17)
            {
                continue;
            }
            const auto t0 = clock::now();
            std::uintmax_t bytes = 0;
            for (const auto& field : fields)
            {
                writeField(dir.path()/field, body, field, f, precision);
                bytes += fs::file_size(dir.path()/field);
            }
            const auto t1 = clock::now();
            particleBody back("water", bodyType::fluid, 3, body.dp());
            for (const auto& field : fields)
            {
                readField(dir.path()/field, back);
            }
            const auto t2 = clock::now();
            const double w = std::chrono::duration<double>(t1 - t0).count();
            const double r = std::chrono::duration<double>(t2 - t1).count();
            std::printf("%s precision %2d, %d particles (position U rho id, "
                "%.1f MB): write %.3f s (%.0f MB/s), read %.3f s "
                "(%.0f MB/s)\n",
                f == writeFormat::ascii ? "ascii " : "binary", precision, n,
                bytes/1e6, w, bytes/1e6/w, r, bytes/1e6/r);
            EXPECT_EQ(back.size(), n);
        }
    }
}
