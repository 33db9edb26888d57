/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Malformed dictionaries: each must stop with a FatalError naming the file,
// the line, and what was expected and found. Refused directives, include
// recursion and bad values are here too.

#include "dictionary.H"
#include "error.H"
#include "../testTools.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <random>
#include <sstream>

using namespace sphvcpm;
using test::catchFatal;
using test::expectError;
using test::scratchDir;

namespace
{

// A case file name, so that messages are checked for the real thing.
const std::string caseFile = "/home/user/run/damBreak/system/badDict";

struct syntaxCase
{
    const char* name;
    const char* text;
    int line;
    std::vector<std::string> parts;
};

// Errors while reading (lexer, entries, macros, directives).
const std::vector<syntaxCase> syntaxCases =
{
    {"unterminatedString", "a 1;\nb \"abc\\\ndef", 2,
     {"Unterminated string (opened at line 2)", "expected a closing '\"'",
      "found end of file"}},
    {"newlineInString", "a 1;\nb \"abc\ndef\";\n", 2,
     {"Newline inside a string (opened at line 2)"}},
    {"unterminatedComment", "a 1;\n/* a comment\nb 2;\n", 2,
     {"Unterminated /* comment (opened at line 2)", "expected '*/'",
      "found end of file"}},
    {"unterminatedVerbatim", "a 1;\ncode #{ x = 1;\n", 2,
     {"Unterminated verbatim string #{", "expected '#}'"}},
    {"missingSemicolonAtEof", "a 1;\nb 2", 2,
     {"Unexpected end of file after the value of keyword 'b'",
      "expected ';'"}},
    {"missingSemicolonBeforeBrace", "s\n{\n    a 1\n}\n", 3,
     {"Missing ';' after the value of keyword 'a'", "expected ';'",
      "found '}' at line 4"}},
    {"eofInsideDict", "a 1;\nsub\n{\n    b 2;\n", 3,
     {"Unexpected end of file in sub-dictionary 'sub' opened at line 3",
      "expected '}'"}},
    {"eofInsideNestedDict", "a\n{\n    b\n    {\n        c 1;\n    }\n", 2,
     {"Unexpected end of file in sub-dictionary 'a' opened at line 2"}},
    {"strayClosingBrace", "a 1;\n}\nb 2;\n", 2,
     {"Unexpected '}' with no matching '{'", "expected a keyword"}},
    {"unclosedParenthesis", "a (1 2;\nb 3;\n", 1,
     {"in the value of keyword 'a'", "expected ')' to close '(' opened at "
      "line 1", "Unexpected end of file"}},
    {"unmatchedParenthesis", "x 0;\na 1 2);\n", 2,
     {"Unmatched ')' in the value of keyword 'a'"}},
    {"mismatchedBracket", "a (1\n2};\n", 2,
     {"Mismatched '}' in the value of keyword 'a'",
      "expected ')' to close '(' opened at line 1"}},
    {"badNumber", "a 1;\nb 1.2.3;\n", 2, {"Bad number '1.2.3'"}},
    {"badExponent", "a 1e;\n", 1, {"Bad number '1e'"}},
    {"numberOverflows", "a 1;\nb -1e999;\n", 2,
     {"Number '-1e999' is too large", "1.8e308"}},
    {"singleQuote", "a 'x';\n", 1,
     {"Unexpected single quote", "double quotes"}},
    {"unbalancedWord", "div(phi,U Gauss linear;\n", 1,
     {"Unbalanced parentheses in word 'div(phi,U'", "expected ')'"}},
    {"numberAsKeyword", "a 1;\n42 b;\n", 2,
     {"Expected a keyword, found integer 42"}},
    {"punctuationAsKeyword", "a 1;\n\n[ b ];\n", 3,
     {"Expected a keyword, found '['"}},
    {"eofAfterKeyword", "a 1;\nb", 2,
     {"Unexpected end of file after keyword 'b'", "expected a value"}},
    {"calcRefused", "a 1;\nb #calc \"$a + 1\";\n", 2,
     {"Directive #calc is not supported by sphvcpm",
      "compiles and runs C++"}},
    {"codeStreamRefused", "a\n{\n    #codeStream { code #{ #}; }\n}\n", 3,
     {"Directive #codeStream is not supported by sphvcpm"}},
    {"ifRefused", "a 1;\n#if 1\nb 2;\n#endif\n", 2,
     {"Directive #if is not supported by sphvcpm", "conditional"}},
    {"ifeqRefused", "#ifeq $a 1\n", 1,
     {"Directive #ifeq is not supported by sphvcpm"}},
    {"elseRefused", "a 1;\n#else\n", 2,
     {"Directive #else is not supported by sphvcpm"}},
    {"endifRefused", "#endif\n", 1,
     {"Directive #endif is not supported by sphvcpm"}},
    {"includeFuncRefused", "functions\n{\n    #includeFunc probes\n}\n", 3,
     {"Directive #includeFunc is not supported by sphvcpm"}},
    {"unknownDirective", "a 1;\n#frobnicate x\n", 2,
     {"Directive #frobnicate is not supported by sphvcpm",
      "Supported directives are (#include #includeIfPresent #sinclude "
      "#includeEtc #remove #inputMode)"}},
    {"directiveInValue", "a 1 #include \"x\";\n", 1,
     {"Directive #include cannot appear inside the value of keyword 'a'"}},
    {"includeWithoutQuotes", "#include controlDict\n", 1,
     {"Expected a quoted file name after #include",
      "found word 'controlDict'"}},
    {"includeAtEof", "a 1;\n#include", 2,
     {"Expected a quoted file name after #include", "found end of file"}},
    {"includeMissingFile", "a 1;\n\n#include \"notThere\"\n", 3,
     {"Cannot find #include file \"notThere\"",
      "/home/user/run/damBreak/system/notThere"}},
    {"badInputMode", "#inputMode sloppy\n", 1,
     {"Expected one of (merge overwrite protect warn error default) after "
      "#inputMode", "found word 'sloppy'"}},
    {"removeNothing", "a 1;\n#remove ;\n", 2,
     {"Expected a keyword or a list (a b ...) after #remove", "found ';'"}},
    {"removeUnclosedList", "a 1;\n#remove (a b\n", 2,
     {"Unexpected end of file in the list of #remove", "expected ')'"}},
    {"duplicateInErrorMode", "#inputMode error\na 1;\nb 2;\na 3;\n", 4,
     {"Duplicate keyword 'a'", "first defined at line 2"}},
    {"undefinedVariable", "nu 1e-6;\nrho 1000;\nmu $nuu;\n", 3,
     {"Undefined variable '$nuu' in the value of keyword 'mu'",
      "Did you mean 'nu'?", "Valid keywords are: (nu rho)"}},
    {"undefinedScopedVariable", "a { b 1; }\nc $a/x;\n", 2,
     {"Undefined variable '$a/x'", "no keyword 'a/x' in dictionary \""
      "/home/user/run/damBreak/system/badDict/a\"",
      "Valid keywords are: (b)"}},
    {"parentOfTopLevel", "a $../b;\n", 1, {"Undefined variable '$../b'"}},
    {"spliceValue", "a 1;\nb\n{\n    $a;\n}\n", 4,
     {"Cannot splice '$a'", "it is not a sub-dictionary"}},
    {"dictExpandedOutsideBrackets", "a { b 1; }\nc x $a;\n", 2,
     {"The sub-dictionary $a is expanded outside brackets in the value of "
      "keyword 'c'", "write 'c $a;' to copy it"}},
    {"patternNotUsedInValue", "\".*\" 1;\nb $a;\n", 2,
     {"Undefined variable '$a'"}},
    {"keyFromDictVariable", "a { }\n$a { b 1; }\n", 2,
     {"'$a' used as a keyword must name a single word",
      "it is a sub-dictionary"}},
    {"badVariable", "a 1;\nb $ ;\n", 2,
     {"Bad variable: expected a name after '$'", "found ' '"}},
    {"unterminatedBracedVariable", "a ${b;\n", 1,
     {"Unterminated variable '${b;", "expected '}'"}},
    {"badDirective", "a 1;\n# b 2;\n", 2,
     {"Bad directive: expected a name after '#'"}},
    {"invalidRegexKey", "a 1;\n\"(abc\" 2;\n", 2,
     {"Invalid regular expression \"(abc\" as keyword"}},
    {"anonymousList", "(a b);\n", 1,
     {"Expected a keyword, found '('", "not supported"}},
};


// Names the case in gtest's output instead of dumping its bytes.
void PrintTo(const syntaxCase& c, std::ostream* os)
{
    *os << c.name;
}

class dictionarySyntaxError : public testing::TestWithParam<syntaxCase> {};

std::string caseName(const testing::TestParamInfo<syntaxCase>& info)
{
    return info.param.name;
}

} // End anonymous namespace


TEST_P(dictionarySyntaxError, namesFileLineAndCause)
{
    const syntaxCase& c = GetParam();
    const auto err = catchFatal([&]
    {
        dictionary::fromString(c.text, caseFile);
    });
    expectError(err, caseFile, c.line, c.parts);
}

INSTANTIATE_TEST_SUITE_P(table, dictionarySyntaxError,
                         testing::ValuesIn(syntaxCases), caseName);


namespace
{

struct valueCase
{
    const char* name;
    const char* text;
    std::function<void(const dictionary&)> get;
    int line;
    std::vector<std::string> parts;
};

const std::vector<valueCase> valueCases =
{
    {"labelOverflow", "a 1;\nn 3000000000;\n",
     [](const dictionary& d){ d.get<label>("n"); }, 2,
     {"Keyword 'n'", "integer 3000000000 is out of range for a 32-bit label",
      "-2147483648 to 2147483647"}},
    {"labelUnderflow", "n -2147483649;\n",
     [](const dictionary& d){ d.get<label>("n"); }, 1,
     {"integer -2147483649 is out of range for a 32-bit label"}},
    {"int64Overflow", "n 99999999999999999999;\n",
     [](const dictionary& d){ d.get<std::int64_t>("n"); }, 1,
     {"integer 99999999999999999999 is out of range for a 64-bit integer"}},
    {"floatForInteger", "a 1;\nnCorr 2.5;\n",
     [](const dictionary& d){ d.get<label>("nCorr"); }, 2,
     {"Keyword 'nCorr'", "expected an integer (a 32-bit label)",
      "found floating-point number 2.5"}},
    {"floatInIntegerList", "l\n(\n    1\n    2.0\n);\n",
     [](const dictionary& d){ d.get<std::vector<label>>("l"); }, 4,
     {"expected an integer", "found floating-point number 2.0"}},
    {"trailingTokens", "a 1 2;\n",
     [](const dictionary& d){ d.get<double>("a"); }, 1,
     {"Keyword 'a'", "unexpected integer 2 after the value",
      "expected ';' to end the entry"}},
    {"forgottenSemicolon", "endTime 1\ndeltaT 0.1;\n",
     [](const dictionary& d){ d.get<double>("endTime"); }, 2,
     {"Keyword 'endTime'", "unexpected word 'deltaT' after the value"}},
    {"wordForNumber", "a\n    abc;\n",
     [](const dictionary& d){ d.get<double>("a"); }, 2,
     {"Keyword 'a'", "expected a number", "found word 'abc'"}},
    {"emptyForNumber", "x 1;\na;\n",
     [](const dictionary& d){ d.get<double>("a"); }, 2,
     {"expected a number", "found no value (an empty entry)"}},
    {"badSwitch", "adjustTimeStep maybe;\n",
     [](const dictionary& d){ d.get<bool>("adjustTimeStep"); }, 1,
     {"expected a switch (true/false, on/off, yes/no",
      "found word 'maybe'"}},
    {"numberForSwitch", "a 2;\n",
     [](const dictionary& d){ d.get<bool>("a"); }, 1,
     {"Keyword 'a'", "expected a switch", "1/0)", "found integer 2"}},
    {"floatForSwitch", "\nopenTop 1.0;\n",
     [](const dictionary& d){ d.get<bool>("openTop"); }, 2,
     {"Keyword 'openTop'", "expected a switch",
      "found floating-point number 1.0"}},
    {"numberForWord", "\ntype 3;\n",
     [](const dictionary& d){ d.get<std::string>("type"); }, 2,
     {"expected a word or a quoted string", "found integer 3"}},
    {"listSizeMismatch", "a 1;\nl 3(1 2);\n",
     [](const dictionary& d){ d.get<std::vector<double>>("l"); }, 2,
     {"Keyword 'l'", "list size 3 given but 2 elements found"}},
    {"notAList", "l 5;\n",
     [](const dictionary& d){ d.get<std::vector<double>>("l"); }, 1,
     {"expected a list of numbers ( ... )", "found integer 5"}},
    {"vectorTooLong", "g (0 -9.81 0 1);\n",
     [](const dictionary& d){ d.get<vec3>("g"); }, 1,
     {"Keyword 'g'", "expected a vector of 2 or 3 components, found 4"}},
    {"vectorTooShort", "g (1);\n",
     [](const dictionary& d){ d.get<vec3>("g"); }, 1,
     {"expected a vector of 2 or 3 components, found 1"}},
    {"vectorBadComponent", "g\n(\n    0\n    x\n    0\n);\n",
     [](const dictionary& d){ d.get<vec3>("g"); }, 4,
     {"expected a number (vector component)", "found word 'x'"}},
    {"scalarForVector", "g 9.81;\n",
     [](const dictionary& d){ d.get<vec3>("g"); }, 1,
     {"expected '(' to start a vector (x y z)",
      "found floating-point number 9.81"}},
    {"pointForListOfPoints", "probeLocations (0.29 0.05 0);\n",
     [](const dictionary& d){ d.get<std::vector<vec3>>("probeLocations"); },
     1, {"Keyword 'probeLocations'", "expected '(' to start a vector of the"
      " list (a list of points is ((x y z) ...), and one point ((x y z)))",
      "found floating-point number 0.29"}},
    {"uniformListUnclosed", "l 3{1 2};\n",
     [](const dictionary& d){ d.get<std::vector<double>>("l"); }, 1,
     {"expected '}' to close the uniform list 3{...}", "found integer 2"}},
    {"subDictForValue", "a\n{\n}\n",
     [](const dictionary& d){ d.get<double>("a"); }, 1,
     {"Keyword 'a'", "found a sub-dictionary"}},
    {"wordNotAllowed", "device gpu;\n",
     [](const dictionary& d){ d.getWord("device", {"cpu", "cuda"}); }, 1,
     {"Keyword 'device'", "unknown value 'gpu'", "Did you mean 'cpu'?",
      "Valid values are: (cpu cuda)"}},
    {"notPositive", "\n\ndp -0.01;\n",
     [](const dictionary& d){ d.getPositive("dp"); }, 3,
     {"Keyword 'dp'", "expected a positive number, found -0.01"}},
};


void PrintTo(const valueCase& c, std::ostream* os)
{
    *os << c.name;
}

class dictionaryValueError : public testing::TestWithParam<valueCase> {};

std::string valueCaseName(const testing::TestParamInfo<valueCase>& info)
{
    return info.param.name;
}

} // End anonymous namespace


TEST_P(dictionaryValueError, namesFileLineAndCause)
{
    const valueCase& c = GetParam();
    const auto d = dictionary::fromString(c.text, caseFile);
    const auto err = catchFatal([&]{ c.get(d); });
    expectError(err, caseFile, c.line, c.parts);
}

INSTANTIATE_TEST_SUITE_P(table, dictionaryValueError,
                         testing::ValuesIn(valueCases), valueCaseName);


// Vectors of (x y) are a 2D case's shorthand for z = 0; a dictionary of a
// 3D case (and its sub-dictionaries, and copies of them) refuses them.
TEST(dictionaryErrors, twoComponentVectorsOnlyIn2D)
{
    dictionary d = dictionary::fromString("g (0 -9.81);\ns { p (1 2); }\n",
                                          "case");
    EXPECT_EQ(d.get<vec3>("g"), (vec3{0, -9.81, 0}));
    d.setCaseDimensions(3);
    expectError(catchFatal([&]{ d.get<vec3>("g"); }), "case", 1,
                {"expected a vector of 3 components (x y z) in a 3D case",
                 "found 2 components"});
    const dictionary sub = d.subDict("s");
    expectError(catchFatal([&]{ sub.get<vec3>("p"); }), "case", 2,
                {"3D case"});
    expectError(catchFatal([&]
        { d.subDict("s").getDimensioned<vec3>("p", dimensionSet()); }),
        "case", 2, {"3D case"});
    d.setCaseDimensions(2);
    EXPECT_EQ(d.subDict("s").get<vec3>("p"), (vec3{1, 2, 0}));
}


// A NUL byte inside a keyword: the report goes on past it (shown as \0)
// to the file and line, instead of ending where a C string would.
TEST(dictionaryErrors, nulByteDoesNotCutTheReport)
{
    const std::string text("a 1;\nad\0j 2;\n", 13);
    const auto err = catchFatal([&]
    {
        dictionary::fromString(text, "withNul").checkKeywords({"a"});
    });
    const std::string shown(err.what());
    EXPECT_NE(shown.find("ad\\0j"), std::string::npos) << shown;
    EXPECT_NE(shown.find("file: withNul at line 2"), std::string::npos)
        << shown;
}


// The header's format is checked in every dictionary, not only in the
// field files that act on it: a typo there must not pass unnoticed.
TEST(dictionaryErrors, foamFileHeaderFormat)
{
    const std::string bogus =
        "FoamFile\n{\n    version 2.0;\n    format bogus;\n}\na 1;\n";
    const auto err =
        catchFatal([&]{ dictionary::fromString(bogus, caseFile); });
    expectError(err, caseFile, 4, {"Keyword 'format': unknown value 'bogus'",
                                   "Valid values are: (ascii binary)"});
    EXPECT_EQ(err.keyword(), "format");

    // In an #include'd file too, although its header is dropped.
    scratchDir dir("dictHeaderFormat");
    dir.write("params", "FoamFile { format asci; }\nH 0.2;\n");
    const auto main = dir.write("main", "#include \"params\"\nL $H;\n");
    expectError(catchFatal([&]{ dictionary::fromFile(main); }),
                (dir.path()/"params").string(), 1,
                {"unknown value 'asci'", "Did you mean 'ascii'?"});

    // ascii, binary (also quoted) and no format at all are fine.
    for (const std::string format :
             {"format ascii;", "format binary;", "format \"binary\";", ""})
    {
        const auto d = dictionary::fromString
        (
            "FoamFile { version 2.0; " + format + " class dictionary; }\n"
            "a 1;\n"
        );
        ASSERT_NE(d.header(), nullptr) << format;
        EXPECT_EQ(d.keys(), std::vector<std::string>{"a"}) << format;
    }
}


// A runaway keyword or token is quoted by its start and its length, not
// in full; short ones are quoted as they are (the tables above).
TEST(dictionaryErrors, longTextClippedInMessages)
{
    const std::string longKey(1 << 20, 'k');
    const auto err = catchFatal([&]
    {
        dictionary::fromString("a 1;\n" + longKey + " 2;\n", caseFile)
            .checkKeywords({"a"});
    });
    expectError(err, caseFile, 2, {"Unknown keyword '"
        + std::string(80, 'k') + "... (1048576 characters)'"});
    EXPECT_LT(err.report().size(), 1000u) << err.report().substr(0, 1000);

    // Looked up, the long keyword is listed clipped too.
    const auto d = dictionary::fromString("a 1;\n" + longKey + " 2;\n"
        + "w " + std::string(100000, 'w') + ";\n", caseFile);
    const auto missing = catchFatal([&]{ d.get<double>("b"); });
    expectError(missing, caseFile, 0, {"Keywords present: (a "
        + std::string(80, 'k') + "... (1048576 characters) w)"});
    EXPECT_LT(missing.report().size(), 1000u);

    // A long token where a number is expected.
    const auto word = catchFatal([&]{ d.get<double>("w"); });
    expectError(word, caseFile, 3, {"Keyword 'w'", "expected a number",
        "found word '" + std::string(80, 'w') + "... (100000 characters)'"});
    EXPECT_LT(word.report().size(), 1000u);

    // A long bad token found by the lexer.
    std::string number = "1";
    for (int i = 0; i < 50000; ++i)
    {
        number += ".1";
    }
    const auto bad = catchFatal([&]
    {
        dictionary::fromString("a " + number + ";\n", caseFile);
    });
    expectError(bad, caseFile, 1,
                {"Bad number '" + number.substr(0, 80) + "... (100001 "
                 "characters)'"});
    EXPECT_LT(bad.report().size(), 1000u);

    // A long file name, and the paths made of it.
    const std::string name(100000, 'f');
    const auto include = catchFatal([&]
    {
        dictionary::fromString("#include \"" + name + "\"\n", caseFile);
    });
    expectError(include, caseFile, 1, {"Cannot find #include file \""
        + name.substr(0, 80) + "... (100000 characters)\"",
        "/home/user/run/damBreak/system/ffff", "(100031 characters)"});
    EXPECT_LT(include.report().size(), 2000u);

    // Multi-byte UTF-8 characters are not cut in half, and are counted
    // as characters.
    std::string accents;
    for (int i = 0; i < 100; ++i)
    {
        accents += "\xC3\xA9";   // e acute
    }
    const auto utf8 = catchFatal([&]
    {
        dictionary::fromString(accents + " 1;\n", caseFile)
            .checkKeywords({"a"});
    });
    expectError(utf8, caseFile, 1, {"Unknown keyword '" + accents.substr(0, 80)
        + "... (100 characters)'"});
}


// * * * * * * * * * * * * * * * * Includes * * * * * * * * * * * * * * * //

TEST(dictionaryIncludeErrors, recursionIsCaught)
{
    const std::string dir = std::string(SPHVCPM_TEST_DATA)
        + "/dictionaries/recursive";
    const auto err = catchFatal([&]
    {
        dictionary::fromFile(dir + "/a");
    });
    // a includes b (line 3 of a), b includes a again at its line 3.
    expectError(err, dir + "/b", 3, {"Recursive #include of \"a\"",
                                       "recursive/a -> ", "recursive/b -> ",
                                       "recursive/a"});
}


TEST(dictionaryIncludeErrors, selfIncludeAndDepthLimit)
{
    scratchDir dir("dictRecursion");
    const auto self = dir.write("self", "a 1;\n#include \"self\"\n");
    expectError(catchFatal([&]{ dictionary::fromFile(self); }),
                self.string(), 2, {"Recursive #include of \"self\""});

    // A long chain of distinct files stops at the depth limit.
    for (int i = 0; i < 40; ++i)
    {
        dir.write("chain" + std::to_string(i),
                  "x" + std::to_string(i) + " 1;\n#include \"chain"
                  + std::to_string(i + 1) + "\"\n");
    }
    dir.write("chain40", "end 1;\n");
    const auto err =
        catchFatal([&]{ dictionary::fromFile(dir.path()/"chain0"); });
    EXPECT_NE(err.message().find("nested more than 32 levels deep"),
              std::string::npos) << err.message();
    EXPECT_EQ(err.line(), 2);
    EXPECT_NE(err.file().find("chain"), std::string::npos);

    // A shorter chain is fine.
    dir.write("chain5", "end 1;\n");
    const auto d = dictionary::fromFile(dir.path()/"chain0");
    EXPECT_EQ(d.keys(), (std::vector<std::string>
        {"x0", "x1", "x2", "x3", "x4", "end"}));
}


TEST(dictionaryIncludeErrors, errorsInIncludedFileNameThatFile)
{
    scratchDir dir("dictIncludedError");
    dir.write("constant/bad", "ok 1;\n\nbroken (1 2;\n");
    const auto main =
        dir.write("system/main", "a 1;\n#include \"../constant/bad\"\n");
    expectError(catchFatal([&]{ dictionary::fromFile(main); }),
                (dir.path()/"system"/"../constant/bad").string(), 3,
                {"expected ')' to close '(' opened at line 3"});
}


TEST(dictionaryIncludeErrors, includeEtcWithoutInstallation)
{
    const char* old = std::getenv("SPHVCPM_DIR");
    const std::string saved = old ? old : "";
    ::unsetenv("SPHVCPM_DIR");
    const auto err = catchFatal([]
    {
        dictionary::fromString("\n#includeEtc \"caseDicts/x\"\n", "f");
    });
    if (old)
    {
        ::setenv("SPHVCPM_DIR", saved.c_str(), 1);
    }
    expectError(err, "f", 2, {"#includeEtc \"caseDicts/x\"",
                              "SPHVCPM_DIR is not set"});
}


// Something that is there but is not a file is named as such, not
// reported missing.
TEST(dictionaryIncludeErrors, notARegularFile)
{
    scratchDir dir("dictIncludeDirectory");
    std::filesystem::create_directories(dir.path()/"params");
    const auto main =
        dir.write("main", "a 1;\n#include \"params\"\n");
    const auto err = catchFatal([&]{ dictionary::fromFile(main); });
    expectError(err, main.string(), 2, {"Cannot read #include file \""
        + (dir.path()/"params").string() + "\": it is a directory"});
    EXPECT_EQ(err.message().find("Cannot find"), std::string::npos)
        << err.message();

    const auto absolute = catchFatal([&]
    {
        dictionary::fromString("#include \"/tmp\"\n", caseFile);
    });
    expectError(absolute, caseFile, 1, {"\"/tmp\": it is a directory"});

    const auto device = catchFatal([&]
    {
        dictionary::fromString("a 1;\n#include \"/dev/null\"\n", caseFile);
    });
    expectError(device, caseFile, 2, {"Cannot read #include file "
        "\"/dev/null\": it is not a regular file"});

    // Optional includes skip it, as OpenFOAM does.
    const auto d = dictionary::fromString
    (
        "a 1;\n#includeIfPresent \"/tmp\"\n#sinclude \"/dev/null\"\n",
        caseFile
    );
    EXPECT_EQ(d.keys(), std::vector<std::string>{"a"});
}


TEST(dictionaryIncludeErrors, missingFile)
{
    expectError
    (
        catchFatal([]
        {
            dictionary::fromFile("/nonexistent/system/fvSchemes");
        }),
        "/nonexistent/system/fvSchemes", 0,
        {"Cannot open dictionary file \"/nonexistent/system/fvSchemes\""}
    );
}


// * * * * * * * * * * * * * * * * Limits * * * * * * * * * * * * * * * * //

TEST(dictionaryLimits, deepNestingIsAnErrorNotACrash)
{
    std::string text;
    for (int i = 0; i < 100000; ++i)
    {
        text += "a {\n";
    }
    expectError(catchFatal([&]{ dictionary::fromString(text, "deep"); }),
                "deep", 257, {"Sub-dictionary 'a' nested more than 256 "
                              "levels deep"});

    // Within the limit nesting is fine.
    std::string ok = "x 1;\n";
    for (int i = 0; i < 100; ++i)
    {
        ok += "a { ";
    }
    ok += "v $x;";
    for (int i = 0; i < 100; ++i)
    {
        ok += " }";
    }
    const auto d = dictionary::fromString(ok);
    const dictionary* cur = &d;
    for (int i = 0; i < 100; ++i)
    {
        cur = &cur->subDict("a");
    }
    EXPECT_EQ(cur->get<label>("v"), 1);

    const std::string units = "x [" + std::string(1000, '(') + "m"
        + std::string(1000, ')') + "] 1;";
    expectError
    (
        catchFatal([&]{ dictionary::fromString(units, "u").get<double>("x"); }),
        "u", 1, {"brackets nested too deep"}
    );
}


// A quoted keyword is a regular expression, and std::regex recurses: a
// very long one (100,000 characters, or 20,000 nested groups) overflowed
// the stack. Refused by length; the longest allowed still compiles.
TEST(dictionaryLimits, longPatternKeywordIsAnErrorNotACrash)
{
    const std::string longPattern = "\"" + std::string(100000, 'a')
        + "\" 1;\n";
    expectError(catchFatal([&]{ dictionary::fromString(longPattern, "p"); }),
                "p", 1, {"regular expression", "100000 characters",
                         "more than the 1000 allowed"});
    const std::string nested = "\"" + std::string(20000, '(') + "a"
        + std::string(20000, ')') + "\" 1;\n";
    expectError(catchFatal([&]{ dictionary::fromString(nested, "n"); }),
                "n", 1, {"regular expression", "40001 characters"});

    const std::string deepest = "\"" + std::string(499, '(') + "a+"
        + std::string(499, ')') + "\" 1;\n";
    const auto d = dictionary::fromString(deepest, "ok");
    EXPECT_EQ(d.get<label>("aaa"), 1);
}


TEST(dictionaryLimits, keywordsMadeInCodeMustBeWords)
{
    dictionary d("built");
    for (const std::string bad : {"two words", "", "1abc", "a;b", "\"q\"",
                                  "a/b", "{"})
    {
        expectError(catchFatal([&]{ d.set(bad, label(1)); }), "built", 0,
                    {"Invalid keyword '" + bad + "'"});
        expectError(catchFatal([&]{ d.setSubDict(bad); }), "built", 0,
                    {"Invalid keyword '" + bad + "'"});
    }
    d.set("div(phi,U)", "Gauss linear");
    d.set("alpha.water", 0.5);
    EXPECT_EQ(d.keys(), (std::vector<std::string>{"div(phi,U)",
                                                  "alpha.water"}));
}


// Random edits of a real file: every result either reads (and then writes
// and reads back equal) or stops with a FatalError inside the text.
TEST(dictionaryLimits, mutatedInputsReadOrFailCleanly)
{
    std::ifstream is(std::string(SPHVCPM_TEST_DATA)
        + "/dictionaries/system/fvSolution");
    std::stringstream ss;
    ss << is.rdbuf();
    const std::string base = ss.str()
        + "vals (1 2.5 -3e-2 \"s\\\"q\" [m/s]);\nw 3{(0 0 1)};\n"
          "code #{ a; #};\nref $PISO/nCorrectors;\nc { $relaxationFactors; }\n";
    ASSERT_GT(base.size(), 500u);

    const std::string alphabet = "{}();[]\"'#$/*\\\n -.0123456789eab:!";
    std::mt19937 rng(20240611);
    int readOk = 0;
    int failed = 0;
    for (int i = 0; i < 2000; ++i)
    {
        std::string text = base;
        const int edits = 1 + int(rng() % 4);
        for (int k = 0; k < edits; ++k)
        {
            const std::size_t pos = rng() % text.size();
            const char c = alphabet[rng() % alphabet.size()];
            switch (rng() % 3)
            {
                case 0: text.erase(pos, 1); break;
                case 1: text.insert(pos, 1, c); break;
                default: text[pos] = c; break;
            }
        }
        const int lines =
            1 + int(std::count(text.begin(), text.end(), '\n'));
        try
        {
            const auto d = dictionary::fromString(text, "mutated");
            std::ostringstream os;
            d.write(os);
            const auto back = dictionary::fromString(os.str(), "written");
            std::ostringstream again;
            back.write(again);
            EXPECT_TRUE(back == d) << "written:\n" << os.str()
                << "\nread back and written:\n" << again.str();
            ++readOk;
        }
        catch (const FatalError& err)
        {
            EXPECT_EQ(err.file(), "mutated") << err.what();
            EXPECT_GE(err.line(), 1) << err.what();
            EXPECT_LE(err.line(), lines) << err.what();
            EXPECT_FALSE(err.message().empty());
            ++failed;
        }
        if (HasFailure())
        {
            break;
        }
    }
    EXPECT_GT(readOk, 100);
    EXPECT_GT(failed, 100);
}
