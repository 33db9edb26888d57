/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// ASCII and binary STL parsing, gzip through zlib.

#include "stlReader.H"
#include "error.H"

#include <zlib.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace sphvcpm
{

namespace
{

constexpr std::size_t binaryHeaderSize = 84;     // 80 bytes + uint32 count
constexpr std::size_t binaryTriangleSize = 50;   // 12 floats + uint16

bool equalsNoCase(const char* a, std::size_t n, const char* word)
{
    const std::size_t m = std::strlen(word);
    if (n != m)
    {
        return false;
    }
    for (std::size_t i = 0; i < n; ++i)
    {
        if (std::tolower(static_cast<unsigned char>(a[i])) != word[i])
        {
            return false;
        }
    }
    return true;
}

// Whitespace-separated tokens of an ASCII STL with their line numbers.
class asciiTokens
{
public:
    asciiTokens(const char* data, std::size_t size, const std::string& file)
    :
        data_(data),
        size_(size),
        file_(file)
    {}

    // Moves to the next token; false at the end of the data.
    bool next()
    {
        while (pos_ < size_ && std::isspace(uc(data_[pos_])))
        {
            line_ += data_[pos_] == '\n';
            ++pos_;
        }
        start_ = pos_;
        while (pos_ < size_ && !std::isspace(uc(data_[pos_])))
        {
            ++pos_;
        }
        return pos_ > start_;
    }

    bool is(const char* word) const
    {
        return equalsNoCase(data_ + start_, pos_ - start_, word);
    }

    std::string text() const
    {
        // Long or binary garbage is cut so that messages stay readable.
        std::string t(data_ + start_, std::min<std::size_t>(pos_ - start_, 40));
        for (char& c : t)
        {
            if (!std::isprint(uc(c)))
            {
                c = '?';
            }
        }
        return t;
    }

    // The rest of the current line (a solid's name), trimmed.
    std::string restOfLine()
    {
        const std::size_t from = pos_;
        while (pos_ < size_ && data_[pos_] != '\n')
        {
            ++pos_;
        }
        std::string s(data_ + from, pos_ - from);
        const auto notSpace = [](char c) { return !std::isspace(uc(c)); };
        s.erase(s.begin(), std::find_if(s.begin(), s.end(), notSpace));
        s.erase(std::find_if(s.rbegin(), s.rend(), notSpace).base(), s.end());
        return s;
    }

    int line() const { return line_; }

    [[noreturn]] void fail(const std::string& message) const
    {
        fatalIOError(file_, line_, "ASCII STL: " + message);
    }

    // The next token, which must be word.
    void expect(const char* word, const char* context)
    {
        if (!next())
        {
            fail(std::string("the file ends where '") + word + "' is expected"
                " (" + context + "): it is truncated");
        }
        if (!is(word))
        {
            fail(std::string("expected '") + word + "' (" + context
                + "), found '" + text() + "'" + endNote());
        }
    }

    // The next token as a finite number.
    scalar number(const char* what)
    {
        if (!next())
        {
            fail(std::string("the file ends where a ") + what + " is"
                " expected: it is truncated");
        }
        const std::string t(data_ + start_, pos_ - start_);
        char* end = nullptr;
        const scalar v = std::strtod(t.c_str(), &end);
        if (end == t.c_str() || *end != '\0')
        {
            fail(std::string("expected a number (") + what + "), found '"
                + text() + "'" + endNote());
        }
        if (!std::isfinite(v))
        {
            fail(std::string("the ") + what + " '" + text() + "' is not a"
                " finite number");
        }
        return v;
    }

private:
    // A token cut by the end of the file is a truncation, not a typo.
    std::string endNote() const
    {
        return pos_ == size_ ? " at the end of the file: it is truncated" : "";
    }

    static unsigned char uc(char c) { return static_cast<unsigned char>(c); }

    const char* data_;
    std::size_t size_;
    const std::string& file_;
    std::size_t pos_ = 0;
    std::size_t start_ = 0;
    int line_ = 1;
};


void parseAscii(const char* data, std::size_t size, const std::string& file,
                stlData& stl)
{
    asciiTokens tok(data, size, file);
    while (tok.next())
    {
        if (!tok.is("solid"))
        {
            tok.fail("expected 'solid' (the start of a solid), found '"
                + tok.text() + "'");
        }
        const int solidLine = tok.line();
        stl.solids.push_back(tok.restOfLine());

        while (true)
        {
            if (!tok.next())
            {
                std::ostringstream os;
                os << "the file ends inside solid '" << stl.solids.back()
                   << "' (opened at line " << solidLine << ") without"
                   << " 'endsolid': it is truncated";
                tok.fail(os.str());
            }
            if (tok.is("endsolid"))
            {
                (void)tok.restOfLine();     // the repeated name, if any
                break;
            }
            if (!tok.is("facet"))
            {
                tok.fail("expected 'facet' or 'endsolid', found '"
                    + tok.text() + "'");
            }
            // The normal is ignored (often absent or wrong in exports), but
            // its three numbers must be there.
            tok.expect("normal", "after 'facet'");
            for (int i = 0; i < 3; ++i)
            {
                if (!tok.next())
                {
                    tok.fail("the file ends inside a facet normal: it is"
                        " truncated");
                }
            }
            tok.expect("outer", "after the facet normal");
            tok.expect("loop", "after 'outer'");
            for (int v = 0; v < 3; ++v)
            {
                tok.expect("vertex", "a triangle has three vertices");
                vec3 p;
                for (int d = 0; d < 3; ++d)
                {
                    p[d] = tok.number("vertex coordinate");
                }
                stl.vertices.push_back(p);
            }
            tok.expect("endloop", "a facet has exactly three vertices");
            tok.expect("endfacet", "after 'endloop'");
        }
    }
}


void parseBinary(const char* data, std::size_t size, const std::string& file,
                 stlData& stl)
{
    std::uint32_t n = 0;
    std::memcpy(&n, data + 80, sizeof(n));      // little endian, as x86
    stl.binary = true;
    stl.vertices.resize(std::size_t(n)*3);
    for (std::size_t t = 0; t < n; ++t)
    {
        const char* rec = data + binaryHeaderSize + t*binaryTriangleSize;
        float f[12];
        std::memcpy(f, rec, sizeof(f));
        for (int v = 0; v < 3; ++v)
        {
            const vec3 p{f[3 + 3*v], f[4 + 3*v], f[5 + 3*v]};
            if (!std::isfinite(p.x) || !std::isfinite(p.y)
             || !std::isfinite(p.z))
            {
                std::ostringstream os;
                os << "Binary STL: triangle " << t << " (of " << n << ") has"
                   << " a non-finite vertex coordinate (" << p.x << ' '
                   << p.y << ' ' << p.z << ")";
                fatalIOError(file, 0, os.str());
            }
            stl.vertices[3*t + v] = p;
        }
    }
    (void)size;
}


// Printable text (and whitespace) only: an ASCII file, not binary floats.
bool looksLikeText(const char* data, std::size_t size)
{
    for (std::size_t i = 0; i < size; ++i)
    {
        const unsigned char c = static_cast<unsigned char>(data[i]);
        if (c < 9 || (c > 13 && c < 32) || c > 126)
        {
            return false;
        }
    }
    return true;
}

} // End anonymous namespace


stlData parseSTL(const char* data, std::size_t size,
                 const std::string& fileName)
{
    stlData stl;

    std::size_t first = 0;
    while
    (
        first < size && std::isspace(static_cast<unsigned char>(data[first]))
    )
    {
        ++first;
    }
    if (first == size)
    {
        fatalIOError(fileName, 0, "The STL file is empty");
    }

    const bool startsWithSolid = size - first >= 5
        && equalsNoCase(data + first, 5, "solid");

    // Binary files may also start with "solid" (several exporters write it
    // in the header), so the byte count decides first.
    bool sizeMatchesBinary = false;
    std::uint32_t nBinary = 0;
    if (size >= binaryHeaderSize)
    {
        std::memcpy(&nBinary, data + 80, sizeof(nBinary));
        sizeMatchesBinary =
            size == binaryHeaderSize + std::size_t(nBinary)*binaryTriangleSize;
    }

    const std::size_t probe = std::min<std::size_t>(size, 4096);
    if
    (
        startsWithSolid
     && (!sizeMatchesBinary || looksLikeText(data, probe))
    )
    {
        parseAscii(data, size, fileName, stl);
    }
    else if (size < binaryHeaderSize)
    {
        std::ostringstream os;
        os << "The file is neither ASCII STL (it does not start with"
           << " 'solid') nor binary STL (it has " << size << " bytes, fewer"
           << " than the 84-byte header): it is truncated or not an STL file";
        fatalIOError(fileName, 0, os.str());
    }
    else if (!sizeMatchesBinary)
    {
        std::ostringstream os;
        os << "Binary STL: the header counts " << nBinary << " triangles,"
           << " which take 84 + 50 x " << nBinary << " = "
           << binaryHeaderSize + std::size_t(nBinary)*binaryTriangleSize
           << " bytes, but the file has " << size << " bytes: it is"
           << " truncated or not an STL file";
        fatalIOError(fileName, 0, os.str());
    }
    else
    {
        parseBinary(data, size, fileName, stl);
    }

    if (stl.vertices.empty())
    {
        fatalIOError(fileName, 0, std::string("The ")
            + (stl.binary ? "binary" : "ASCII") + " STL file holds no"
              " triangles");
    }
    return stl;
}


stlData readSTL(const std::filesystem::path& file)
{
    const std::string name = file.string();
    const std::string problem = fileProblem(name);
    if (!problem.empty())
    {
        fatalIOError(name, 0, "The STL file " + name + " " + problem);
    }

    gzFile in = gzopen(name.c_str(), "rb");
    if (!in)
    {
        fatalIOError(name, 0, "Cannot open the STL file " + name);
    }
    std::string bytes;
    char buffer[1 << 16];
    int n = 0;
    while ((n = gzread(in, buffer, sizeof(buffer))) > 0)
    {
        bytes.append(buffer, std::size_t(n));
    }
    int code = Z_OK;
    const char* message = gzerror(in, &code);
    const bool compressed = gzdirect(in) == 0;
    const std::string zlibMessage = message ? message : "";
    gzclose(in);
    if (n < 0 || (code != Z_OK && code != Z_STREAM_END))
    {
        fatalIOError(name, 0, "Cannot decompress the gzip STL file: "
            + zlibMessage + " (truncated or corrupt)");
    }

    stlData stl = parseSTL(bytes.data(), bytes.size(), name);
    stl.compressed = compressed;
    return stl;
}

} // End namespace sphvcpm
