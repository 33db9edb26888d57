/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Malformed field files, body directories and uniform/time: each must stop
// with a FatalError naming the file, the line (ascii) and what was
// expected. The files are good ones written by writeField and then broken
// by hand, as a user or a crash would.

#include "timeDirectory.H"
#include "testParticleTools.H"

#include <gtest/gtest.h>

using namespace sphvcpm;
using test::catchFatal;
using test::expectError;
using test::lineOf;
using test::readText;
using test::scratchDir;
using test::writeText;

namespace fs = std::filesystem;

namespace
{

// water: 3 particles with rho, cell and known values.
particleBody water(label n = 3)
{
    particleBody body("water", bodyType::fluid, 3, 0.01);
    body.resize(n);
    auto& rho = body.addScalarField("rho");
    auto& cell = body.addLabelField("cell");
    for (label i = 0; i < n; ++i)
    {
        body.position()[i] = {0.5*i, 0.25*i, 1.0*i};
        rho[i] = 1000 + 0.5*i;
        cell[i] = i % 2 ? -6 : 5;
    }
    return body;
}


class fieldErrors : public ::testing::Test
{
protected:
    scratchDir dir_;

    // Text of a good file of field f of water().
    std::string good(const std::string& f,
                     writeFormat format = writeFormat::ascii) const
    {
        const fs::path file = dir_.path()/"good"/f;
        fs::create_directories(file.parent_path());
        writeField(file, water(), f, format, 6, "0/water");
        return readText(file);
    }

    // Writes text as field f and reads it into a body of size n (0: an
    // empty body); returns the error, which names the file.
    FatalError broken(const std::string& f, const std::string& text,
                      label n = 0)
    {
        file_ = (dir_.path()/"broken"/f).string();
        writeText(file_, text);
        particleBody body = n ? water(n)
            : particleBody("water", bodyType::fluid, 3, 0.01);
        return catchFatal([&]{ readField(file_, body); });
    }

    std::string file_;
};


std::string replace(std::string text, const std::string& from,
                    const std::string& to)
{
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "no '" << from << "' in the file";
    if (at != std::string::npos)
    {
        text.replace(at, from.size(), to);
    }
    return text;
}


int lastLine(const std::string& text)
{
    return 1 + int(std::count(text.begin(), text.end(), '\n'));
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * Header  * * * * * * * * * * * * * * * //

TEST_F(fieldErrors, missingHeader)
{
    const FatalError err = broken("rho",
        "value nonuniform List<scalar> 3(1 2 3);\n");
    expectError(err, file_, 1, {"Missing FoamFile header",
        "found 'value'"});

    const std::string text = "// no header\n\nrho 1;\n" + good("rho");
    expectError(broken("rho", text), file_, 3, {"Missing FoamFile header"});
    expectError(broken("rho", ""), file_, 1, {"Missing FoamFile header",
        "found end of file"});
}


TEST_F(fieldErrors, unterminatedHeader)
{
    const std::string text = replace(good("rho"), "}\n", "\n");
    expectError(broken("rho", text), file_, lineOf(text, "FoamFile"),
        {"Unterminated FoamFile header"});
}


TEST_F(fieldErrors, unknownClassOrFormat)
{
    std::string text = replace(good("rho"), "class       scalarField",
                               "class       volScalarField");
    expectError(broken("rho", text), file_, lineOf(text, "class"),
        {"Keyword 'class': unknown value 'volScalarField'",
         "scalarField", "vectorField", "labelField"});

    text = replace(good("rho"), "format      ascii", "format      text");
    expectError(broken("rho", text), file_, lineOf(text, "format"),
        {"Keyword 'format': unknown value 'text'", "ascii", "binary"});
}


TEST_F(fieldErrors, classDoesNotMatchList)
{
    const std::string text = replace(good("rho"), "class       scalarField",
                                      "class       vectorField");
    expectError(broken("rho", text), file_, lineOf(text, "value"),
        {"Expected 'List<vector>' (the header says class vectorField), "
         "found 'List<scalar>'"});
}


TEST_F(fieldErrors, classDoesNotMatchBodyField)
{
    // position is a vectorField of every body.
    std::string text = replace(good("rho"), "object      rho",
                               "object      position");
    expectError(broken("position", text), file_, lineOf(text, "class"),
        {"Field 'position' of body 'water' is a vectorField, the file holds "
         "a scalarField"});
}


TEST_F(fieldErrors, archMismatch)
{
    const std::string bin = good("cell", writeFormat::binary);
    std::string text = replace(bin, "label=32", "label=64");
    expectError(broken("cell", text), file_, lineOf(text, "arch"),
        {"Binary file written for another architecture",
         "arch \"LSB;label=64;scalar=64\"",
         "the file has 64-bit labels, this build 32-bit"});

    text = replace(good("rho", writeFormat::binary), "scalar=64", "scalar=32");
    expectError(broken("rho", text), file_, lineOf(text, "arch"),
        {"the file has 32-bit scalars, this build 64-bit"});

    text = replace(bin, "LSB", "MSB");
    expectError(broken("cell", text), file_, lineOf(text, "arch"),
        {"the file is big-endian (MSB)"});
}


// * * * * * * * * * * * * * * * * The entry  * * * * * * * * * * * * * * * //

TEST_F(fieldErrors, notTheValueEntry)
{
    std::string text = replace(good("rho"), "value  ", "values ");
    expectError(broken("rho", text), file_, lineOf(text, "values"),
        {"Expected the entry 'value' after the FoamFile header, "
         "found 'values'"});

    text = replace(good("rho"), "nonuniform", "unifrom");
    expectError(broken("rho", text), file_, lineOf(text, "unifrom"),
        {"Expected 'uniform' or 'nonuniform' after 'value', found "
         "'unifrom'"});
}


TEST_F(fieldErrors, badUniformValue)
{
    // Headers of a scalar field (rho) and a vector field (U).
    const std::string rho = good("rho");
    const std::string rhoHead = rho.substr(0, rho.find("value"));
    const std::string head = replace(rhoHead, "scalarField", "vectorField");
    const int line = lastLine(head);   // of the value entry

    // A scalar where the header says vectorField, and the other way round.
    std::string text = head + "value uniform 0;\n";
    expectError(broken("U", text, 3), file_, line,
        {"The uniform value '0' is not a vector: expected '(x y z)' (field "
         "'U', the header says class vectorField)"});
    text = rhoHead + "value uniform (0 0 0);\n";
    expectError(broken("rho", text, 3), file_, line,
        {"The uniform value '(0 0 0)' is not a number (field 'rho', the "
         "header says class scalarField)"});

    // Two components, no value, no ';', something after it.
    expectError(broken("U", head + "value uniform (1 2);\n", 3), file_,
        line, {"The uniform value '(1 2)' is not a vector: it has fewer "
               "than 3 components"});
    expectError(broken("U", head + "value uniform ;\n", 3), file_, line,
        {"Expected a vector after 'uniform' (field 'U'", "found ';'"});
    expectError(broken("U", head + "value uniform (1 2 3)\n", 3), file_,
        line + 1, {"Expected ';' after the uniform value, found end of "
                   "file"});
    expectError(broken("U", head + "value uniform (1 2 3); x 1;\n", 3),
        file_, line, {"Unexpected 'x' after the value entry"});

    // An empty body: a uniform value cannot tell how many particles.
    expectError(broken("U", head + "value uniform (1 2 3);\n"), file_, line,
        {"'value uniform' gives one value to every particle, but body "
         "'water' has none yet", "'position' field, read first"});
}


TEST_F(fieldErrors, badCount)
{
    std::string text = replace(good("rho"), "\n3\n(", "\n-3\n(");
    expectError(broken("rho", text), file_, lineOf(text, "-3"),
        {"Expected the number of values N before the list, found '-3'"});

    text = replace(good("rho"), "\n3\n(", "\nthree\n(");
    expectError(broken("rho", text), file_, lineOf(text, "three"),
        {"Expected the number of values N", "found 'three'"});

    text = replace(good("rho"), "\n3\n(", "\n99999999999\n(");
    expectError(broken("rho", text), file_, lineOf(text, "9999"),
        {"The number of values '99999999999' exceeds the largest label"});

    // An N the file cannot hold is refused before anything is allocated.
    text = replace(good("rho"), "\n3\n(", "\n2000000000\n(");
    expectError(broken("rho", text), file_, lineOf(text, "2000000000"),
        {"Truncated data: 2000000000 scalar values need at least "
         "4000000001 more bytes", "a wrong count N or a truncated file"});
}


TEST_F(fieldErrors, fewerValuesThanCount)
{
    const std::string text = replace(good("rho"), "\n3\n(", "\n5\n(");
    expectError(broken("rho", text), file_, lineOf(text, ")\n;"),
        {"Found ')' after 3 values, expected 5",
         "the count N does not match the list"});
}


TEST_F(fieldErrors, moreValuesThanCount)
{
    const std::string text = replace(good("rho"), "\n3\n(", "\n2\n(");
    expectError(broken("rho", text), file_, lineOf(text, "1001"),
        {"Expected ')' after 2 values, found '1001'",
         "the list has more values than N"});
}


TEST_F(fieldErrors, missingCloseParenthesis)
{
    const std::string text = replace(good("rho"), "1001\n)\n;", "1001\n;");
    expectError(broken("rho", text), file_, lineOf(text, "1001\n;") + 1,
        {"Expected ')' after 3 values, found ';'"});
}


TEST_F(fieldErrors, missingSemicolon)
{
    const std::string text = replace(good("rho"), ")\n;", ")\n");
    expectError(broken("rho", text), file_, lastLine(text),
        {"Expected ';' after the list, found end of file"});
}


TEST_F(fieldErrors, trailingContent)
{
    const std::string text = good("rho") + "extra 1;\n";
    expectError(broken("rho", text), file_, lineOf(text, "extra"),
        {"Unexpected 'extra' after the value entry"});
}


// * * * * * * * * * * * * * * * * * Values  * * * * * * * * * * * * * * * //

TEST_F(fieldErrors, badNumber)
{
    std::string text = replace(good("rho"), "\n1000.5\n", "\n1000.5x\n");
    expectError(broken("rho", text), file_, lineOf(text, "1000.5x"),
        {"'1000.5x' is not a number (scalar 2 of 3)"});

    text = replace(good("rho"), "\n1000.5\n", "\nrho\n");
    expectError(broken("rho", text), file_, lineOf(text, "\nrho\n") + 1,
        {"'rho' is not a number (scalar 2 of 3)"});

    text = replace(good("rho"), "\n1000.5\n", "\n1e999\n");
    expectError(broken("rho", text), file_, lineOf(text, "1e999"),
        {"'1e999' is out of the range of a double"});
}


TEST_F(fieldErrors, nonFiniteValues)
{
    std::string text = replace(good("rho"), "\n1000.5\n", "\nnan\n");
    expectError(broken("rho", text), file_, lineOf(text, "nan"),
        {"'nan' is not a finite number (NaN or inf", "(scalar 2 of 3)"});

    text = replace(good("position"), "(0.5 0.25 1)", "(0.5 -inf 1)");
    expectError(broken("position", text), file_, lineOf(text, "-inf"),
        {"is not a finite number", "(vector 2 of 3)"});

    // Binary: a NaN written by a diverged run is refused on reading.
    particleBody body = water();
    body.scalarField("rho")[1] = NAN;
    const fs::path file = dir_.path()/"nan"/"rho";
    fs::create_directories(file.parent_path());
    writeField(file, body, "rho", writeFormat::binary, 6);
    particleBody back("water", bodyType::fluid, 3, 0.01);
    expectError(catchFatal([&]{ readField(file, back); }), file.string(), 0,
        {"Value 2 of 3 is not a finite number"});
}


TEST_F(fieldErrors, badVector)
{
    std::string text = replace(good("position"), "(0.5 0.25 1)",
                               "(0.5 0.25)");
    expectError(broken("position", text), file_, lineOf(text, "(0.5 0.25)"),
        {"is not a vector: it has fewer than 3 components (vector 2 of 3)"});

    text = replace(good("position"), "(0.5 0.25 1)", "0.5 0.25 1");
    expectError(broken("position", text), file_, lineOf(text, "0.5 0.25 1"),
        {"'0.5' is not a vector: expected '(x y z)'"});

    text = replace(good("position"), "(0.5 0.25 1)", "(0.5 0.25 1 2)");
    expectError(broken("position", text), file_, lineOf(text, "0.5 0.25 1 2"),
        {"expected ')' after 3 components"});
}


TEST_F(fieldErrors, badLabel)
{
    std::string text = replace(good("cell"), "\n-6\n", "\n3000000000\n");
    expectError(broken("cell", text), file_, lineOf(text, "3000000000"),
        {"'3000000000' overflows a 32-bit label (label 2 of 3)"});

    text = replace(good("cell"), "\n-6\n", "\n-6.5\n");
    expectError(broken("cell", text), file_, lineOf(text, "-6.5"),
        {"'-6.5' is not an integer (label 2 of 3)"});
}


TEST_F(fieldErrors, truncatedAscii)
{
    std::string text = good("rho");
    text = text.substr(0, text.find("1000.5") + 5);
    expectError(broken("rho", text), file_, lastLine(text),
        {"Unexpected end of file after 2 of 3 values: the file is "
         "truncated"});
}


TEST_F(fieldErrors, truncatedBinary)
{
    std::string text = good("position", writeFormat::binary);
    text = text.substr(0, text.find("3(") + 2 + 40);
    expectError(broken("position", text), file_, lineOf(text, "value"),
        {"Truncated binary data: 3 vector values need at least 73 more "
         "bytes, the file has 40", "a wrong count N or a truncated file"});
}


TEST_F(fieldErrors, binaryCountDoesNotMatchData)
{
    std::string text = replace(good("rho", writeFormat::binary), "3(", "2(");
    FatalError err = broken("rho", text);
    expectError(err, file_, 0,
        {"Expected ')' right after the 2 binary values (16 bytes), found",
         "a wrong count N or a damaged file", "(at byte"});

    text = replace(good("rho", writeFormat::binary), "3(", "4(");
    err = broken("rho", text);
    expectError(err, file_, 0,
        {"Expected ')' right after the 4 binary values (32 bytes)"});
}


// * * * * * * * * * * * * * * * * * * Ids * * * * * * * * * * * * * * * * //

TEST_F(fieldErrors, badIds)
{
    std::string text = replace(good("id"), "\n0\n1\n2\n", "\n0\n1\n1\n");
    expectError(broken("id", text), file_, 0,
        {"Particle id 1 appears twice (again at value 3 of 3): ids must be "
         "unique"});

    text = replace(good("id"), "\n0\n1\n2\n", "\n0\n-1\n2\n");
    expectError(broken("id", text), file_, 0,
        {"Negative particle id -1 (value 2 of 3)"});

    // Sparse ids take the sorting path.
    text = replace(good("id"), "\n0\n1\n2\n", "\n2000000\n7\n2000000\n");
    expectError(broken("id", text), file_, 0,
        {"Particle id 2000000 appears twice"});

    text = replace(good("id"), "\n0\n1\n2\n", "\n0\n2147483647\n2\n");
    expectError(broken("id", text), file_, 0,
        {"Particle id 2147483647 leaves no id for a new particle"});
}


// * * * * * * * * * * * * * * * Sizes of a body * * * * * * * * * * * * * //

TEST_F(fieldErrors, sizeDiffersFromTheBody)
{
    const std::string text = good("rho");
    expectError(broken("rho", text, 5), file_, lineOf(text, "\n3\n") + 1,
        {"Field 'rho' has 3 values but body 'water' has 5 particles: all "
         "fields of a body must have the same size"});
}


TEST_F(fieldErrors, missingFile)
{
    particleBody body("water", bodyType::fluid, 3, 0.01);
    const std::string file = (dir_.path()/"nothing").string();
    expectError(catchFatal([&]{ readField(file, body); }), file, 0,
        {"Cannot open \"" + file + "\" for reading"});
}


TEST_F(fieldErrors, inconsistentSizesInATimeDirectory)
{
    timeState state;
    writeTimeDirectory(dir_.path(), state, {water()});
    const fs::path bodyDir = dir_.path()/"0"/"water";

    // rho is read after cell, id and position.
    particleBody small = water(2);
    writeField(bodyDir/"rho", small, "rho", writeFormat::ascii, 6, "0/water");
    const std::string rho = readText(bodyDir/"rho");
    expectError(catchFatal([&]{ readTimeDirectory(dir_.path(), "0"); }),
        (bodyDir/"rho").string(), lineOf(rho, "\n2\n") + 1,
        {"Field 'rho' has 2 values but body 'water' has 3 particles"});

    // An empty position (read first) must not let the others resize the
    // body.
    particleBody none("water", bodyType::fluid, 3, 0.01);
    writeField(bodyDir/"rho", water(), "rho", writeFormat::ascii, 6);
    writeField(bodyDir/"position", none, "position", writeFormat::binary, 6);
    expectError(catchFatal([&]{ readTimeDirectory(dir_.path(), "0"); }),
        (bodyDir/"cell").string(), 0,
        {"Field 'cell' has 3 values but body 'water' has 0 particles"});
    writeField(bodyDir/"position", water(), "position", writeFormat::binary,
               6);

    // A uniform list N{v} gives no size of its own: checked against
    // position's, it cannot allocate the N it says (2e9 vectors, 48 GB).
    particleBody withU = water();
    withU.addVectorField("U");
    writeField(bodyDir/"U", withU, "U", writeFormat::ascii, 6, "0/water");
    std::string U = readText(bodyDir/"U");
    U = U.substr(0, U.find("value"))
        + "value nonuniform List<vector> 2000000000{(0 0 0)};\n";
    writeText(bodyDir/"U", U);
    expectError(catchFatal([&]{ readTimeDirectory(dir_.path(), "0"); }),
        (bodyDir/"U").string(), lineOf(U, "2000000000"),
        {"Field 'U' has 2000000000 values but body 'water' has 3 particles"});
    // Read alone into an empty body it cannot set the body's size.
    particleBody alone("water", bodyType::fluid, 3, 0.01);
    expectError(catchFatal([&]{ readField(bodyDir/"U", alone); }),
        (bodyDir/"U").string(), lineOf(U, "2000000000"),
        {"A uniform list 2000000000{...} cannot set the number of particles"});
}


TEST_F(fieldErrors, badBodyDirectory)
{
    timeState state;
    writeTimeDirectory(dir_.path(), state, {water()});
    const fs::path bodyDir = dir_.path()/"0"/"water";
    const auto readIt = [&]{ readTimeDirectory(dir_.path(), "0"); };

    fs::rename(bodyDir/"position", dir_.path()/"position");
    expectError(catchFatal(readIt), (bodyDir/"position").string(), 0,
        {"Missing field file 'position' of body 'water'"});
    fs::rename(dir_.path()/"position", bodyDir/"position");

    fs::create_directory(bodyDir/"sub");
    expectError(catchFatal(readIt), (bodyDir/"sub").string(), 0,
        {"is not a field file"});
    fs::remove(bodyDir/"sub");

    const std::string props = readText(bodyDir/"bodyProperties");
    writeText(bodyDir/"bodyProperties",
        replace(props, "nDimensions     3", "nDimensions     4"));
    expectError(catchFatal(readIt), (bodyDir/"bodyProperties").string(),
        lineOf(props, "nDimensions"), {"expected 2 or 3, found 4"});

    writeText(bodyDir/"bodyProperties",
        replace(props, "type            fluid", "type            gas"));
    expectError(catchFatal(readIt), (bodyDir/"bodyProperties").string(),
        lineOf(props, "type"), {"Keyword 'type': unknown value 'gas'"});

    writeText(bodyDir/"bodyProperties", replace(props, "dp ", "dx "));
    expectError(catchFatal(readIt), (bodyDir/"bodyProperties").string(),
        lineOf(props, "dp "), {"dx"});

    fs::remove(bodyDir/"bodyProperties");
    expectError(catchFatal(readIt), (bodyDir/"bodyProperties").string(), 0,
        {"Missing bodyProperties"});
}


TEST_F(fieldErrors, badUniformTime)
{
    timeState state;
    state.name = "0.5";
    state.value = 0.5;
    state.index = 5;
    writeTimeDirectory(dir_.path(), state, {water()});
    const fs::path file = dir_.path()/"0.5"/"uniform"/"time";
    const std::string good = readText(file);

    writeText(file, replace(good, "index           5", "index           -5"));
    expectError(catchFatal([&]{ readTimeState(dir_.path(), "0.5"); }),
        file.string(), lineOf(good, "index"),
        {"Keyword 'index': expected a time-step index >= 0, found -5"});

    writeText(file, replace(good, "deltaT          0", "deltaT          -1"));
    expectError(catchFatal([&]{ readTimeState(dir_.path(), "0.5"); }),
        file.string(), lineOf(good, "deltaT "),
        {"Keyword 'deltaT': expected a finite non-negative number"});

    writeText(file, replace(good, "value           0.5;\n", ""));
    expectError(catchFatal([&]{ readTimeState(dir_.path(), "0.5"); }),
        file.string(), -1, {"value"});
}
