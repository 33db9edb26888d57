/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// dimensionSet, and the reading of what is written between [ and ]:
// exponents ([0 2 -1 0 0 0 0], 5 or 7 of them) or named units
// ([kg/m^3], [m^2/s], [N*m], [kg m^-3], [1/s]).

#include "dimensionSet.H"
#include "dictionaryParser.H"
#include "formatting.H"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace sphvcpm
{

bool dimensionSet::operator==(const dimensionSet& other) const
{
    for (std::size_t i = 0; i < exponents.size(); ++i)
    {
        // Exponents may be fractions (m^0.5): compare with a tolerance.
        if (std::abs(exponents[i] - other.exponents[i]) > 1e-10)
        {
            return false;
        }
    }
    return true;
}


std::string dimensionSet::str() const
{
    std::ostringstream os;
    os << '[';
    for (std::size_t i = 0; i < exponents.size(); ++i)
    {
        const double e = exponents[i];
        os << (i ? " " : "");
        if (e == std::round(e))
        {
            os << static_cast<long long>(std::round(e));
        }
        else
        {
            os << e;
        }
    }
    os << ']';
    return os.str();
}


namespace
{

struct namedUnit
{
    const char* name;
    dimensionSet dims;
};

// SI base and derived units without a scale factor, then the named sets
// OpenFOAM-dev accepts ([velocity]).
const std::vector<namedUnit>& namedUnits()
{
    static const std::vector<namedUnit> units =
    {
        {"kg", {1, 0, 0}},
        {"m", {0, 1, 0}},
        {"s", {0, 0, 1}},
        {"K", {0, 0, 0, 1}},
        {"mol", {0, 0, 0, 0, 1}},
        {"A", {0, 0, 0, 0, 0, 1}},
        {"cd", {0, 0, 0, 0, 0, 0, 1}},
        {"N", {1, 1, -2}},
        {"Pa", {1, -1, -2}},
        {"J", {1, 2, -2}},
        {"W", {1, 2, -3}},
        {"Hz", {0, 0, -1}},
        {"dimless", {0, 0, 0}},
        {"dimensionless", {0, 0, 0}},
        {"length", dimensions::length()},
        {"time", dimensions::time()},
        {"mass", dimensions::mass()},
        {"density", dimensions::density()},
        {"velocity", dimensions::velocity()},
        {"acceleration", dimensions::acceleration()},
        {"pressure", dimensions::pressure()},
        {"kinematicViscosity", dimensions::kinematicViscosity()},
        {"force", dimensions::force()}
    };
    return units;
}


dimensionSet operator+(const dimensionSet& a, const dimensionSet& b)
{
    dimensionSet c;
    for (std::size_t i = 0; i < c.exponents.size(); ++i)
    {
        c.exponents[i] = a.exponents[i] + b.exponents[i];
    }
    return c;
}


dimensionSet operator*(const dimensionSet& a, double p)
{
    dimensionSet c;
    for (std::size_t i = 0; i < c.exponents.size(); ++i)
    {
        c.exponents[i] = a.exponents[i]*p;
    }
    return c;
}


// Signals a bad unit expression; caught in parseDimensions.
struct unitError
{
    std::string message;
};


// Recursive descent over the text between the brackets:
//   product := power { ('*' | '/' | nothing) power }
//   power   := primary [ '^' number | '^' '(' number ')' ]
//   primary := unit | 1 | '(' product ')'
class unitParser
{
public:
    struct piece
    {
        enum class kind { number, name, op, end } type;
        std::string text;
        double value = 0;
    };

    explicit unitParser(const std::string& text)
    {
        std::size_t i = 0;
        while (i < text.size())
        {
            const char c = text[i];
            const bool sign = (c == '-' || c == '+') && i + 1 < text.size()
                && (std::isdigit(static_cast<unsigned char>(text[i + 1]))
                 || text[i + 1] == '.');
            if (std::isspace(static_cast<unsigned char>(c)))
            {
                ++i;
            }
            else if
            (
                std::isdigit(static_cast<unsigned char>(c)) || c == '.'
             || sign
            )
            {
                const char* start = text.c_str() + i;
                char* end = nullptr;
                const double v = std::strtod(start, &end);
                if (end == start)
                {
                    throw unitError{"bad number '" + std::string(1, c) + "'"};
                }
                const std::size_t n = std::size_t(end - start);
                pieces_.push_back
                (
                    {piece::kind::number, std::string(start, n), v}
                );
                i += n;
            }
            else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_')
            {
                std::string name;
                while
                (
                    i < text.size()
                 && (std::isalnum(static_cast<unsigned char>(text[i]))
                  || text[i] == '_')
                )
                {
                    name += text[i++];
                }
                pieces_.push_back({piece::kind::name, name});
            }
            else if (c == '*' || c == '/' || c == '^' || c == '(' || c == ')')
            {
                pieces_.push_back({piece::kind::op, std::string(1, c)});
                ++i;
            }
            else
            {
                throw unitError
                {
                    "unexpected character '" + std::string(1, c) + "'"
                };
            }
        }
        pieces_.push_back({piece::kind::end, ""});
    }

    const std::vector<piece>& pieces() const { return pieces_; }

    dimensionSet parse()
    {
        const dimensionSet d = product();
        if (current().type != piece::kind::end)
        {
            throw unitError{"unexpected '" + current().text + "'"};
        }
        return d;
    }

private:
    std::vector<piece> pieces_;
    std::size_t i_ = 0;
    int depth_ = 0;

    const piece& current() const { return pieces_[i_]; }

    bool isOp(const char* op) const
    {
        return current().type == piece::kind::op && current().text == op;
    }

    dimensionSet product()
    {
        dimensionSet d = power();
        while (true)
        {
            if (isOp("*"))
            {
                ++i_;
                d = d + power();
            }
            else if (isOp("/"))
            {
                ++i_;
                d = d + power()*-1.0;
            }
            else if
            (
                current().type == piece::kind::name
             || current().type == piece::kind::number || isOp("(")
            )
            {
                d = d + power();   // kg m^-3: a space multiplies
            }
            else
            {
                return d;
            }
        }
    }

    dimensionSet power()
    {
        const dimensionSet base = primary();
        if (!isOp("^"))
        {
            return base;
        }
        ++i_;
        const bool bracketed = isOp("(");
        if (bracketed)
        {
            ++i_;
        }
        if (current().type != piece::kind::number)
        {
            throw unitError
            {
                "expected a number after '^', found "
              + (current().type == piece::kind::end
                 ? std::string("the end") : "'" + current().text + "'")
            };
        }
        const double p = current().value;
        ++i_;
        if (bracketed)
        {
            if (!isOp(")"))
            {
                throw unitError{"expected ')' after the exponent"};
            }
            ++i_;
        }
        return base*p;
    }

    dimensionSet primary()
    {
        const piece& p = current();
        if (p.type == piece::kind::name)
        {
            for (const auto& u : namedUnits())
            {
                if (p.text == u.name)
                {
                    ++i_;
                    return u.dims;
                }
            }
            std::vector<std::string> known;
            for (const auto& u : namedUnits())
            {
                known.push_back(u.name);
            }
            // MPa, mm, kN: a prefix on a known unit. Values are SI.
            const std::string prefixes = "GMkhdcmun";
            const char* factors[] = {"1e9", "1e6", "1e3", "100", "0.1",
                                     "0.01", "0.001", "1e-6", "1e-9"};
            const std::size_t prefix = p.text.size() > 1
                ? prefixes.find(p.text[0]) : std::string::npos;
            const std::string unprefixed =
                prefix != std::string::npos ? p.text.substr(1) : "";
            const bool prefixed = std::any_of(known.begin(), known.end(),
                [&](const std::string& k) { return k == unprefixed; });
            const std::string guess =
                dictionaryDetail::closest(p.text, known);
            throw unitError
            {
                "unknown unit '" + p.text + "'"
              + (prefixed
                 ? " (units take no prefix: values are in SI units, so "
                   "write the value in " + unprefixed + ": 1 " + p.text
                   + " is [" + unprefixed + "] " + factors[prefix] + ")"
                 : guess.empty() ? "" : " (did you mean '" + guess + "'?)")
              + "; known units are " + str(known)
            };
        }
        if (p.type == piece::kind::number)
        {
            if (p.value != 1)
            {
                throw unitError
                {
                    "unexpected number " + p.text + " among named units "
                    "(only 1 may stand alone, as in 1/s)"
                };
            }
            ++i_;
            return dimensionSet();
        }
        if (isOp("("))
        {
            ++i_;
            if (++depth_ > 32)
            {
                throw unitError{"brackets nested too deep"};
            }
            const dimensionSet d = product();
            --depth_;
            if (!isOp(")"))
            {
                throw unitError{"expected ')' in unit expression"};
            }
            ++i_;
            return d;
        }
        throw unitError
        {
            "expected a unit name, found "
          + (p.type == piece::kind::end
             ? std::string("the end") : "'" + p.text + "'")
        };
    }
};

} // End anonymous namespace


bool dictionaryDetail::parseDimensions(const std::string& text,
                                       dimensionSet& dims,
                                       std::string& message)
{
    try
    {
        unitParser parser(text);
        const auto& pieces = parser.pieces();

        // Only numbers: the exponents themselves.
        bool allNumbers = true;
        std::size_t n = 0;
        for (const auto& p : pieces)
        {
            if (p.type == unitParser::piece::kind::number)
            {
                ++n;
            }
            else if (p.type != unitParser::piece::kind::end)
            {
                allNumbers = false;
            }
        }
        if (n == 0 && pieces.size() == 1)
        {
            dims = dimensionSet();
            return true;
        }
        if (allNumbers && !(n == 1 && pieces[0].value == 1))
        {
            if (n != 5 && n != 7)
            {
                message = "expected 5 or 7 dimension exponents, found "
                    + std::to_string(n);
                return false;
            }
            dims = dimensionSet();
            for (std::size_t i = 0; i < n; ++i)
            {
                dims.exponents[i] = pieces[i].value;
            }
            return true;
        }
        dims = parser.parse();
        return true;
    }
    catch (const unitError& err)
    {
        message = err.message;
        return false;
    }
}

} // End namespace sphvcpm
