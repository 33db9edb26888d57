/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Reading, lookup, macros, directives, typed values, writing and round
// trips of dictionaries (errors are in testDictionaryErrors.C, dimensions in
// testDimensions.C).

#include "dictionary.H"
#include "error.H"
#include "../testTools.H"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <sys/wait.h>

using namespace sphvcpm;
using test::catchFatal;
using test::expectError;
using test::scratchDir;

namespace
{

const std::string dataDir = std::string(SPHVCPM_TEST_DATA) + "/dictionaries";

std::string written(const dictionary& d)
{
    std::ostringstream os;
    d.write(os);
    return os.str();
}

// Raw tokens of an entry, for checks of the lexer.
const std::vector<token>& tokensOf(const dictionary& d, const std::string& k)
{
    return d.lookupEntry(k).tokens();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Lexer * * * * * * * * * * * * * * * * * //

TEST(dictionaryLexer, commentsAndLineCounting)
{
    const auto d = dictionary::fromString
    (
        "// line comment with ; and { inside\n"
        "a 1; /* block\n"
        "   comment } ; */ b 2;\n"
        "\n"
        "c /* inline */ 3; // trailing\n"
        "d 4/2;\n"
    );
    EXPECT_EQ(d.keys(), (std::vector<std::string>{"a", "b", "c", "d"}));
    EXPECT_EQ(d.lookupEntry("a").line(), 2);
    EXPECT_EQ(d.lookupEntry("b").line(), 3);
    EXPECT_EQ(d.lookupEntry("c").line(), 5);
    EXPECT_EQ(d.get<label>("c"), 3);
    // A '/' that starts no comment is the DIVIDE punctuation.
    const auto& t = tokensOf(d, "d");
    ASSERT_EQ(t.size(), 3u);
    EXPECT_TRUE(t[1].isPunctuation('/'));
    EXPECT_EQ(t[2].integerValue, 2);
}


// Old Mac files end lines with a lone '\r', Windows ones with "\r\n": a //
// comment ends there (it used to swallow the rest of an old Mac file) and
// lines are counted once per line end.
TEST(dictionaryLexer, carriageReturnLineEnds)
{
    const auto mac = dictionary::fromString
    (
        "// comment\ra 1;\r\r// another\rb \"two\\\rlines\";\rc 3;\r",
        "mac"
    );
    EXPECT_EQ(mac.keys(), (std::vector<std::string>{"a", "b", "c"}));
    EXPECT_EQ(mac.lookupEntry("a").line(), 2);
    EXPECT_EQ(mac.lookupEntry("b").line(), 5);
    EXPECT_EQ(mac.get<std::string>("b"), "two\nlines");
    EXPECT_EQ(mac.lookupEntry("c").line(), 7);

    const auto windows = dictionary::fromString
    (
        "// comment\r\na 1;\r\n\r\nb \"two\\\r\nlines\";\r\nc 3;\r\n",
        "windows"
    );
    EXPECT_EQ(windows.keys(), (std::vector<std::string>{"a", "b", "c"}));
    EXPECT_EQ(windows.lookupEntry("a").line(), 2);
    EXPECT_EQ(windows.lookupEntry("b").line(), 4);
    EXPECT_EQ(windows.get<std::string>("b"), "two\nlines");
    EXPECT_EQ(windows.lookupEntry("c").line(), 6);

    // Errors point at the right line too.
    expectError(catchFatal([]
    {
        dictionary::fromString("a 1;\r// x\rb (1 2;\r", "mac");
    }), "mac", 3, {"expected ')' to close '(' opened at line 3"});

    // A string set in code with them is written so that it reads back.
    dictionary set("set");
    set.set("s", "a\rb\r\nc");
    std::ostringstream os;
    set.write(os);
    EXPECT_EQ(dictionary::fromString(os.str()).get<std::string>("s"),
              "a\nb\nc") << os.str();
}


// A UTF-8 byte-order mark (editors on Windows add one) is not a keyword.
TEST(dictionaryLexer, byteOrderMarkSkipped)
{
    const auto d = dictionary::fromString("\xEF\xBB\xBF" "a 1;\nb 2;\n");
    EXPECT_EQ(d.keys(), (std::vector<std::string>{"a", "b"}));
    EXPECT_EQ(d.lookupEntry("b").line(), 2);
    EXPECT_NO_THROW(d.checkKeywords({"a", "b"}));

    scratchDir dir("dictBom");
    const auto file = dir.write("fvSolution", "\xEF\xBB\xBF"
        "/* banner */\nFoamFile { format ascii; object fvSolution; }\n"
        "PISO { nCorrectors 2; }\n");
    const auto f = dictionary::fromFile(file);
    ASSERT_NE(f.header(), nullptr);
    EXPECT_EQ(f.keys(), (std::vector<std::string>{"PISO"}));
    EXPECT_EQ(f.subDict("PISO").get<label>("nCorrectors"), 2);
}


TEST(dictionaryLexer, wordsKeepBalancedParentheses)
{
    const auto d = dictionary::fromString
    (
        "div(phi,U)      Gauss linearUpwind grad(U);\n"
        "laplacian((1|A(U)),p) Gauss linear corrected;\n"
        "list (a b);\n"
    );
    EXPECT_TRUE(d.found("div(phi,U)"));
    EXPECT_TRUE(d.found("laplacian((1|A(U)),p)"));
    const auto& t = tokensOf(d, "div(phi,U)");
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t[2].type, token::kind::word);
    EXPECT_EQ(t[2].text, "grad(U)");
    // An unmatched ')' ends a word: b) is the word b and the ')'.
    EXPECT_EQ(d.get<std::vector<std::string>>("list"),
              (std::vector<std::string>{"a", "b"}));
}


TEST(dictionaryLexer, numbersAndPunctuation)
{
    const auto d = dictionary::fromString
    (
        "i 42; n -7; f 1.5e-3; g .25; h -0.5; big 9007199254740993;\n"
        "minus - 3; p a=b,c:d;\n"
    );
    EXPECT_EQ(tokensOf(d, "i")[0].type, token::kind::integer);
    EXPECT_EQ(d.get<label>("i"), 42);
    EXPECT_EQ(d.get<label>("n"), -7);
    EXPECT_EQ(tokensOf(d, "f")[0].type, token::kind::floating);
    EXPECT_DOUBLE_EQ(d.get<double>("f"), 1.5e-3);
    EXPECT_DOUBLE_EQ(d.get<double>("g"), 0.25);
    EXPECT_DOUBLE_EQ(d.get<double>("h"), -0.5);
    EXPECT_DOUBLE_EQ(d.get<double>("i"), 42.0);   // integers are numbers
    EXPECT_EQ(d.get<std::int64_t>("big"), 9007199254740993LL);
    // A lone '-' is punctuation.
    const auto& m = tokensOf(d, "minus");
    ASSERT_EQ(m.size(), 2u);
    EXPECT_TRUE(m[0].isPunctuation('-'));
    EXPECT_EQ(m[1].integerValue, 3);
    // = , : are not word terminators.
    EXPECT_EQ(d.get<std::string>("p"), "a=b,c:d");
}


TEST(dictionaryLexer, stringsAndEscapes)
{
    const auto d = dictionary::fromString
    (
        "a \"hello world\";\n"
        "b \"say \\\"hi\\\"\";\n"
        "c \"two\\\n"
        "lines\";\n"
        "d \"a\\.b\";\n"
        "e \"/* not a comment */ // nor this\";\n"
        "f 1;\n"
    );
    EXPECT_EQ(d.get<std::string>("a"), "hello world");
    EXPECT_EQ(d.get<std::string>("b"), "say \"hi\"");
    EXPECT_EQ(d.get<std::string>("c"), "two\nlines");
    EXPECT_EQ(d.get<std::string>("d"), "a\\.b");   // kept, as OpenFOAM does
    EXPECT_EQ(d.get<std::string>("e"), "/* not a comment */ // nor this");
    EXPECT_EQ(d.lookupEntry("f").line(), 7);        // continuation counted
}


TEST(dictionaryLexer, verbatimVariablesDirectives)
{
    const auto d = dictionary::fromString
    (
        "code #{ int x = 1; // } ; #};\n"
        "x 1;\n"
        "y ${x};\n"
    );
    const auto& c = tokensOf(d, "code");
    ASSERT_EQ(c.size(), 1u);
    EXPECT_EQ(c[0].type, token::kind::verbatim);
    EXPECT_EQ(c[0].text, " int x = 1; // } ; ");
    EXPECT_EQ(d.get<label>("y"), 1);
}


// * * * * * * * * * * * * * * * * Entries * * * * * * * * * * * * * * * * //

TEST(dictionaryEntries, subDictionariesOrderAndStraySemicolons)
{
    const auto d = dictionary::fromString
    (
        ";; zeta 1;;\n"
        "alpha\n"
        "{\n"
        "    inner { deep 3; }\n"
        "    x 2;\n"
        "};\n"
        "empty;\n"
        "beta 2;\n"
    );
    EXPECT_EQ(d.keys(),
              (std::vector<std::string>{"zeta", "alpha", "empty", "beta"}));
    EXPECT_EQ(d.subDictKeys(), (std::vector<std::string>{"alpha"}));
    EXPECT_EQ(d.size(), 4u);
    EXPECT_TRUE(d.isDict("alpha"));
    EXPECT_FALSE(d.isDict("beta"));
    EXPECT_EQ(d.subDict("alpha").subDict("inner").get<label>("deep"), 3);
    EXPECT_EQ(d.subDict("alpha").line(), 3);
    EXPECT_EQ(d.subDict("alpha").name(), "<string>/alpha");
    EXPECT_EQ(d.subDict("alpha").subDict("inner").name(),
              "<string>/alpha/inner");
    EXPECT_EQ(&d.subDict("alpha").subDict("inner").topDict(), &d);
    EXPECT_EQ(d.subDict("alpha").parent(), &d);
    EXPECT_TRUE(tokensOf(d, "empty").empty());
    EXPECT_EQ(d.findDict("beta"), nullptr);
    EXPECT_NE(d.findDict("alpha"), nullptr);
}


TEST(dictionaryEntries, duplicateKeysMerge)
{
    const auto d = dictionary::fromString
    (
        "a 1;\n"
        "s { x 1; y 2; t { u 1; } }\n"
        "b 2;\n"
        "a 3;\n"
        "s { y 20; z 30; t { v 2; } }\n"
    );
    // Later replaces in place; sub-dictionaries merge recursively.
    EXPECT_EQ(d.keys(), (std::vector<std::string>{"a", "s", "b"}));
    EXPECT_EQ(d.get<label>("a"), 3);
    EXPECT_EQ(d.lookupEntry("a").line(), 4);
    const auto& s = d.subDict("s");
    EXPECT_EQ(s.keys(), (std::vector<std::string>{"x", "y", "t", "z"}));
    EXPECT_EQ(s.get<label>("x"), 1);
    EXPECT_EQ(s.get<label>("y"), 20);
    EXPECT_EQ(s.get<label>("z"), 30);
    EXPECT_EQ(s.subDict("t").keys(), (std::vector<std::string>{"u", "v"}));
    EXPECT_EQ(s.subDict("t").parent(), &s);
}


TEST(dictionaryEntries, regexKeysSearchedLastFirst)
{
    const auto d = dictionary::fromString
    (
        "\".*\"          { type zeroGradient; }\n"
        "\"wall.*\"      { type noSlip; }\n"
        "inlet         { type fixedValue; }\n"
        "\"wallB\"       { type slip; }\n"
    );
    EXPECT_EQ(d.subDict("inlet").get<std::string>("type"), "fixedValue");
    EXPECT_EQ(d.subDict("wallA").get<std::string>("type"), "noSlip");
    EXPECT_EQ(d.subDict("wallB").get<std::string>("type"), "slip");
    EXPECT_EQ(d.subDict("outlet").get<std::string>("type"), "zeroGradient");
    EXPECT_TRUE(d.lookupEntry("wall.*").isPattern());
    EXPECT_FALSE(d.lookupEntry("inlet").isPattern());
    // An exact key wins over a pattern that also matches.
    const auto e = dictionary::fromString("\"a.*\" 1; abc 2; \"ab.*\" 3;");
    EXPECT_EQ(e.get<label>("abc"), 2);
    EXPECT_EQ(e.get<label>("abd"), 3);
    EXPECT_EQ(e.get<label>("axe"), 1);
    EXPECT_FALSE(e.found("b"));
}


TEST(dictionaryEntries, foamFileHeaderKeptApart)
{
    const auto d =
        dictionary::fromFile(dataDir + "/system/fvSolution");
    ASSERT_NE(d.header(), nullptr);
    EXPECT_EQ(d.header()->get<std::string>("object"), "fvSolution");
    EXPECT_EQ(d.header()->get<std::string>("location"), "system");
    EXPECT_EQ(d.header()->get<double>("version"), 2.0);
    EXPECT_FALSE(d.found("FoamFile"));
    EXPECT_EQ(d.keys(), (std::vector<std::string>
        {"solvers", "PISO", "relaxationFactors"}));
    EXPECT_EQ(d.file(), dataDir + "/system/fvSolution");

    const auto none = dictionary::fromString("a 1;");
    EXPECT_EQ(none.header(), nullptr);
}


TEST(dictionaryEntries, openFoamFvSolution)
{
    const auto d =
        dictionary::fromFile(dataDir + "/system/fvSolution");
    const auto& solvers = d.subDict("solvers");
    const auto& pFinal = solvers.subDict("pFinal");
    EXPECT_EQ(pFinal.keys(), (std::vector<std::string>
        {"solver", "preconditioner", "tolerance", "relTol"}));
    EXPECT_EQ(pFinal.get<std::string>("solver"), "PCG");
    EXPECT_EQ(pFinal.get<double>("relTol"), 0.0);
    EXPECT_EQ(pFinal.get<double>("tolerance"), 1e-06);
    // $U found through the pattern "(U|k|epsilon)".
    const auto& kFinal = solvers.subDict("kFinal");
    EXPECT_EQ(kFinal.get<std::string>("smoother"), "symGaussSeidel");
    EXPECT_EQ(kFinal.get<double>("relTol"), 0.0);
    EXPECT_EQ(solvers.subDict("epsilon").get<double>("relTol"), 0.1);
    EXPECT_EQ(d.subDict("PISO").get<double>("pTolerance"), 1e-06);
    EXPECT_EQ(d.subDict("relaxationFactors").subDict("equations")
        .get<double>("U"), 1.0);
}


// * * * * * * * * * * * * * * * * Macros * * * * * * * * * * * * * * * * //

TEST(dictionaryMacros, valueSubstitutionAndScoping)
{
    const auto d = dictionary::fromString
    (
        "U0 1.5;\n"
        "vec (1 2 3);\n"
        "inlet { value uniform $vec; speed $U0; }\n"
        "a { b { c 7; } x 1; }\n"
        "alpha.water 0.3;\n"
        "scoped\n"
        "{\n"
        "    c1 $a/b/c;\n"
        "    c2 $../a/b/c;\n"
        "    c3 $!a/x;\n"
        "    c4 $:alpha.water;\n"
        "    c5 ${a/b/c};\n"
        "    c6 $alpha.water;\n"
        "    c7 $U0;\n"                    // found in a parent
        "    U0 2.5;\n"
        "    c8 $U0;\n"                    // now found here first
        "    c9 $..U0;\n"                  // ESI: the parent's
        "    c10 $a.b.c;\n"                // ESI dot scoping
        "    deep { d1 $../../U0; d2 $../U0; }\n"
        "}\n"
    );
    const auto& inlet = d.subDict("inlet");
    const auto& t = tokensOf(inlet, "value");
    ASSERT_EQ(t.size(), 6u);
    EXPECT_EQ(t[0].text, "uniform");
    EXPECT_EQ(t[3].integerValue, 2);
    EXPECT_EQ(t[3].line, 3);                 // expansion carries the $ line
    EXPECT_EQ(inlet.get<double>("speed"), 1.5);

    const auto& s = d.subDict("scoped");
    EXPECT_EQ(s.get<label>("c1"), 7);
    EXPECT_EQ(s.get<label>("c2"), 7);
    EXPECT_EQ(s.get<label>("c3"), 1);
    EXPECT_EQ(s.get<double>("c4"), 0.3);
    EXPECT_EQ(s.get<label>("c5"), 7);
    EXPECT_EQ(s.get<double>("c6"), 0.3);
    EXPECT_EQ(s.get<double>("c7"), 1.5);
    EXPECT_EQ(s.get<double>("c8"), 2.5);
    EXPECT_EQ(s.get<double>("c9"), 1.5);
    EXPECT_EQ(s.get<label>("c10"), 7);
    EXPECT_EQ(s.subDict("deep").get<double>("d1"), 1.5);
    EXPECT_EQ(s.subDict("deep").get<double>("d2"), 2.5);
}


TEST(dictionaryMacros, spliceCopyAndKeyFromVariable)
{
    const auto d = dictionary::fromString
    (
        "base { a 1; b 2; sub { c 3; } }\n"
        "derived { $base; b 20; }\n"
        "copy $base;\n"
        "name patchA;\n"
        "$name { type wall; }\n"
        "inline { x (fixed { $base; extra 1; }); }\n"
    );
    const auto& der = d.subDict("derived");
    EXPECT_EQ(der.keys(), (std::vector<std::string>{"a", "b", "sub"}));
    EXPECT_EQ(der.get<label>("b"), 20);
    EXPECT_EQ(der.subDict("sub").get<label>("c"), 3);
    EXPECT_EQ(der.subDict("sub").name(), "<string>/derived/sub");
    EXPECT_EQ(der.subDict("sub").parent(), &der);

    ASSERT_TRUE(d.isDict("copy"));
    EXPECT_EQ(d.subDict("copy"), d.subDict("base"));
    EXPECT_EQ(d.subDict("copy").name(), "<string>/copy");

    EXPECT_EQ(d.subDict("patchA").get<std::string>("type"), "wall");

    // A sub-dictionary inside a value expands to its entries, as in
    // OpenFOAM (sets ( line { $setConfig; start ...; } )).
    const auto& x = tokensOf(d.subDict("inline"), "x");
    std::vector<std::string> text;
    for (const auto& t : x)
    {
        text.push_back(t.str());
    }
    EXPECT_EQ(text, (std::vector<std::string>{"(", "fixed", "{", "a", "1",
        ";", "b", "2", ";", "sub", "{", "c", "3", ";", "}", ";", "extra", "1",
        ";", "}", ")"}));
}


TEST(dictionaryMacros, patternsMatchOnlyInKeywordPosition)
{
    // OpenFOAM's setConstraintTypes: $internalField in a value must not be
    // captured by the ".*" pattern of boundaryField.
    const auto d = dictionary::fromString
    (
        "internalField uniform 0;\n"
        "boundaryField\n"
        "{\n"
        "    \".*\" { type zeroGradient; }\n"
        "    processor { type processor; value $internalField; }\n"
        "    \"(U|k)\" { solver PCG; }\n"
        "    kFinal { $k; relTol 0; }\n"            // keyword position
        "}\n"
    );
    const auto& b = d.subDict("boundaryField");
    EXPECT_EQ(tokensOf(b.subDict("processor"), "value")[0].text, "uniform");
    EXPECT_EQ(b.subDict("kFinal").get<std::string>("solver"), "PCG");
    EXPECT_EQ(b.subDict("kFinal").get<label>("relTol"), 0);
}


TEST(dictionaryMacros, environmentFallback)
{
    ::setenv("SPHVCPM_TEST_NU", "1e-05", 1);
    ::setenv("SPHVCPM_TEST_PATH", "/some/where/file.stl", 1);
    ::setenv("SPHVCPM_TEST_DIR", "sub", 1);
    const auto d = dictionary::fromString
    (
        "nu $SPHVCPM_TEST_NU;\n"
        "file $SPHVCPM_TEST_PATH;\n"
        "braced ${SPHVCPM_TEST_NU};\n"
        "SPHVCPM_TEST_DIR local;\n"
        "which $SPHVCPM_TEST_DIR;\n"     // the dictionary comes first
    );
    EXPECT_EQ(d.get<double>("nu"), 1e-05);
    EXPECT_EQ(d.get<double>("braced"), 1e-05);
    EXPECT_EQ(d.get<std::string>("file"), "/some/where/file.stl");
    EXPECT_EQ(tokensOf(d, "file")[0].type, token::kind::string);
    EXPECT_EQ(d.get<std::string>("which"), "local");
    ::unsetenv("SPHVCPM_TEST_NU");
    ::unsetenv("SPHVCPM_TEST_PATH");
    ::unsetenv("SPHVCPM_TEST_DIR");
}


TEST(dictionaryMacros, nestedBracedNames)
{
    const auto d = dictionary::fromString
    (
        "model fast;\n"
        "fastCoeffs { k 4; }\n"
        "slowCoeffs { k 1; }\n"
        "k ${${model}Coeffs/k};\n"
    );
    EXPECT_EQ(d.get<label>("k"), 4);
}


// * * * * * * * * * * * * * * * Directives * * * * * * * * * * * * * * * //

TEST(dictionaryDirectives, includeRelativeRemoveAndHeaderDropped)
{
    const auto d =
        dictionary::fromFile(dataDir + "/constant/transportProperties");
    EXPECT_EQ(d.keys(), (std::vector<std::string>{"transportModel", "nu",
                                                  "rho"}));
    EXPECT_EQ(d.get<double>("nu"), 1e-06);
    EXPECT_EQ(d.get<double>("rho"), 1000.0);
    EXPECT_EQ(d.header()->get<std::string>("object"),
              "transportProperties");
}


TEST(dictionaryDirectives, includeIntoSubDictAndVariableFileNames)
{
    scratchDir dir("dictInclude");
    dir.write("common/solver", "solver PCG;\ntolerance 1e-6;\n");
    dir.write("common/extra", "relTol 0.1;\n");
    ::setenv("SPHVCPM_TEST_COMMON", "common", 1);
    const auto file = dir.write
    (
        "system/fvSolution",
        "extraName extra;\n"
        "p\n"
        "{\n"
        "    #include \"../common/solver\"\n"
        "    #include \"../$SPHVCPM_TEST_COMMON/${extraName}\"\n"
        "    #sinclude \"../common/missing\"\n"
        "    after 1;\n"
        "}\n"
    );
    const auto d = dictionary::fromFile(file);
    ::unsetenv("SPHVCPM_TEST_COMMON");
    const auto& p = d.subDict("p");
    EXPECT_EQ(p.keys(), (std::vector<std::string>{"solver", "tolerance",
                                                  "relTol", "after"}));
    EXPECT_EQ(p.get<std::string>("solver"), "PCG");
    EXPECT_EQ(p.get<double>("relTol"), 0.1);
    // An entry remembers the file it came from.
    EXPECT_EQ(p.lookupEntry("solver").file(),
              (dir.path()/"system"/"../common/solver").string());
    EXPECT_EQ(p.lookupEntry("solver").line(), 1);
    EXPECT_EQ(p.lookupEntry("after").line(), 7);
}


TEST(dictionaryDirectives, includeCaseTags)
{
    scratchDir dir("dictCaseTags");
    dir.write("case/system/common", "solver PCG;\n");
    dir.write("case/constant/g", "g (0 -9.81 0);\n");
    const auto file = dir.write
    (
        "case/system/fvSolution",
        "#include \"<system>/common\"\n#include \"<constant>/g\"\n"
    );
    const char* foamCase = std::getenv("FOAM_CASE");
    const std::string saved = foamCase ? foamCase : "";
    ::unsetenv("FOAM_CASE");
    const auto d = dictionary::fromFile(file);
    if (foamCase)
    {
        ::setenv("FOAM_CASE", saved.c_str(), 1);
    }
    EXPECT_EQ(d.get<std::string>("solver"), "PCG");
    EXPECT_EQ(d.get<vec3>("g"), (vec3{0, -9.81, 0}));
}


TEST(dictionaryDirectives, includeEtc)
{
    scratchDir dir("dictEtc");
    dir.write("etc/caseDicts/defaults", "writeFormat binary;\n");
    const char* old = std::getenv("SPHVCPM_DIR");
    const std::string saved = old ? old : "";
    ::setenv("SPHVCPM_DIR", dir.path().c_str(), 1);
    const auto d = dictionary::fromString
    (
        "#includeEtc \"caseDicts/defaults\"\nwriteInterval 1;\n"
    );
    if (old)
    {
        ::setenv("SPHVCPM_DIR", saved.c_str(), 1);
    }
    else
    {
        ::unsetenv("SPHVCPM_DIR");
    }
    EXPECT_EQ(d.get<std::string>("writeFormat"), "binary");
    EXPECT_EQ(d.get<label>("writeInterval"), 1);
}


TEST(dictionaryDirectives, removeForms)
{
    const auto d = dictionary::fromString
    (
        "a 1; b 2; c 3; wall1 4; wall2 5; keep 6; d { x 1; }\n"
        "#remove a\n"
        "#remove (b c)\n"
        "#remove \"wall.*\"\n"
        "#remove d\n"
        "#remove notThere\n"
    );
    EXPECT_EQ(d.keys(), (std::vector<std::string>{"keep"}));
}


TEST(dictionaryDirectives, inputModes)
{
    const auto merge = dictionary::fromString
    (
        "s { a 1; b 2; }\n#inputMode merge\ns { b 3; }\n"
    );
    EXPECT_EQ(merge.subDict("s").keys(),
              (std::vector<std::string>{"a", "b"}));
    EXPECT_EQ(merge.subDict("s").get<label>("b"), 3);

    const auto over = dictionary::fromString
    (
        "s { a 1; b 2; }\nx 1;\n#inputMode overwrite\ns { b 3; }\nx 2;\n"
    );
    EXPECT_EQ(over.subDict("s").keys(), (std::vector<std::string>{"b"}));
    EXPECT_EQ(over.get<label>("x"), 2);
    EXPECT_EQ(over.keys(), (std::vector<std::string>{"s", "x"}));

    const auto prot = dictionary::fromString
    (
        "x 1;\n#inputMode protect\nx 2;\ny 3;\n#inputMode default\ny 4;\n"
    );
    EXPECT_EQ(prot.get<label>("x"), 1);
    EXPECT_EQ(prot.get<label>("y"), 4);

    const auto warn = dictionary::fromString("x 1;\n#inputMode warn\nx 2;\n");
    EXPECT_EQ(warn.get<label>("x"), 1);

    const auto err = catchFatal([]
    {
        dictionary::fromString
        (
            "x 1;\n#inputMode error\ny 2;\nx 3;\n", "case/system/modes"
        );
    });
    expectError(err, "case/system/modes", 4,
        {"Duplicate keyword 'x'", "first defined at line 1",
         "#inputMode is error"});
}


// * * * * * * * * * * * * * * * Typed values * * * * * * * * * * * * * * //

TEST(dictionaryValues, switchesAndWords)
{
    const auto d = dictionary::fromString
    (
        "a true; b off; c yes; d n; e t; f none; g any; h on; i false;\n"
        "w word; s \"a string\"; type cuda;\n"
    );
    EXPECT_TRUE(d.get<bool>("a"));
    EXPECT_FALSE(d.get<bool>("b"));
    EXPECT_TRUE(d.get<bool>("c"));
    EXPECT_FALSE(d.get<bool>("d"));
    EXPECT_TRUE(d.get<bool>("e"));
    EXPECT_FALSE(d.get<bool>("f"));
    EXPECT_TRUE(d.get<bool>("g"));
    EXPECT_TRUE(d.get<bool>("h"));
    EXPECT_FALSE(d.get<bool>("i"));
    // 1 and 0, as OpenFOAM reads them (openTop 1;); other numbers are
    // errors (testDictionaryErrors.C).
    const auto n = dictionary::fromString("openTop 1; closed 0;\n");
    EXPECT_TRUE(n.get<bool>("openTop"));
    EXPECT_FALSE(n.get<bool>("closed"));
    EXPECT_TRUE(n.getOrDefault<bool>("openTop", false));
    EXPECT_EQ(d.get<std::string>("w"), "word");
    EXPECT_EQ(d.get<std::string>("s"), "a string");
    EXPECT_EQ(d.getWord("type", {"cpu", "cuda"}), "cuda");
    EXPECT_EQ(d.getWordOrDefault("device", {"cpu", "cuda"}, "cpu"), "cpu");
    EXPECT_EQ(d.getOrDefault<label>("missing", 5), 5);
    EXPECT_EQ(d.getOrDefault<std::string>("w", "x"), "word");
}


TEST(dictionaryValues, vectorsAndLists)
{
    const auto d = dictionary::fromString
    (
        "g (0 -9.81 0);\n"
        "v2 (1 2);\n"
        "gd g [0 1 -2 0 0 0 0] (0 0 -9.81);\n"
        "gu (1 2 3) [m/s^2];\n"
        "s (1 2.5 -3);\n"
        "sn 3(1 2 3);\n"
        "su 4{0.5};\n"
        "empty ();\n"
        "empty0 0();\n"
        "l (1 2 3);\n"
        "lu 2{7};\n"
        "w (a \"b c\" d);\n"
        "pts\n"
        "(\n"
        "    (0 0 0)\n"
        "    (1 0 0)\n"
        ");\n"
        "ptsN 2((0 0 1) (1 1 1));\n"
        "ptsU 3{(1 2 3)};\n"
    );
    EXPECT_EQ(d.get<vec3>("g"), (vec3{0, -9.81, 0}));
    EXPECT_EQ(d.get<vec3>("v2"), (vec3{1, 2, 0}));
    EXPECT_EQ(d.get<vec3>("gd"), (vec3{0, 0, -9.81}));
    EXPECT_EQ(d.get<vec3>("gu"), (vec3{1, 2, 3}));
    EXPECT_EQ(d.get<std::vector<double>>("s"),
              (std::vector<double>{1, 2.5, -3}));
    EXPECT_EQ(d.get<std::vector<double>>("sn"),
              (std::vector<double>{1, 2, 3}));
    EXPECT_EQ(d.get<std::vector<double>>("su"),
              (std::vector<double>{0.5, 0.5, 0.5, 0.5}));
    EXPECT_TRUE(d.get<std::vector<double>>("empty").empty());
    EXPECT_TRUE(d.get<std::vector<label>>("empty0").empty());
    EXPECT_EQ(d.get<std::vector<label>>("l"), (std::vector<label>{1, 2, 3}));
    EXPECT_EQ(d.get<std::vector<label>>("lu"), (std::vector<label>{7, 7}));
    EXPECT_EQ(d.get<std::vector<std::string>>("w"),
              (std::vector<std::string>{"a", "b c", "d"}));
    EXPECT_EQ(d.get<std::vector<vec3>>("pts"),
              (std::vector<vec3>{{0, 0, 0}, {1, 0, 0}}));
    EXPECT_EQ(d.get<std::vector<vec3>>("ptsN"),
              (std::vector<vec3>{{0, 0, 1}, {1, 1, 1}}));
    EXPECT_EQ(d.get<std::vector<vec3>>("ptsU"),
              (std::vector<vec3>(3, vec3{1, 2, 3})));
}


TEST(dictionaryValues, integersAndPositive)
{
    const auto d = dictionary::fromString
    (
        "maxLabel 2147483647; minLabel -2147483648; big 4000000000;\n"
        "dt 1e-4; zero 0;\n"
    );
    EXPECT_EQ(d.get<label>("maxLabel"), 2147483647);
    EXPECT_EQ(d.get<label>("minLabel"), -2147483647 - 1);
    EXPECT_EQ(d.get<std::int64_t>("big"), 4000000000LL);
    EXPECT_EQ(d.getPositive("dt"), 1e-4);
    const auto err = catchFatal([&]{ d.getPositive("zero"); });
    expectError(err, "<string>", 2, {"Keyword 'zero'", "positive", "found 0"});
}


TEST(dictionaryValues, parseTokensForFieldReaders)
{
    const auto tokens = dictionary::fromString("x 3(1 2 3);")
        .lookupEntry("x").tokens();
    EXPECT_EQ(parseTokens<std::vector<label>>(tokens, "x", "f", 1),
              (std::vector<label>{1, 2, 3}));
    const auto err = catchFatal([&]
    {
        parseTokens<vec3>(tokens, "x", "field/U", 12);
    });
    expectError(err, "field/U", 1, {"Keyword 'x'", "expected '('",
                                    "found integer 3"});
}


// * * * * * * * * * * * * * * * Missing keys * * * * * * * * * * * * * * //

TEST(dictionaryLookup, missingKeywordSuggestsClosest)
{
    const std::string file = "/case/system/controlDict";
    const auto d = dictionary::fromString
    (
        "application sphVcpmFsi;\nstartTime 0;\nendTme 1;\ndeltaT 1e-5;\n"
        "sub\n{\n    writeInterval 0.1;\n}\n",
        file
    );
    const auto err = catchFatal([&]{ d.get<double>("endTime"); });
    expectError(err, file, 0,
        {"Keyword 'endTime' is undefined in dictionary \"" + file + "\"",
         "Did you mean 'endTme'?",
         "Keywords present: (application startTime endTme deltaT sub)"});
    EXPECT_EQ(err.keyword(), "endTime");

    // In a sub-dictionary: its scoped name and the line of its brace.
    const auto sub = catchFatal([&]
    {
        d.subDict("sub").get<double>("writeIntervall");
    });
    expectError(sub, file, 6,
        {"Keyword 'writeIntervall' is undefined in dictionary \""
         + file + "/sub\"", "Did you mean 'writeInterval'?"});

    // Nothing close: no suggestion, still the list.
    const auto far = catchFatal([&]{ d.subDict("solvers"); });
    EXPECT_EQ(far.message().find("Did you mean"), std::string::npos);
    EXPECT_NE(far.message().find("Keywords present: ("), std::string::npos);

    // A value asked for as a sub-dictionary, and the other way round.
    expectError(catchFatal([&]{ d.subDict("deltaT"); }), file, 4,
        {"Keyword 'deltaT' is not a sub-dictionary", "found the value '1e-5'"});
    expectError(catchFatal([&]{ d.get<double>("sub"); }), file, 5,
        {"Keyword 'sub'", "found a sub-dictionary"});
}


TEST(dictionaryLookup, checkKeywordsNamesLineAndSuggestion)
{
    const std::string file = "case/system/controlDict";
    const auto d = dictionary::fromString
    (
        "startTime 0;\nendTime 1;\n\nwriteIntervall 0.1;\n", file
    );
    const std::vector<std::string> valid =
        {"startTime", "endTime", "deltaT", "writeInterval"};
    const auto err = catchFatal([&]{ d.checkKeywords(valid); });
    expectError(err, file, 4,
        {"Unknown keyword 'writeIntervall'", "Did you mean 'writeInterval'?",
         "Valid keywords are: (startTime endTime deltaT writeInterval)"});
    EXPECT_NO_THROW(d.checkKeywords({"startTime", "endTime",
                                     "writeIntervall"}));
}


TEST(dictionaryLookup, checkKeywordsSuggestsWhatOtherCodesCallIt)
{
    // Young's modulus, Poisson's ratio and density as other codes and
    // papers name them: the keyword meant, though no misspelling.
    const std::string file = "case/constant/solidProperties";
    const std::vector<std::string> solid = {"rho", "E", "nu", "plane"};
    for (const auto& [given, meant] :
         std::vector<std::pair<std::string, std::string>>{
             {"Emod", "E"}, {"youngs_modulus", "E"}, {"YoungModulus", "E"},
             {"PoissonRatio", "nu"}, {"poisson", "nu"}, {"density", "rho"}})
    {
        const auto d = dictionary::fromString("rho 1100;\n" + given
                                              + " 2e6;\n", file);
        const auto err = catchFatal([&]{ d.checkKeywords(solid); });
        expectError(err, file, 2, {"Unknown keyword '" + given + "'",
                                   "Did you mean '" + meant + "'?"});
    }
    // And where the keyword is asked for and missing: Emod given for E.
    const auto asked = dictionary::fromString("rho 1100;\nEmod 2e6;\n", file);
    test::expectMessage(catchFatal([&]{ asked.get<double>("E"); }),
                  {"Keyword 'E' is undefined", "'Emod' is not read here:"
                   " write it as 'E'."});
    // Only a keyword that is valid there: density in fluidProperties.
    const auto fluid = dictionary::fromString("density 1000;\n", file);
    expectError(catchFatal([&]{ fluid.checkKeywords({"rho0", "nu"}); }),
                file, 1, {"Did you mean 'rho0'?"});
    const auto none = catchFatal([&]{ fluid.checkKeywords({"nu", "c0"}); });
    EXPECT_EQ(none.message().find("Did you mean"), std::string::npos)
        << none.message();
}


TEST(dictionaryLookup, checkKeywordsAcceptsVariables)
{
    // Variables as OpenFOAM users write them, some from an included file:
    // every entry a $name expanded passes, in copies too.
    scratchDir dir("dictVariables");
    dir.write("system/caseParams", "L 0.2;\nunusedHere 1;\n");
    const auto file = dir.write
    (
        "system/generateParticlesDict",
        "#include \"caseParams\"\n"
        "H 0.2;\n"
        "dpVal 5e-3;\n"
        "dp $dpVal;\n"
        "max ($L $H 0);\n"
        "H 0.25;\n"                  // redefined after its use
        "defaults { type fluid; }\n"
        "bodies\n"
        "{\n"
        "    water { $defaults; r 0.1; radius $r; }\n"
        "}\n"
    );
    const dictionary d = dictionary::fromFile(file);
    const std::vector<std::string> top = {"dp", "max", "bodies",
                                          "unusedHere"};
    EXPECT_NO_THROW(d.checkKeywords(top));
    const dictionary& water = d.subDict("bodies").subDict("water");
    EXPECT_NO_THROW(water.checkKeywords({"type", "radius"}));
    EXPECT_EQ(d.get<vec3>("max"), (vec3{0.2, 0.2, 0}));

    const dictionary copy(d);
    dictionary assigned;
    assigned = d;
    EXPECT_NO_THROW(copy.checkKeywords(top));
    EXPECT_NO_THROW(assigned.checkKeywords(top));
    EXPECT_NO_THROW(copy.subDict("bodies").subDict("water")
        .checkKeywords({"type", "radius"}));

    // Parameters kept in a sub-dictionary, read as $sub/x, ${sub/x} or
    // $/sub/x: the sub-dictionary passes too.
    for (const char* ref : {"$params/rho", "${params/rho}", "$/params/rho",
                            "$params/inner/nu"})
    {
        const auto scoped = dictionary::fromString(
            "params { rho 1000; inner { nu 1e-6; } }\nrho0 "
            + std::string(ref) + ";\n", "fluidProperties");
        EXPECT_NO_THROW(scoped.checkKeywords({"rho0"})) << ref;
    }

    // A keyword no $name expands is checked as before: the misspelling.
    // A variable of the included file that this file does not use passes
    // (several dictionaries share the file), unless it reads as a
    // misspelling of one of this dictionary's keywords.
    const std::string name = file.string();
    const auto bad = dictionary::fromString
    (
        "#include \"caseParams\"\nH 0.2;\ndp $H;\nmaxx ($L $H 0);\n", name
    );
    expectError(catchFatal([&]{ bad.checkKeywords({"dp", "max",
                                                   "unusedHere"}); }),
        name, 4, {"Unknown keyword 'maxx' in dictionary \"" + name + "\".",
                  "Did you mean 'max'?",
                  "Valid keywords are: (dp max unusedHere)"});
    EXPECT_NO_THROW(bad.checkKeywords({"dp", "maxx"}));
    const auto err = catchFatal([&]{ bad.checkKeywords({"dp", "maxx",
                                                        "unusedHer"}); });
    expectError(err, (dir.path()/"system"/"caseParams").string(), 2,
        {"Unknown keyword 'unusedHere'", "Did you mean 'unusedHer'?"});
}


TEST(dictionaryLookup, fatalAndFatalAt)
{
    const auto d = dictionary::fromString("a 1;\nb\n{\n    c 2;\n}\n", "f");
    expectError(catchFatal([&]{ d.fatalAt("a", "bad a"); }), "f", 1,
                {"bad a"});
    expectError(catchFatal([&]{ d.subDict("b").fatalAt("c", "bad c"); }),
                "f", 4, {"bad c"});
    expectError(catchFatal([&]{ d.subDict("b").fatal("bad b"); }), "f", 3,
                {"bad b"});
}


// * * * * * * * * * * * * * * * * Writing * * * * * * * * * * * * * * * * //

TEST(dictionaryWrite, openFoamLayout)
{
    dictionary d("test");
    d.set("application", "sphVcpmFsi");
    d.set("deltaT", 1e-05);
    d.set("n", label(3));
    d.set("flag", true);
    d.set("g", vec3{0, -9.81, 0});
    d.set("title", std::string("a \"quoted\" title"));
    d.setTokens("empty", {});
    dictionary& sub = d.setSubDict("solver");
    sub.set("tolerance", 1e-6);
    sub.setSubDict("inner").set("list", std::vector<label>{1, 2, 3});

    const std::string expected =
        "application     sphVcpmFsi;\n"
        "\n"
        "deltaT          1e-05;\n"
        "\n"
        "n               3;\n"
        "\n"
        "flag            true;\n"
        "\n"
        "g               (0 -9.81 0);\n"
        "\n"
        "title           \"a \\\"quoted\\\" title\";\n"
        "\n"
        "empty;\n"
        "\n"
        "solver\n"
        "{\n"
        "    tolerance       1e-06;\n"
        "    inner\n"
        "    {\n"
        "        list            (1 2 3);\n"
        "    }\n"
        "}\n";
    EXPECT_EQ(written(d), expected);
}


TEST(dictionaryWrite, patternsAndListsAsOpenFoam)
{
    const auto d = dictionary::fromString
    (
        "\"(U|k)\" 1;\nsn 3(1 2 3);\nsu 10{0};\nrho [kg/m^3] 1000;\n"
        "nu [0 2 -1 0 0 0 0] 1e-06;\n"
    );
    std::istringstream is(written(d));
    std::vector<std::string> lines;
    for (std::string l; std::getline(is, l);)
    {
        if (!l.empty())
        {
            lines.push_back(l);
        }
    }
    // A quoted keyword takes its two quotes out of the padding.
    EXPECT_EQ(lines, (std::vector<std::string>{
        "\"(U|k)\"         1;",
        "sn              3(1 2 3);",
        "su              10{0};",
        "rho             [kg/m^3] 1000;",
        "nu              [0 2 -1 0 0 0 0] 1e-06;"}));
}


TEST(dictionaryWrite, setReplacesInPlaceAndRemove)
{
    auto d = dictionary::fromString("a 1; b 2; c 3;");
    d.set("b", std::string("two"));
    d.set<const char*>("d", "four");
    d.set("e", "five words");
    EXPECT_EQ(d.keys(), (std::vector<std::string>{"a", "b", "c", "d", "e"}));
    EXPECT_EQ(d.get<std::string>("b"), "two");
    EXPECT_EQ(d.get<std::string>("d"), "four");
    EXPECT_EQ(tokensOf(d, "e")[0].type, token::kind::string);
    EXPECT_TRUE(d.remove("a"));
    EXPECT_FALSE(d.remove("a"));
    EXPECT_EQ(d.keys(), (std::vector<std::string>{"b", "c", "d", "e"}));
    // A value that would read back as a number or switch stays a string.
    d.set("version", std::string("2.0"));
    EXPECT_EQ(tokensOf(d, "version")[0].type, token::kind::string);
}


// * * * * * * * * * * * * * * * Round trips * * * * * * * * * * * * * * * //

TEST(dictionaryRoundTrip, everySetType)
{
    dictionary d("roundTrip");
    d.set("b", false);
    d.set("l", label(-42));
    d.set("i64", std::int64_t(1) << 40);
    d.set("s1", 0.1);
    d.set("s2", 1.0/3.0);
    d.set("s3", 6.02214076e23);
    d.set("s4", -2.5e-300);
    d.set("s5", 1000.0);
    d.set("w", std::string("linear"));
    d.set("str", std::string("with \"quotes\", \\backslash and\nnewline"));
    d.set("path", std::string("constant/geometry/gate.stl"));
    d.set("v", vec3{1e-3, -2, 3.25});
    d.set("ls", std::vector<double>{0.5, 1e-7, -3});
    d.set("ll", std::vector<label>{});
    d.set("lw", std::vector<std::string>{"a", "b c", "\"q\""});
    d.set("lv", std::vector<vec3>{{1, 2, 3}, {4, 5, 6}});
    d.set("cstr", "text");

    const auto back = dictionary::fromString(written(d));
    EXPECT_EQ(back, d) << written(d) << "\n---\n" << written(back);
    EXPECT_EQ(back.get<bool>("b"), false);
    EXPECT_EQ(back.get<label>("l"), -42);
    EXPECT_EQ(back.get<std::int64_t>("i64"), std::int64_t(1) << 40);
    EXPECT_EQ(back.get<double>("s1"), 0.1);
    EXPECT_EQ(back.get<double>("s2"), 1.0/3.0);
    EXPECT_EQ(back.get<double>("s3"), 6.02214076e23);
    EXPECT_EQ(back.get<double>("s4"), -2.5e-300);
    EXPECT_EQ(back.get<double>("s5"), 1000.0);
    EXPECT_EQ(back.get<std::string>("str"),
              "with \"quotes\", \\backslash and\nnewline");
    EXPECT_EQ(back.get<std::string>("path"), "constant/geometry/gate.stl");
    EXPECT_EQ(back.get<vec3>("v"), (vec3{1e-3, -2, 3.25}));
    EXPECT_EQ(back.get<std::vector<double>>("ls"),
              (std::vector<double>{0.5, 1e-7, -3}));
    EXPECT_TRUE(back.get<std::vector<label>>("ll").empty());
    EXPECT_EQ(back.get<std::vector<std::string>>("lw"),
              (std::vector<std::string>{"a", "b c", "\"q\""}));
    EXPECT_EQ(back.get<std::vector<vec3>>("lv"),
              (std::vector<vec3>{{1, 2, 3}, {4, 5, 6}}));
    EXPECT_EQ(back.get<std::string>("cstr"), "text");
}


TEST(dictionaryRoundTrip, parsedFilesWriteAndReadBack)
{
    for (const std::string name :
         {"/system/fvSolution", "/constant/transportProperties"})
    {
        const auto d = dictionary::fromFile(dataDir + name);
        const auto back = dictionary::fromString(written(d));
        EXPECT_EQ(back, d) << name << ":\n" << written(d);
        EXPECT_GT(d.size(), 1u);
    }

    const auto d = dictionary::fromString
    (
        "\"(inlet|outlet)\" { type \"zero.*\"; \"w.*\" { n 1; } }\n"
        "nested { a { b { c { d (1 2 (3 4) \"five\"); } } } }\n"
        "units rho [kg/m^3] 1000;\n"
        "units2 9.81 [m/s^2];\n"
        "dims [0 2 -1 0 0 0 0];\n"
        "mixed (a 1 2.5 \"s t\" (x y) [m]);\n"
        "uniformList 10{(0 0 1)};\n"
        "blocks ( hex { n 1; } );\n"
        "code #{ x = \"y\"; #};\n"
        "escaped \"a\\\\\\\"b\";\n"
        "minus - 1;\n"
        "div(phi,U) Gauss linear;\n"
        "empty;\n"
    );
    const auto back = dictionary::fromString(written(d));
    EXPECT_EQ(back, d) << written(d) << "\n---\n" << written(back);
    EXPECT_EQ(written(back), written(d));
    EXPECT_NE(d, dictionary::fromString("a 1;"));
}


TEST(dictionaryRoundTrip, writeFileReadFile)
{
    scratchDir dir("dictWrite");
    const auto d = dictionary::fromFile(dataDir + "/system/fvSolution");
    const auto file = dir.path()/"fvSolution";
    d.writeFile(file, "system");
    const auto back = dictionary::fromFile(file);
    EXPECT_EQ(back, d);
    ASSERT_NE(back.header(), nullptr);
    EXPECT_EQ(back.header()->get<std::string>("object"), "fvSolution");
    EXPECT_EQ(back.header()->get<std::string>("class"), "dictionary");
    EXPECT_EQ(back.header()->get<std::string>("location"), "system");

    // Copies are deep and independent, with parents of their own.
    dictionary copy = back;
    EXPECT_EQ(copy, back);
    copy.subDict("PISO").set("nCorrectors", label(3));
    EXPECT_NE(copy, back);
    EXPECT_EQ(back.subDict("PISO").get<label>("nCorrectors"), 2);
    EXPECT_EQ(copy.subDict("PISO").parent(), &copy);
    dictionary moved = std::move(copy);
    EXPECT_EQ(moved.subDict("PISO").parent(), &moved);
    EXPECT_EQ(moved.subDict("PISO").get<label>("nCorrectors"), 3);
    // Assigning to a sub-dictionary keeps its place and scoped name.
    moved.subDict("PISO") = dictionary::fromString("n 1; s { m 2; }");
    EXPECT_EQ(moved.subDict("PISO").keys(),
              (std::vector<std::string>{"n", "s"}));
    EXPECT_EQ(moved.subDict("PISO").parent(), &moved);
    EXPECT_EQ(moved.subDict("PISO").subDict("s").name(),
              moved.name() + "/PISO/s");
    EXPECT_EQ(moved.subDict("PISO").subDict("s").parent(),
              &moved.subDict("PISO"));
    // Assigning a dictionary its own sub-dictionary.
    moved = moved.subDict("solvers");
    EXPECT_TRUE(moved.isDict("pFinal"));
    EXPECT_EQ(moved.subDict("pFinal").parent(), &moved);
}


// * * * * * * * * * * * * * * * * OpenFOAM * * * * * * * * * * * * * * * * //

TEST(dictionaryOpenFoam, foamDictionaryReadsOurOutput)
{
    if (!std::filesystem::exists("/usr/bin/foamDictionary"))
    {
        GTEST_SKIP() << "OpenFOAM's foamDictionary is not installed";
    }
    scratchDir dir("dictFoam");
    auto d = dictionary::fromFile(dataDir + "/system/fvSolution");
    d.set("title", std::string("a \"quoted\" title"));
    d.set("g", vec3{0, -9.81, 0});
    d.set("points", std::vector<vec3>{{0, 0, 0}, {1, 2, 3}});
    d.set("deltaT", 1e-05);
    const auto extra = dictionary::fromString
    (
        "nu [0 2 -1 0 0 0 0] 1e-06;\nrho [kg/m^3] 1000;\nsu 3{0.5};\n"
        "sn 2(1 2);\nempty;\n"
    );
    for (const auto& k : extra.keys())
    {
        d.setTokens(k, extra.lookupEntry(k).tokens());
    }
    const auto file = dir.path()/"controlDict";
    d.writeFile(file, "system");

    auto run = [&](const std::string& args, std::string& out)
    {
        const std::string cmd = "bash -c 'source /usr/share/openfoam/etc/"
            "bashrc >/dev/null 2>&1; foamDictionary " + args + " "
            + file.string() + "' 2>&1";
        FILE* pipe = ::popen(cmd.c_str(), "r");
        if (!pipe)
        {
            return -1;
        }
        out.clear();
        char buf[4096];
        while (std::fgets(buf, sizeof(buf), pipe))
        {
            out += buf;
        }
        const int status = ::pclose(pipe);
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    };

    std::string out;
    ASSERT_EQ(run("", out), 0) << out;
    for (const std::string s :
         {"solvers", "pFinal", "\"(U|k|epsilon)Final\"", "symGaussSeidel",
          "nCorrectors     2;", "\"a \\\"quoted\\\" title\"", "1e-05",
          "object          controlDict;"})
    {
        EXPECT_NE(out.find(s), std::string::npos) << s << " in\n" << out;
    }

    ASSERT_EQ(run("-entry solvers/pFinal/solver -value", out), 0) << out;
    EXPECT_EQ(out, "PCG\n");
    ASSERT_EQ(run("-entry PISO/pTolerance -value", out), 0) << out;
    EXPECT_EQ(out, "1e-06\n");
    ASSERT_EQ(run("-entry g -value", out), 0) << out;
    EXPECT_NE(out.find("0 -9.81 0"), std::string::npos) << out;
    ASSERT_EQ(run("-entry su -value", out), 0) << out;
    EXPECT_NE(out.find("0.5"), std::string::npos) << out;
    ASSERT_EQ(run("-entry nu -value", out), 0) << out;
    EXPECT_NE(out.find("1e-06"), std::string::npos) << out;
}
