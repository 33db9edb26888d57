/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Typed values of dictionary entries: get<T>, set<T>, parseTokens<T> and
// dimensioned values [name] [dims] value [units] (docs/dictionaries.md).

#include "dictionary.H"
#include "dictionaryParser.H"
#include "error.H"
#include "formatting.H"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

namespace sphvcpm
{

namespace
{

using dictionaryDetail::clip;
using dictionaryDetail::describe;

// Reads tokens left to right; every error names the keyword, the line of
// the offending token and what was expected.
class valueReader
{
public:
    valueReader(const std::vector<token>& tokens, const std::string& keyword,
                const std::string& file, int line,
                int fewestVectorComponents = 2)
    :
        t_(tokens),
        keyword_(keyword),
        file_(file),
        line_(line),
        fewestVectorComponents_(std::size_t(fewestVectorComponents))
    {}

    bool atEnd() const { return i_ >= t_.size(); }
    const token& peek(std::size_t ahead = 0) const { return t_[i_ + ahead]; }
    bool has(std::size_t ahead) const { return i_ + ahead < t_.size(); }
    std::size_t position() const { return i_; }
    const token& next() { return t_[i_++]; }

    int lineAt(std::size_t i) const
    {
        const int l = i < t_.size() ? t_[i].line : 0;
        return l > 0 ? l : line_;
    }

    [[noreturn]] void failAt(std::size_t i, const std::string& message) const
    {
        fatalIOError(file_, lineAt(i), "Keyword '" + clip(keyword_) + "': "
            + message, keyword_);
    }

    // "expected X, found <the current token>"
    [[noreturn]] void expected(const std::string& what) const
    {
        std::string found;
        if (!atEnd())
        {
            found = describe(peek());
        }
        else if (t_.empty())
        {
            found = "no value (an empty entry)";
        }
        else
        {
            found = "the end of the value";
        }
        failAt(i_, "expected " + what + ", found " + found);
    }

    void expectEnd() const
    {
        if (!atEnd())
        {
            failAt(i_, "unexpected " + describe(peek()) + " after the "
                "value: expected ';' to end the entry");
        }
    }

    void expectPunctuation(char c, const std::string& context)
    {
        if (atEnd() || !peek().isPunctuation(c))
        {
            expected("'" + std::string(1, c) + "'" + context);
        }
        ++i_;
    }

    // Numbers are read as double in every build (dictionary numbers such
    // as times must not lose digits); callers round them to scalar.
    double readScalar(const std::string& what = "a number")
    {
        if (atEnd() || !peek().isNumber())
        {
            expected(what);
        }
        return next().floatValue;
    }

    std::int64_t readInteger(std::int64_t lo, std::int64_t hi,
                             const std::string& typeName)
    {
        if (atEnd() || !peek().isNumber())
        {
            expected("an integer (" + typeName + ")");
        }
        const token& t = peek();
        if (t.type == token::kind::floating)
        {
            const bool digits = t.text.find_first_not_of("-0123456789")
                == std::string::npos && !t.text.empty();
            if (digits)
            {
                failAt(i_, "integer " + clip(t.text) + " is out of range for "
                    + typeName + " (" + std::to_string(lo) + " to "
                    + std::to_string(hi) + ")");
            }
            expected("an integer (" + typeName + ")");
        }
        if (t.integerValue < lo || t.integerValue > hi)
        {
            failAt(i_, "integer " + clip(t.str()) + " is out of range for "
                + typeName + " (" + std::to_string(lo) + " to "
                + std::to_string(hi) + ")");
        }
        return next().integerValue;
    }

    bool readSwitch()
    {
        static const std::vector<std::pair<std::string, bool>> names =
        {
            {"true", true}, {"false", false}, {"on", true}, {"off", false},
            {"yes", true}, {"no", false}, {"y", true}, {"n", false},
            {"t", true}, {"f", false}, {"any", true}, {"none", false}
        };
        const std::string what = "a switch (true/false, on/off, yes/no, "
            "y/n, t/f, any/none, 1/0)";
        // OpenFOAM reads the integers 1 and 0 as switches (openTop 1;).
        if
        (
            !atEnd() && peek().type == token::kind::integer
         && (peek().integerValue == 0 || peek().integerValue == 1)
        )
        {
            return next().integerValue == 1;
        }
        if (atEnd() || peek().type != token::kind::word)
        {
            expected(what);
        }
        for (const auto& [name, value] : names)
        {
            if (peek().text == name)
            {
                ++i_;
                return value;
            }
        }
        expected(what);
    }

    std::string readString()
    {
        if
        (
            atEnd()
         || (peek().type != token::kind::word
          && peek().type != token::kind::string)
        )
        {
            expected("a word or a quoted string");
        }
        return next().text;
    }

    vec3 readVector()
    {
        const std::size_t open = i_;
        expectPunctuation('(', " to start a vector (x y z)");
        std::vector<double> c;
        while (!atEnd() && !peek().isPunctuation(')'))
        {
            c.push_back(readScalar("a number (vector component)"));
        }
        if (atEnd())
        {
            expected("')' to close the vector opened at line "
                + std::to_string(lineAt(open)));
        }
        if (c.size() < fewestVectorComponents_ || c.size() > 3)
        {
            failAt(open, std::string(fewestVectorComponents_ == 3
                  ? "expected a vector of 3 components (x y z) in a 3D case"
                  : "expected a vector of 2 or 3 components")
                + ", found " + std::to_string(c.size()) + " components");
        }
        ++i_;
        return {scalar(c[0]), scalar(c[1]), scalar(c.size() == 3 ? c[2] : 0)};
    }

    // (a b c), N(a b c) or N{a}; element reads one element.
    template<class T, class Element>
    std::vector<T> readList(Element element, const std::string& what)
    {
        std::vector<T> list;
        if (!atEnd() && peek().type == token::kind::integer && has(1)
         && (peek(1).isPunctuation('(') || peek(1).isPunctuation('{')))
        {
            const std::size_t sizeAt = i_;
            const std::int64_t n = next().integerValue;
            if (n < 0)
            {
                failAt(sizeAt, "negative list size " + std::to_string(n));
            }
            if (peek().isPunctuation('{'))
            {
                ++i_;
                const T v = element();
                expectPunctuation('}', " to close the uniform list "
                    + std::to_string(n) + "{...}");
                return std::vector<T>(std::size_t(n), v);
            }
            list = readBracketed<T>(element, what);
            if (std::int64_t(list.size()) != n)
            {
                failAt(sizeAt, "list size " + std::to_string(n)
                    + " given but " + std::to_string(list.size())
                    + " elements found");
            }
            return list;
        }
        if (atEnd() || !peek().isPunctuation('('))
        {
            expected(what + " ( ... )");
        }
        return readBracketed<T>(element, what);
    }

    // [ ... ]: 5 or 7 exponents or named units.
    dimensionSet readDimensions()
    {
        const std::size_t open = i_;
        expectPunctuation('[', "");
        std::string text;
        bool prevOperand = false;
        auto append = [&](const std::string& piece, bool operand)
        {
            if (operand && prevOperand)
            {
                text += ' ';
            }
            text += piece;
            prevOperand = operand;
        };
        while (true)
        {
            if (atEnd())
            {
                failAt(open, "expected ']' to close the dimensions '[' "
                    "opened at line " + std::to_string(lineAt(open))
                    + ", found the end of the value");
            }
            const token& t = next();
            if (t.isPunctuation(']'))
            {
                break;
            }
            if (t.isPunctuation('['))
            {
                failAt(i_ - 1, "unexpected '[' inside dimensions opened at "
                    "line " + std::to_string(lineAt(open)));
            }
            if (t.type == token::kind::word)
            {
                // The lexer glues ']' to a word (s] in [m^2/s]).
                const auto close = t.text.find(']');
                if (close == std::string::npos)
                {
                    append(t.text, true);
                    continue;
                }
                if (close + 1 != t.text.size())
                {
                    failAt(i_ - 1, "unexpected '"
                        + clip(t.text.substr(close + 1))
                        + "' after ']' in dimensions");
                }
                append(t.text.substr(0, close), true);
                break;
            }
            if (t.isNumber())
            {
                append(t.text.empty() ? t.str() : t.text, true);
            }
            else if (t.type == token::kind::punctuation)
            {
                append(t.text, false);
            }
            else
            {
                failAt(i_ - 1, "unexpected " + describe(t) + " in dimensions");
            }
        }
        dimensionSet dims;
        std::string message;
        if (!dictionaryDetail::parseDimensions(text, dims, message))
        {
            failAt(open, message + " in dimensions [" + clip(text) + "]");
        }
        return dims;
    }

    // [name] [dims] value [units]. A name is only taken when dimensions
    // are written, so a stray word is still reported as such.
    template<class T, class Value>
    T readDimensioned(Value value, dimensionSet& dims, bool& hasDims)
    {
        hasDims = false;
        std::size_t nameAt = std::string::npos;
        if
        (
            !atEnd() && peek().type == token::kind::word && has(1)
         && (peek(1).isPunctuation('[') || peek(1).isNumber()
          || peek(1).isPunctuation('('))
        )
        {
            nameAt = i_++;
        }
        if (!atEnd() && peek().isPunctuation('['))
        {
            dims = readDimensions();
            hasDims = true;
        }
        T v = value();
        if (!atEnd() && peek().isPunctuation('['))
        {
            if (hasDims)
            {
                failAt(i_, "dimensions are given both before and after the "
                    "value");
            }
            dims = readDimensions();
            hasDims = true;
        }
        if (nameAt != std::string::npos && !hasDims)
        {
            // Only a dimensioned value carries a name: report the word
            // where the value was expected.
            i_ = nameAt;
            value();
            failAt(nameAt, "unexpected " + describe(t_[nameAt]));
        }
        return v;
    }

private:
    const std::vector<token>& t_;
    const std::string& keyword_;
    const std::string& file_;
    int line_;
    std::size_t fewestVectorComponents_;
    std::size_t i_ = 0;

    template<class T, class Element>
    std::vector<T> readBracketed(Element element, const std::string& what)
    {
        const std::size_t open = i_;
        ++i_;   // (
        std::vector<T> list;
        while (!atEnd() && !peek().isPunctuation(')'))
        {
            list.push_back(element());
        }
        if (atEnd())
        {
            failAt(open, "expected ')' to close " + what + " opened at line "
                + std::to_string(lineAt(open)) + ", found the end of the "
                "value");
        }
        ++i_;
        return list;
    }
};


// What get<T> reads, one overload per supported T.
bool readValue(valueReader& r, bool*) { return r.readSwitch(); }

label readValue(valueReader& r, label*)
{
    return label(r.readInteger(std::numeric_limits<label>::min(),
        std::numeric_limits<label>::max(), "a 32-bit label"));
}

std::int64_t readValue(valueReader& r, std::int64_t*)
{
    return r.readInteger(std::numeric_limits<std::int64_t>::min(),
        std::numeric_limits<std::int64_t>::max(), "a 64-bit integer");
}

double readValue(valueReader& r, double*)
{
    dimensionSet dims;
    bool hasDims;
    return r.readDimensioned<double>([&]{ return r.readScalar(); }, dims,
                                     hasDims);
}

#ifdef SPHVCPM_SINGLE
// Single precision: read as double, rounded once to scalar.
float readValue(valueReader& r, float*)
{
    return float(readValue(r, static_cast<double*>(nullptr)));
}
#endif

std::string readValue(valueReader& r, std::string*) { return r.readString(); }

vec3 readValue(valueReader& r, vec3*)
{
    dimensionSet dims;
    bool hasDims;
    return r.readDimensioned<vec3>([&]{ return r.readVector(); }, dims,
                                   hasDims);
}

std::vector<double> readValue(valueReader& r, std::vector<double>*)
{
    return r.readList<double>([&]{ return r.readScalar(); },
                              "a list of numbers");
}

#ifdef SPHVCPM_SINGLE
std::vector<float> readValue(valueReader& r, std::vector<float>*)
{
    return r.readList<float>([&]{ return float(r.readScalar()); },
                             "a list of numbers");
}
#endif

std::vector<label> readValue(valueReader& r, std::vector<label>*)
{
    return r.readList<label>
    (
        [&]{ return readValue(r, static_cast<label*>(nullptr)); },
        "a list of integers"
    );
}

std::vector<std::string> readValue(valueReader& r, std::vector<std::string>*)
{
    return r.readList<std::string>([&]{ return r.readString(); },
                                   "a list of words");
}

std::vector<vec3> readValue(valueReader& r, std::vector<vec3>*)
{
    return r.readList<vec3>([&]
    {
        // (0.3 0.05 0) for one point: say how a list of one is written.
        if (!r.atEnd() && (r.peek().type == token::kind::integer
                        || r.peek().type == token::kind::floating))
        {
            r.expected("'(' to start a vector of the list (a list of"
                " points is ((x y z) ...), and one point ((x y z)))");
        }
        return r.readVector();
    }, "a list of vectors");
}


// What set<T> writes.
using dictionaryDetail::integerToken;
using dictionaryDetail::numberToken;
using dictionaryDetail::punctuationToken;

void appendTokens(std::vector<token>& out, bool v)
{
    out.push_back(dictionaryDetail::wordToken(v ? "true" : "false"));
}

void appendTokens(std::vector<token>& out, label v)
{
    out.push_back(integerToken(v));
}

void appendTokens(std::vector<token>& out, std::int64_t v)
{
    out.push_back(integerToken(v));
}

void appendTokens(std::vector<token>& out, double v)
{
    if (!std::isfinite(v))
    {
        fatalError("Cannot write the non-finite value "
            + dictionaryDetail::formatScalar(v) + " to a dictionary");
    }
    out.push_back(numberToken(v));
}

#ifdef SPHVCPM_SINGLE
// A float is written in its shortest decimal form (0.01f as 0.01, not
// 0.009999999776), so that a double build reads back the intended number.
void appendTokens(std::vector<token>& out, float v)
{
    char buf[32];
    const auto end = std::to_chars(buf, buf + sizeof(buf), v).ptr;
    double d = 0;
    std::from_chars(buf, end, d);
    appendTokens(out, std::isfinite(v) ? d : double(v));
}
#endif

void appendTokens(std::vector<token>& out, const std::string& v)
{
    out.push_back
    (
        isValidWord(v)
      ? dictionaryDetail::wordToken(v)
      : dictionaryDetail::stringToken(v)
    );
}

void appendTokens(std::vector<token>& out, const vec3& v)
{
    out.push_back(punctuationToken('('));
    appendTokens(out, v.x);
    appendTokens(out, v.y);
    appendTokens(out, v.z);
    out.push_back(punctuationToken(')'));
}

template<class T>
void appendTokens(std::vector<token>& out, const std::vector<T>& list)
{
    out.push_back(punctuationToken('('));
    for (const T& v : list)
    {
        appendTokens(out, v);
    }
    out.push_back(punctuationToken(')'));
}

template<class T>
std::vector<token> toTokens(const T& value)
{
    std::vector<token> out;
    appendTokens(out, value);
    return out;
}


const entry& valueEntry(const dictionary& dict, const std::string& key,
                        const std::string& what)
{
    const entry& e = dict.lookupEntry(key);
    if (e.isDict())
    {
        fatalIOError(e.file(), e.line(), "Keyword '" + clip(key)
            + "': expected " + what + ", found a sub-dictionary", key);
    }
    return e;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member functions  * * * * * * * * * * * * //

template<class T>
T parseTokens(const std::vector<token>& tokens, const std::string& keyword,
              const std::string& file, int line,
              const int fewestVectorComponents)
{
    valueReader r(tokens, keyword, file, line, fewestVectorComponents);
    T v = readValue(r, static_cast<T*>(nullptr));
    r.expectEnd();
    return v;
}


template<class T>
T dictionary::get(const std::string& key) const
{
    const entry& e = valueEntry(*this, key, "a value");
    return parseTokens<T>(e.tokens(), key, e.file(), e.line(),
                          topDict().fewestVectorComponents_);
}


template<class T>
T dictionary::getOrDefault(const std::string& key, const T& deflt) const
{
    return found(key) ? get<T>(key) : deflt;
}


template<class T>
T dictionary::getDimensioned(const std::string& key,
                             const dimensionSet& dims) const
{
    const entry& e = valueEntry(*this, key, "a dimensioned value");
    valueReader r(e.tokens(), key, e.file(), e.line(),
                  topDict().fewestVectorComponents_);
    dimensionSet found;
    bool hasDims = false;
    T v;
    if constexpr (std::is_same_v<T, vec3>)
    {
        v = r.readDimensioned<vec3>([&]{ return r.readVector(); }, found,
                                    hasDims);
    }
    else
    {
        v = T(r.readDimensioned<double>([&]{ return r.readScalar(); }, found,
                                        hasDims));
    }
    r.expectEnd();
    if (hasDims && found != dims)
    {
        fatalIOError(e.file(), e.line(), "Keyword '"
            + dictionaryDetail::clip(key) + "': dimensions "
            "do not match: expected " + dims.str() + ", found "
            + found.str(), key);
    }
    return v;
}


void dictionary::checkDimensionsEntry(const std::string& key,
                                      const dimensionSet& dims) const
{
    const entry& e = valueEntry(*this, key, "dimensions [...]");
    valueReader r(e.tokens(), key, e.file(), e.line(),
                  topDict().fewestVectorComponents_);
    const dimensionSet found = r.readDimensions();
    r.expectEnd();
    if (found != dims)
    {
        fatalIOError(e.file(), e.line(), "Keyword '"
            + dictionaryDetail::clip(key) + "': dimensions do not match:"
            " expected " + dims.str() + ", found " + found.str(), key);
    }
}


std::string dictionary::getWord(const std::string& key,
                                const std::vector<std::string>& allowed) const
{
    const std::string w = get<std::string>(key);
    if (std::find(allowed.begin(), allowed.end(), w) == allowed.end())
    {
        const std::string guess = dictionaryDetail::closest(w, allowed);
        fatalAt(key, "Keyword '" + dictionaryDetail::clip(key)
            + "': unknown value '" + dictionaryDetail::clip(w) + "'."
            + (guess.empty() ? "" : " Did you mean '" + guess + "'?")
            + " Valid values are: " + str(allowed));
    }
    return w;
}


std::string dictionary::getWordOrDefault
(
    const std::string& key,
    const std::vector<std::string>& allowed,
    const std::string& deflt
) const
{
    return found(key) ? getWord(key, allowed) : deflt;
}


double dictionary::getPositive(const std::string& key) const
{
    const double v = get<double>(key);
    if (!(v > 0))
    {
        fatalAt(key, "Keyword '" + dictionaryDetail::clip(key)
            + "': expected a positive number, "
            "found " + dictionaryDetail::formatScalar(v));
    }
    return v;
}


template<class T>
void dictionary::set(const std::string& key, const T& value)
{
    setTokens(key, toTokens(value));
}


void dictionary::set(const std::string& key, const char* value)
{
    setTokens(key, toTokens(std::string(value ? value : "")));
}


template<>
void dictionary::set<const char*>(const std::string& key,
                                  const char* const& value)
{
    set(key, value);
}


// * * * * * * * * * * * * * Explicit instantiations * * * * * * * * * * * //

#define SPHVCPM_DICTIONARY_TYPE(T)                                            \
    template T parseTokens<T>(const std::vector<token>&, const std::string&, \
                              const std::string&, int, int);                 \
    template T dictionary::get<T>(const std::string&) const;                 \
    template T dictionary::getOrDefault<T>(const std::string&, const T&)     \
        const;                                                               \
    template void dictionary::set<T>(const std::string&, const T&);

SPHVCPM_DICTIONARY_TYPE(bool)
SPHVCPM_DICTIONARY_TYPE(label)
SPHVCPM_DICTIONARY_TYPE(std::int64_t)
SPHVCPM_DICTIONARY_TYPE(double)
SPHVCPM_DICTIONARY_TYPE(std::string)
SPHVCPM_DICTIONARY_TYPE(vec3)
SPHVCPM_DICTIONARY_TYPE(std::vector<double>)
#ifdef SPHVCPM_SINGLE
SPHVCPM_DICTIONARY_TYPE(float)
SPHVCPM_DICTIONARY_TYPE(std::vector<float>)
#endif
SPHVCPM_DICTIONARY_TYPE(std::vector<label>)
SPHVCPM_DICTIONARY_TYPE(std::vector<std::string>)
SPHVCPM_DICTIONARY_TYPE(std::vector<vec3>)

#undef SPHVCPM_DICTIONARY_TYPE

template double dictionary::getDimensioned<double>(const std::string&,
    const dimensionSet&) const;
#ifdef SPHVCPM_SINGLE
template float dictionary::getDimensioned<float>(const std::string&,
    const dimensionSet&) const;
#endif
template vec3 dictionary::getDimensioned<vec3>(const std::string&,
    const dimensionSet&) const;

} // End namespace sphvcpm
