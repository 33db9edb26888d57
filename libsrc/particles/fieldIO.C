/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Writing and reading one particle field file (see timeDirectory.H):
//
//     FoamFile { format ascii|binary; class scalarField|...; ... }
//     value           nonuniform List<scalar|vector|label>
//     N
//     (
//     ...
//     )
//     ;
//
// Binary files hold "N(" followed directly by the raw values and ");".
// Read also: OpenFOAM's "value uniform v;" (v for every particle, as
// written by hand in 0/) and "N{v}".
// Fields have millions of values, so the header goes through the
// dictionary reader but the values do not: ascii values are converted with
// to_chars/from_chars in one pass over the file held in memory, binary ones
// with one memcpy. Line numbers are only counted when an error needs one.

#include "timeDirectory.H"
#include "dictionary.H"
#include "error.H"
#include "foamFile.H"
#include "particleFiles.H"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <sstream>
#include <type_traits>
#include <vector>

#if __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "binary particle fields are written little-endian (LSB) only"
#endif

namespace sphvcpm
{

static_assert(sizeof(vec3) == 3*sizeof(scalar),
              "vec3 must be three packed scalars for binary I/O");

// * * * * * * * * * * * * * * * * Helpers * * * * * * * * * * * * * * * * //

namespace
{

const char* className(fieldKind kind)
{
    switch (kind)
    {
        case fieldKind::scalarField: return "scalarField";
        case fieldKind::vectorField: return "vectorField";
        case fieldKind::labelField: return "labelField";
    }
    return "unknown";
}


const char* listType(fieldKind kind)
{
    switch (kind)
    {
        case fieldKind::scalarField: return "scalar";
        case fieldKind::vectorField: return "vector";
        case fieldKind::labelField: return "label";
    }
    return "unknown";
}


// Bytes of one value in a binary file (64-bit scalars in every build).
std::size_t valueBytes(fieldKind kind)
{
    switch (kind)
    {
        case fieldKind::scalarField: return sizeof(fileScalar);
        case fieldKind::vectorField: return 3*sizeof(fileScalar);
        case fieldKind::labelField: return sizeof(label);
    }
    return 0;
}


// Fewest characters an ascii value can take, separator included ("0\n",
// "(0 0 0)"), to refuse an N the file cannot hold before allocating it.
std::size_t minAsciiChars(fieldKind kind)
{
    return kind == fieldKind::vectorField ? 7 : 2;
}


inline bool isSpace(char c)
{
    return c == ' ' || c == '\n' || c == '\t' || c == '\r' || c == '\f'
        || c == '\v';
}


// What may follow a number: a blank or the end of a vector or list.
inline bool endsValue(char c)
{
    return isSpace(c) || c == ')' || c == '}';
}


inline char* formatScalar(char* p, double v, int precision)
{
    // The longest %g form: sign, precision digits, point, "e-308".
    return std::to_chars(p, p + precision + 12, v,
                         std::chars_format::general, precision).ptr;
}


// Formats n values in chunks (in parallel when OpenMP is on) and writes
// them in order; format(p, value) writes one value and returns the end.
template<class T, class Format>
void writeAsciiValues(particleFiles::outputFile& out, const T* data, label n,
                      std::size_t maxChars, const Format& format)
{
    constexpr label chunk = 1 << 15;
    constexpr label batch = 32;
    const label nChunks = (n + chunk - 1)/chunk;
    std::vector<std::string> buffers(batch);
    for (label c0 = 0; c0 < nChunks; c0 += batch)
    {
        const label c1 = std::min(nChunks, c0 + batch);
        #pragma omp parallel for schedule(dynamic) if (c1 - c0 > 1)
        for (label c = c0; c < c1; ++c)
        {
            std::string& buf = buffers[c - c0];
            const label i0 = c*chunk;
            const label i1 = std::min(n, i0 + chunk);
            buf.resize(std::size_t(i1 - i0)*maxChars);
            char* p = buf.data();
            for (label i = i0; i < i1; ++i)
            {
                p = format(p, data[i]);
                *p++ = '\n';
            }
            buf.resize(std::size_t(p - buf.data()));
        }
        for (label c = c0; c < c1; ++c)
        {
            out.write(buffers[c - c0]);
        }
    }
}


// A cursor over a field file held in memory.
class fieldParser
{
public:
    fieldParser(const std::string& file, const std::string& text)
    :
        file_(file),
        s_(text),
        pos_(0),
        binaryFrom_(std::string::npos)
    {}

    std::size_t pos() const { return pos_; }
    void setPos(std::size_t pos) { pos_ = pos; }
    bool atEnd() const { return pos_ >= s_.size(); }
    char peek() const { return s_[pos_]; }
    const char* data() const { return s_.data(); }
    std::size_t size() const { return s_.size(); }

    // Past here the file holds raw bytes, where lines mean nothing.
    void markBinary(std::size_t from) { binaryFrom_ = from; }

    int lineAt(std::size_t at) const
    {
        if (at >= binaryFrom_)
        {
            return 0;
        }
        at = std::min(at, s_.size());
        return 1 + int(std::count(s_.begin(), s_.begin() + at, '\n'));
    }

    [[noreturn]] void fail(const std::string& message, std::size_t at) const
    {
        if (at >= binaryFrom_)
        {
            fatalIOError(file_, 0, message + " (at byte " + std::to_string(at)
                + ")");
        }
        fatalIOError(file_, lineAt(at), message);
    }

    // What stands at 'at', quoted, for messages.
    std::string found(std::size_t at) const
    {
        if (at >= s_.size())
        {
            return "end of file";
        }
        // A word, or a whole "( ... )" on its line.
        std::size_t e = at;
        const bool group = s_[at] == '(';
        while
        (
            e < s_.size() && e - at < 40 && s_[e] != '\n'
         && (group || !isSpace(s_[e]))
        )
        {
            ++e;
            if (group && s_[e - 1] == ')')
            {
                break;
            }
        }
        if (e == at)
        {
            e = at + 1;
        }
        std::string text = s_.substr(at, e - at);
        for (char c : text)
        {
            if (static_cast<unsigned char>(c) < 32
             || static_cast<unsigned char>(c) > 126)
            {
                char hex[8];
                std::snprintf(hex, sizeof(hex), "0x%02x",
                              unsigned(static_cast<unsigned char>(s_[at])));
                return std::string("byte ") + hex;
            }
        }
        return "'" + text + "'";
    }

    void skipSpace()
    {
        while (pos_ < s_.size() && isSpace(s_[pos_]))
        {
            ++pos_;
        }
    }

    // Blanks and C/C++ comments between the entries.
    void skipSpaceAndComments()
    {
        for (;;)
        {
            skipSpace();
            if (s_.compare(pos_, 2, "//") == 0)
            {
                const std::size_t e = s_.find('\n', pos_);
                pos_ = e == std::string::npos ? s_.size() : e + 1;
            }
            else if (s_.compare(pos_, 2, "/*") == 0)
            {
                const std::size_t e = s_.find("*/", pos_ + 2);
                if (e == std::string::npos)
                {
                    fail("Unterminated /* comment", pos_);
                }
                pos_ = e + 2;
            }
            else
            {
                return;
            }
        }
    }

    // A run of characters up to a blank or one of ( ) { } ; " /
    std::string word()
    {
        const std::size_t b = pos_;
        while
        (
            pos_ < s_.size() && !isSpace(s_[pos_])
         && std::strchr("(){};\"/", s_[pos_]) == nullptr
        )
        {
            ++pos_;
        }
        return s_.substr(b, pos_ - b);
    }

    // End of the FoamFile { ... } block (one past its closing brace).
    std::size_t headerEnd()
    {
        skipSpaceAndComments();
        const std::size_t start = pos_;
        if (word() != "FoamFile")
        {
            fail("Missing FoamFile header: a field file starts with "
                "'FoamFile { format ...; class ...; object ...; }', found "
                + found(start), start);
        }
        skipSpaceAndComments();
        if (atEnd() || peek() != '{')
        {
            fail("Expected '{' after FoamFile, found " + found(pos_), pos_);
        }
        int depth = 0;
        while (pos_ < s_.size())
        {
            const char c = s_[pos_];
            if (c == '"')
            {
                ++pos_;
                while (pos_ < s_.size() && s_[pos_] != '"' && s_[pos_] != '\n')
                {
                    pos_ += s_[pos_] == '\\' ? 2 : 1;
                }
                ++pos_;
                continue;
            }
            if (c == '/' && (s_.compare(pos_, 2, "//") == 0
                          || s_.compare(pos_, 2, "/*") == 0))
            {
                skipSpaceAndComments();
                continue;
            }
            if (c == '{')
            {
                ++depth;
            }
            else if (c == '}' && --depth == 0)
            {
                return ++pos_;
            }
            ++pos_;
        }
        fail("Unterminated FoamFile header: no closing '}'", start);
    }

private:
    std::string file_;
    const std::string& s_;
    std::size_t pos_;
    std::size_t binaryFrom_;
};


// What the header says about the values.
struct fieldHeader
{
    bool binary = false;
    fieldKind kind = fieldKind::scalarField;
    int classLine = 0;
};


// Checks "LSB;label=32;scalar=64" against this build.
void checkArch(const dictionary& header, const std::string& file)
{
    if (!header.found("arch"))
    {
        // As OpenFOAM does: a binary file without arch is taken as native.
        return;
    }
    const std::string arch = header.get<std::string>("arch");
    const std::string mine = archString();
    if (arch == mine)
    {
        return;
    }
    std::string why;
    std::istringstream is(arch);
    std::string part;
    while (std::getline(is, part, ';'))
    {
        if (part == "MSB")
        {
            why += "; the file is big-endian (MSB), this build reads LSB";
        }
        else if (part.rfind("label=", 0) == 0
              && part != "label=" + std::to_string(8*sizeof(label)))
        {
            why += "; the file has " + part.substr(6) + "-bit labels, this "
                "build " + std::to_string(8*sizeof(label)) + "-bit";
        }
        else if (part.rfind("scalar=", 0) == 0
              && part != "scalar=" + std::to_string(8*sizeof(fileScalar)))
        {
            // Also in a single-precision build: its files are 64-bit too.
            why += "; the file has " + part.substr(7) + "-bit scalars, this "
                "build " + std::to_string(8*sizeof(fileScalar)) + "-bit";
        }
    }
    if (why.empty())
    {
        // Unknown words: still refuse, the raw bytes may mean anything.
        why = "; expected \"" + mine + "\"";
    }
    fatalIOError(file, header.lookupEntry("arch").line(),
        "Binary file written for another architecture: arch \"" + arch
        + "\"" + why, "arch");
}


fieldHeader readHeader(fieldParser& parser, const std::string& text,
                       const std::string& file)
{
    const std::size_t end = parser.headerEnd();
    const dictionary dict = dictionary::fromString(text.substr(0, end), file);
    const dictionary* header = dict.header();
    if (!header)
    {
        fatalIOError(file, 1, "Missing FoamFile header");
    }

    fieldHeader result;
    result.binary =
        header->getWord("format", {"ascii", "binary"}) == "binary";
    const std::string cls = header->getWord
    (
        "class", {"scalarField", "vectorField", "labelField"}
    );
    result.kind =
        cls == "scalarField" ? fieldKind::scalarField
      : cls == "vectorField" ? fieldKind::vectorField
      : fieldKind::labelField;
    result.classLine = header->lookupEntry("class").line();
    if (result.binary)
    {
        checkArch(*header, file);
    }
    return result;
}


// Why and where an ascii value failed to parse.
struct parseError
{
    const char* why = nullptr;
    const char* at = nullptr;
};


// Ascii values. Each reader parses one value at p (blanks skipped before
// it) and returns its end, or nullptr with err set.
struct asciiScalar
{
    template<class T>
    static const char* read(const char* p, const char* end, T& v,
                            parseError& err)
    {
        err.at = p;
        if (p < end && *p == '+')
        {
            ++p;
        }
        // Read as double in every build, then rounded once to T.
        double d = 0;
        const auto [q, ec] = std::from_chars(p, end, d);
        if (ec == std::errc::result_out_of_range)
        {
            err.why = "is out of the range of a double";
            return nullptr;
        }
        v = T(d);
        if (ec != std::errc() || (q < end && !endsValue(*q)))
        {
            err.why = "is not a number";
            return nullptr;
        }
        if (!std::isfinite(v))
        {
            err.why =
                "is not a finite number (NaN or inf: did the run diverge?)";
            return nullptr;
        }
        return q;
    }
};


struct asciiLabel
{
    static const char* read(const char* p, const char* end, label& v,
                            parseError& err)
    {
        err.at = p;
        if (p < end && *p == '+')
        {
            ++p;
        }
        const auto [q, ec] = std::from_chars(p, end, v);
        if (ec == std::errc::result_out_of_range)
        {
            err.why = "overflows a 32-bit label";
            return nullptr;
        }
        if (ec != std::errc() || (q < end && !endsValue(*q)))
        {
            err.why = "is not an integer";
            return nullptr;
        }
        return q;
    }
};


inline const char* skipBlanks(const char* p, const char* end)
{
    while (p < end && isSpace(*p))
    {
        ++p;
    }
    return p;
}


// "(x y z)"
struct asciiVector
{
    template<class T>
    static const char* read(const char* p, const char* end, Vec3<T>& v,
                            parseError& err)
    {
        const char* start = p;
        err.at = p;
        if (p >= end || *p != '(')
        {
            err.why = "is not a vector: expected '(x y z)'";
            return nullptr;
        }
        ++p;
        for (int d = 0; d < 3; ++d)
        {
            p = skipBlanks(p, end);
            const char* q = asciiScalar::read(p, end, v[d], err);
            if (!q)
            {
                if (p < end && *p == ')')
                {
                    err.at = start;
                    err.why =
                        "is not a vector: it has fewer than 3 components";
                }
                return nullptr;
            }
            p = q;
        }
        p = skipBlanks(p, end);
        if (p >= end || *p != ')')
        {
            err.at = start;
            err.why = "is not a vector: expected ')' after 3 components";
            return nullptr;
        }
        return p + 1;
    }
};


template<class Reader, class T>
void readAsciiValues(fieldParser& parser, T* data, label n,
                     const char* typeName)
{
    const char* const begin = parser.data();
    const char* const end = begin + parser.size();
    const char* p = begin + parser.pos();
    for (label i = 0; i < n; ++i)
    {
        p = skipBlanks(p, end);
        parseError err;
        const char* q = p < end ? Reader::read(p, end, data[i], err) : nullptr;
        if (!q)
        {
            std::size_t at = std::size_t(p - begin);
            const std::string which = "(" + std::string(typeName) + " "
                + std::to_string(i + 1) + " of " + std::to_string(n) + ")";
            if (p >= end)
            {
                parser.fail("Unexpected end of file after "
                    + std::to_string(i) + " of " + std::to_string(n)
                    + " values: the file is truncated", at);
            }
            if (*p == ')')
            {
                parser.fail("Found ')' after " + std::to_string(i)
                    + " values, expected " + std::to_string(n)
                    + ": the count N does not match the list", at);
            }
            at = std::size_t(err.at - begin);
            parser.fail(parser.found(at) + " " + err.why + " " + which, at);
        }
        p = q;
    }
    parser.setPos(std::size_t(p - begin));
}


// Ids must be non-negative and unique; returns one past the largest.
label checkIds(const std::vector<label>& ids, const std::string& file)
{
    label maxId = -1;
    for (std::size_t i = 0; i < ids.size(); ++i)
    {
        if (ids[i] < 0)
        {
            fatalIOError(file, 0, "Negative particle id "
                + std::to_string(ids[i]) + " (value " + std::to_string(i + 1)
                + " of " + std::to_string(ids.size()) + ")", "id");
        }
        maxId = std::max(maxId, ids[i]);
    }
    if (maxId == std::numeric_limits<label>::max())
    {
        fatalIOError(file, 0, "Particle id " + std::to_string(maxId)
            + " leaves no id for a new particle", "id");
    }
    // A bitmap when ids are dense (the usual case), else a sorted copy.
    if (std::size_t(maxId) < 8*ids.size() + 1024)
    {
        std::vector<char> seen(std::size_t(maxId) + 1, 0);
        for (std::size_t i = 0; i < ids.size(); ++i)
        {
            if (seen[ids[i]]++)
            {
                fatalIOError(file, 0, "Particle id " + std::to_string(ids[i])
                    + " appears twice (again at value " + std::to_string(i + 1)
                    + " of " + std::to_string(ids.size())
                    + "): ids must be unique", "id");
            }
        }
    }
    else
    {
        std::vector<label> sorted(ids);
        std::sort(sorted.begin(), sorted.end());
        const auto dup = std::adjacent_find(sorted.begin(), sorted.end());
        if (dup != sorted.end())
        {
            fatalIOError(file, 0, "Particle id " + std::to_string(*dup)
                + " appears twice: ids must be unique", "id");
        }
    }
    return maxId + 1;
}

// The word at the cursor must be expected; message says what was wanted.
void expectWord(fieldParser& parser, const std::string& expected,
                const std::string& message)
{
    parser.skipSpaceAndComments();
    const std::size_t at = parser.pos();
    if (parser.word() != expected)
    {
        parser.fail(message + ", found " + parser.found(at), at);
    }
}


// The count N of "N(" or "N{".
label readCount(fieldParser& parser)
{
    parser.skipSpaceAndComments();
    const std::size_t at = parser.pos();
    const char* b = parser.data() + at;
    const char* e = parser.data() + parser.size();
    long long count = -1;
    const auto [q, ec] = std::from_chars(b, e, count);
    if
    (
        ec == std::errc::result_out_of_range
     || (ec == std::errc() && count > std::numeric_limits<label>::max())
    )
    {
        parser.fail("The number of values " + parser.found(at)
            + " exceeds the largest label", at);
    }
    if
    (
        ec != std::errc() || count < 0
     || (q < e && !isSpace(*q) && *q != '(' && *q != '{')
    )
    {
        parser.fail("Expected the number of values N before the list, "
            "found " + parser.found(at), at);
    }
    parser.setPos(std::size_t(q - parser.data()));
    return label(count);
}


// n raw values right after "(", then ")"; into points (double) when
// points, else into the field's scalar.
void readBinaryValues(fieldParser& parser, void* dest, label n,
                      fieldKind kind, const std::string& file,
                      const bool points)
{
    const std::size_t bytes = std::size_t(n)*valueBytes(kind);
    parser.markBinary(parser.pos());
    if (bytes)
    {
        if (kind == fieldKind::labelField || points
         || std::is_same_v<scalar, fileScalar>)
        {
            std::memcpy(dest, parser.data() + parser.pos(), bytes);
        }
        else
        {
            // Single precision: the file's doubles rounded to scalar (the
            // file's bytes need not be aligned for a double).
            const char* src = parser.data() + parser.pos();
            scalar* d = static_cast<scalar*>(dest);
            const std::size_t nValues = bytes/sizeof(fileScalar);
            for (std::size_t i = 0; i < nValues; ++i)
            {
                fileScalar x;
                std::memcpy(&x, src + i*sizeof(fileScalar), sizeof(x));
                d[i] = scalar(x);
            }
        }
    }
    parser.setPos(parser.pos() + bytes);
    if (parser.atEnd() || parser.peek() != ')')
    {
        parser.fail("Expected ')' right after the " + std::to_string(n)
            + " binary values (" + std::to_string(bytes) + " bytes), found "
            + parser.found(parser.pos())
            + ": a wrong count N or a damaged file", parser.pos());
    }
    if (kind == fieldKind::labelField)
    {
        return;
    }
    const std::size_t perValue = kind == fieldKind::vectorField ? 3 : 1;
    const auto value = [&](const std::size_t i) -> double
    {
        return points ? static_cast<const double*>(dest)[i]
                      : static_cast<const scalar*>(dest)[i];
    };
    for (std::size_t i = 0; i < std::size_t(n)*perValue; ++i)
    {
        if (!std::isfinite(value(i)))
        {
            fatalIOError(file, 0, "Value " + std::to_string(i/perValue + 1)
                + " of " + std::to_string(n) + " is not a finite number (NaN "
                "or inf: did the run diverge?)");
        }
    }
}


// One value for all n values: N{value}, as OpenFOAM writes a list of
// equal values (closer '}'), or 'value uniform value;' (closer ';', what
// names the field for messages); ends before the closer.
void readUniformValue(fieldParser& parser, void* dest, label n,
                      fieldKind kind, const bool points, const char closer,
                      const std::string& what = "")
{
    parser.skipSpace();
    parseError err;
    const char* b = parser.data() + parser.pos();
    // The value ends at the closer: "0;" is the number 0.
    const char* e = std::find(b, parser.data() + parser.size(), closer);
    const char* q = nullptr;
    switch (kind)
    {
        case fieldKind::scalarField:
        {
            scalar v = 0;
            q = asciiScalar::read(b, e, v, err);
            std::fill_n(static_cast<scalar*>(dest), n, v);
            break;
        }
        case fieldKind::vectorField:
        {
            if (points)
            {
                point v{0, 0, 0};
                q = asciiVector::read(b, e, v, err);
                std::fill_n(static_cast<point*>(dest), n, v);
                break;
            }
            vec3 v{0, 0, 0};
            q = asciiVector::read(b, e, v, err);
            std::fill_n(static_cast<vec3*>(dest), n, v);
            break;
        }
        case fieldKind::labelField:
        {
            label v = 0;
            q = asciiLabel::read(b, e, v, err);
            std::fill_n(static_cast<label*>(dest), n, v);
            break;
        }
    }
    if (!q && what.empty())
    {
        const std::size_t at = std::size_t(err.at - parser.data());
        parser.fail(parser.found(at) + " " + err.why, at);
    }
    if (!q)
    {
        // The value as written, up to the ';'.
        std::string text(b, e);
        text.erase(text.find_last_not_of(" \t\r\n") + 1);
        if (text.empty())
        {
            parser.fail("Expected a " + std::string(listType(kind))
                + " after 'uniform' (" + what + "), found "
                + parser.found(parser.pos()), parser.pos());
        }
        parser.fail("The uniform value '" + text.substr(0, 40) + "' "
            + err.why + " (" + what + ")", parser.pos());
    }
    parser.setPos(std::size_t(q - parser.data()));
    parser.skipSpace();
    if (parser.atEnd() || parser.peek() != closer)
    {
        parser.fail("Expected '" + std::string(1, closer) + "' after the "
            "uniform value, found " + parser.found(parser.pos()),
            parser.pos());
    }
}


// n ascii values after "(", then ")".
void readAsciiList(fieldParser& parser, void* dest, label n, fieldKind kind,
                   const bool points)
{
    switch (kind)
    {
        case fieldKind::scalarField:
            readAsciiValues<asciiScalar>(parser, static_cast<scalar*>(dest),
                                         n, "scalar");
            break;
        case fieldKind::vectorField:
            if (points)
            {
                readAsciiValues<asciiVector>(parser,
                    static_cast<point*>(dest), n, "vector");
                break;
            }
            readAsciiValues<asciiVector>(parser, static_cast<vec3*>(dest),
                                         n, "vector");
            break;
        case fieldKind::labelField:
            readAsciiValues<asciiLabel>(parser, static_cast<label*>(dest),
                                        n, "label");
            break;
    }
    parser.skipSpace();
    if (parser.atEnd() || parser.peek() != ')')
    {
        parser.fail("Expected ')' after " + std::to_string(n)
            + " values, found " + parser.found(parser.pos())
            + (parser.atEnd() ? ": the file is truncated"
             : ": the list has more values than N"), parser.pos());
    }
}


// After the value: ';' and nothing but comments.
void readEntryEnd(fieldParser& parser)
{
    parser.skipSpaceAndComments();
    if (parser.atEnd() || parser.peek() != ';')
    {
        parser.fail("Expected ';' after the list, found "
            + parser.found(parser.pos()), parser.pos());
    }
    parser.setPos(parser.pos() + 1);
    parser.skipSpaceAndComments();
    if (!parser.atEnd())
    {
        parser.fail("Unexpected " + parser.found(parser.pos())
            + " after the value entry: a field file holds one entry, value",
            parser.pos());
    }
}


// The storage of field name of body, added when missing.
void* fieldData(particleBody& body, const std::string& name, fieldKind kind)
{
    switch (kind)
    {
        case fieldKind::scalarField:
            return body.addScalarField(name).data();
        case fieldKind::vectorField:
            if (particleBody::isPointField(name))
            {
                return body.position().data();
            }
            return body.addVectorField(name).data();
        case fieldKind::labelField:
            return body.addLabelField(name).data();
    }
    return nullptr;
}


// value uniform v; gives every particle of the body the value v. The
// number of particles is the body's, from its listed position field (read
// first by readTimeDirectory).
void readUniformField(fieldParser& parser, particleBody& body,
                      const std::string& fieldName, fieldKind kind,
                      const std::size_t at)
{
    if (body.size() == 0)
    {
        parser.fail("'value uniform' gives one value to every particle, but"
            " body '" + body.name() + "' has none yet: its number of"
            " particles comes from the list of its 'position' field, read"
            " first", at);
    }
    const bool points =
        kind == fieldKind::vectorField && particleBody::isPointField(fieldName);
    const std::string what = "field '" + fieldName + "', the header says"
        " class " + className(kind);
    readUniformValue(parser, fieldData(body, fieldName, kind), body.size(),
                     kind, points, ';', what);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Writing  * * * * * * * * * * * * * * * //

void writeField(const std::filesystem::path& file, const particleBody& body,
                const std::string& fieldName, writeFormat format,
                int precision, const std::string& location)
{
    const fieldKind kind = body.kindOf(fieldName);
    const bool points = particleBody::isPointField(fieldName);
    const label n = body.size();
    std::size_t size = 0;
    const void* raw = nullptr;
    switch (kind)
    {
        case fieldKind::scalarField:
            size = body.scalarField(fieldName).size();
            raw = body.scalarField(fieldName).data();
            break;
        case fieldKind::vectorField:
            size = points ? body.position().size()
                          : body.vectorField(fieldName).size();
            raw = points ? static_cast<const void*>(body.position().data())
                         : body.vectorField(fieldName).data();
            break;
        case fieldKind::labelField:
            size = body.labelField(fieldName).size();
            raw = body.labelField(fieldName).data();
            break;
    }
    // The vectors are public: one may have been resized on its own.
    if (size != std::size_t(n))
    {
        fatalError("Field '" + fieldName + "' of body '" + body.name()
            + "' has " + std::to_string(size) + " values but the body has "
            + std::to_string(n) + " particles");
    }
    if (format == writeFormat::ascii && (precision < 1 || precision > 30))
    {
        fatalError("writePrecision " + std::to_string(precision)
            + " is out of range: expected 1 to 30");
    }

    foamFileHeader header;
    header.format = format == writeFormat::binary ? "binary" : "ascii";
    header.className = className(kind);
    header.location = location;
    header.object = fieldName;
    std::ostringstream os;
    writeFoamFileHeader(os, header);
    os << "value           nonuniform List<" << listType(kind) << "> ";

    particleFiles::outputFile out(file);
    if (format == writeFormat::binary)
    {
        os << n << '(';
        out.write(os.str());
        if (kind == fieldKind::labelField || points
         || std::is_same_v<scalar, fileScalar>)
        {
            out.write(static_cast<const char*>(raw),
                      std::size_t(n)*valueBytes(kind));
        }
        else
        {
            // Single precision: widened to the file's 64-bit scalars, in
            // chunks to bound the extra memory.
            const scalar* v = static_cast<const scalar*>(raw);
            const std::size_t nValues =
                std::size_t(n)*(kind == fieldKind::vectorField ? 3 : 1);
            constexpr std::size_t chunk = 1 << 16;
            std::vector<fileScalar> wide(std::min(nValues, chunk));
            for (std::size_t i0 = 0; i0 < nValues; i0 += chunk)
            {
                const std::size_t m = std::min(chunk, nValues - i0);
                for (std::size_t i = 0; i < m; ++i)
                {
                    wide[i] = fileScalar(v[i0 + i]);
                }
                out.write(reinterpret_cast<const char*>(wide.data()),
                          m*sizeof(fileScalar));
            }
        }
        out.write(");");
    }
    else
    {
        os << '\n' << n << "\n(\n";
        out.write(os.str());
        const std::size_t scalarChars = std::size_t(precision) + 12;
        switch (kind)
        {
            case fieldKind::scalarField:
                writeAsciiValues(out, static_cast<const scalar*>(raw), n,
                    scalarChars + 1,
                    [precision](char* p, scalar v)
                    {
                        return formatScalar(p, v, precision);
                    });
                break;
            case fieldKind::vectorField:
            {
                const auto formatVector = [precision](char* p, const auto& v)
                {
                    *p++ = '(';
                    p = formatScalar(p, v.x, precision);
                    *p++ = ' ';
                    p = formatScalar(p, v.y, precision);
                    *p++ = ' ';
                    p = formatScalar(p, v.z, precision);
                    *p++ = ')';
                    return p;
                };
                if (points)
                {
                    writeAsciiValues(out, static_cast<const point*>(raw), n,
                                     3*scalarChars + 4, formatVector);
                    break;
                }
                writeAsciiValues(out, static_cast<const vec3*>(raw), n,
                                 3*scalarChars + 4, formatVector);
                break;
            }
            case fieldKind::labelField:
                writeAsciiValues(out, static_cast<const label*>(raw), n, 13,
                    [](char* p, label v)
                    {
                        return std::to_chars(p, p + 12, v).ptr;
                    });
                break;
        }
        out.write(")\n;");
    }
    std::ostringstream end;
    writeFoamFileEnd(end);
    out.write(end.str());
    out.close();
}


// * * * * * * * * * * * * * * * * Reading  * * * * * * * * * * * * * * * //

void readField(const std::filesystem::path& file, particleBody& body)
{
    const std::string fileName = file.string();
    const std::string fieldName = file.filename().string();
    const std::string text = particleFiles::readFile(file);
    fieldParser parser(fileName, text);
    const fieldHeader header = readHeader(parser, text, fileName);
    const fieldKind kind = header.kind;

    if (body.hasField(fieldName) && body.kindOf(fieldName) != kind)
    {
        fatalIOError(fileName, header.classLine, "Field '" + fieldName
            + "' of body '" + body.name() + "' is a "
            + className(body.kindOf(fieldName)) + ", the file holds a "
            + className(kind), "class");
    }

    // value uniform v; or value nonuniform List<type> N( or N{
    expectWord(parser, "value",
        "Expected the entry 'value' after the FoamFile header");
    parser.skipSpaceAndComments();
    const std::size_t formAt = parser.pos();
    const std::string form = parser.word();
    if (form == "uniform")
    {
        readUniformField(parser, body, fieldName, kind, formAt);
        readEntryEnd(parser);
        if (fieldName == "id")
        {
            body.setNextId(checkIds(body.labelField("id"), fileName));
        }
        return;
    }
    if (form != "nonuniform")
    {
        parser.fail("Expected 'uniform' or 'nonuniform' after 'value', found "
            + parser.found(formAt), formAt);
    }
    const std::string listName = "List<" + std::string(listType(kind)) + ">";
    expectWord(parser, listName, "Expected '" + listName
        + "' (the header says class " + className(kind) + ")");
    parser.skipSpaceAndComments();
    const std::size_t countAt = parser.pos();
    const label n = readCount(parser);
    parser.skipSpace();
    const std::size_t open = parser.pos();
    const bool uniform = !parser.atEnd() && parser.peek() == '{';
    if
    (
        parser.atEnd() || (parser.peek() != '(' && !uniform)
     || (uniform && header.binary)
    )
    {
        parser.fail("Expected '(' after the number of values, found "
            + parser.found(open), open);
    }
    parser.setPos(open + 1);

    // N against what the file can hold (before allocating), then against
    // the body's other fields.
    const std::size_t left = parser.size() - parser.pos();
    const std::size_t need = header.binary
        ? std::size_t(n)*valueBytes(kind) + 1
        : (uniform ? 2 : std::size_t(n)*minAsciiChars(kind) + 1);
    if (need > left)
    {
        parser.fail(std::string(header.binary ? "Truncated binary data: "
            : "Truncated data: ") + std::to_string(n) + " " + listType(kind)
            + " values need at least " + std::to_string(need)
            + " more bytes, the file has " + std::to_string(left)
            + " (a wrong count N or a truncated file)", countAt);
    }
    if (uniform && body.size() == 0 && n > 0)
    {
        // Nothing bounds its N (one value stands for all): a body's size
        // comes from a list of its values, position's when reading a time.
        parser.fail("A uniform list " + std::to_string(n) + "{...} cannot"
            " set the number of particles: write the values of '"
            + fieldName + "' as a list, or read a listed field first",
            countAt);
    }
    if (body.size() != 0 && body.size() != n)
    {
        parser.fail("Field '" + fieldName + "' has " + std::to_string(n)
            + " values but body '" + body.name() + "' has "
            + std::to_string(body.size())
            + " particles: all fields of a body must have the same size",
            countAt);
    }
    if (body.size() == 0)
    {
        body.resize(n);
    }

    void* dest = fieldData(body, fieldName, kind);
    const bool points =
        kind == fieldKind::vectorField && particleBody::isPointField(fieldName);
    if (header.binary)
    {
        readBinaryValues(parser, dest, n, kind, fileName, points);
    }
    else if (uniform)
    {
        readUniformValue(parser, dest, n, kind, points, '}');
    }
    else
    {
        readAsciiList(parser, dest, n, kind, points);
    }
    parser.setPos(parser.pos() + 1);   // the closing bracket
    readEntryEnd(parser);

    if (fieldName == "id")
    {
        body.setNextId(checkIds(body.labelField("id"), fileName));
    }
}

} // End namespace sphvcpm
