/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "timeFunction.H"
#include "waveTheory.H"

#include "dictionary.H"
#include "error.H"
#include "formatting.H"
#include "gravity.H"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace sphvcpm
{

namespace fs = std::filesystem;

namespace
{

constexpr scalar pi = 3.14159265358979323846;

std::string trim(const std::string& s)
{
    const auto first = s.find_first_not_of(" \t\r\n");
    if (first == std::string::npos) return "";
    const auto last = s.find_last_not_of(" \t\r\n");
    return s.substr(first, last - first + 1);
}

// A CSV header may quote its names: "t_s" reads as t_s.
std::string unquote(const std::string& s)
{
    if (s.size() >= 2 && s.front() == '"' && s.back() == '"')
    {
        return s.substr(1, s.size() - 2);
    }
    return s;
}

// Cells of a line: semicolon-separated when it has a semicolon (the CSV of
// DualSPHysics and of spreadsheets set to a decimal comma), else
// comma-separated when it has a comma, else separated by whitespace.
std::vector<std::string> splitCells(const std::string& line)
{
    std::vector<std::string> cells;
    const char separator = line.find(';') != std::string::npos ? ';'
        : line.find(',') != std::string::npos ? ',' : ' ';
    if (separator != ' ')
    {
        std::istringstream is(line);
        std::string cell;
        while (std::getline(is, cell, separator))
        {
            cells.push_back(unquote(trim(cell)));
        }
        // "a;b;" ends with an empty cell that getline does not return.
        if (line.back() == separator) cells.push_back("");
    }
    else
    {
        std::istringstream is(line);
        std::string cell;
        while (is >> cell) cells.push_back(unquote(cell));
    }
    return cells;
}

// The whole cell as a finite number (strtod alone would accept "1.5abc",
// "nan" and "inf"); "1,5" is 1.5.
bool parseNumber(std::string cell, scalar& v)
{
    if (cell.empty()) return false;
    // A comma in a cell (rows split at semicolons) is a decimal comma.
    std::replace(cell.begin(), cell.end(), ',', '.');
    char* end = nullptr;
    v = std::strtod(cell.c_str(), &end);
    return end == cell.c_str() + cell.size() && std::isfinite(v);
}

std::string numberText(const scalar v)
{
    std::ostringstream os;
    os.precision(12);
    os << v;
    return os.str();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

timeFunction::timeFunction(const scalar value)
:
    type_(kind::constant),
    constant_(value)
{}


timeFunction timeFunction::read
(
    const dictionary& dict,
    const fs::path& caseDir,
    const bool isAngle
)
{
    timeFunction f;
    const std::string type = dict.getWord("type",
        {"constant", "sinusoid", "pistonWave", "flapWave", "table"});
    const bool wavemaker = type == "pistonWave" || type == "flapWave";
    if (wavemaker && isAngle != (type == "flapWave"))
    {
        dict.fatalAt("type", "Dictionary \"" + dict.name() + "\": type "
            + type + " is " + (isAngle
            ? "the offset of a translation (a piston wavemaker), not an"
              " angle; a flap is type flapWave"
            : "the angle of a rotation (a flap hinged on the floor), not an"
              " offset; a piston is type pistonWave"));
    }

    std::vector<std::string> valid{"type"};
    if (type == "constant")
    {
        valid.insert(valid.end(), {"value"});
    }
    else if (type == "sinusoid" || wavemaker)
    {
        valid.insert(valid.end(), {"period", "frequency", "phase",
                                   "startTime", "rampTime"});
        if (type == "sinusoid")
        {
            valid.push_back("amplitude");
        }
        else
        {
            valid.insert(valid.end(), {"waveHeight", "depth"});
        }
    }
    else
    {
        valid.insert(valid.end(), {"file", "timeColumn", "valueColumn",
                                   "select"});
    }

    // Degrees against radians is the classic silent error: an angle must
    // say which, and nothing else may. A flapWave's angle is derived, in
    // radians.
    const bool takesUnits = isAngle && !wavemaker;
    if (takesUnits)
    {
        valid.push_back("units");
    }
    else if (dict.found("units"))
    {
        dict.fatalAt("units", "Keyword 'units' in dictionary \""
            + dict.name() + "\": only an angle given as a number takes"
              " units (degrees or radians); this quantity is in SI units"
              " (metres for an offset; a flapWave's angle is derived)");
    }
    dict.checkKeywords(valid);

    scalar scale = 1;
    if (takesUnits)
    {
        if (!dict.found("units"))
        {
            dict.fatal("Dictionary \"" + dict.name() + "\" is an angle:"
                " say units degrees; or units radians;", "units");
        }
        const std::string units =
            dict.getWord("units", {"degrees", "radians"});
        scale = units == "degrees" ? pi/180 : 1;
    }

    // Dimensions, where written, are checked: an offset is a length, an
    // angle a number in its units.
    const dimensionSet valueDims =
        isAngle ? dimensions::none() : dimensions::length();
    if (type == "constant")
    {
        f.type_ = kind::constant;
        f.constant_ = scale*dict.getDimensioned<scalar>("value", valueDims);
    }
    else if (type == "sinusoid")
    {
        f.readSinusoid(dict, scale, valueDims);
    }
    else if (wavemaker)
    {
        f.readWavemaker(dict, caseDir, type == "flapWave");
    }
    else
    {
        f.readTable(dict, caseDir, scale);
    }
    return f;
}


void timeFunction::readSinusoid(const dictionary& dict, const scalar scale,
                                const dimensionSet& valueDims,
                                const bool withAmplitude)
{
    type_ = kind::sinusoid;

    if (withAmplitude)
    {
        amplitude_ =
            scale*dict.getDimensioned<scalar>("amplitude", valueDims);
    }

    const bool hasPeriod = dict.found("period");
    const bool hasFrequency = dict.found("frequency");
    if (hasPeriod && hasFrequency)
    {
        dict.fatalAt("frequency", "Keyword 'frequency' in dictionary \""
            + dict.name() + "\": give period or frequency, not both");
    }
    if (!hasPeriod && !hasFrequency)
    {
        dict.fatal("Dictionary \"" + dict.name() + "\": a sinusoid needs"
            " period (s) or frequency (Hz)", "period");
    }
    const std::string key = hasPeriod ? "period" : "frequency";
    const scalar given = dict.getDimensioned<scalar>(key, hasPeriod
        ? dimensions::time() : dimensionSet(0, 0, -1));
    if (!(given > 0))
    {
        dict.fatalAt(key, "Keyword '" + key + "' in dictionary \""
            + dict.name() + "\": must be positive, found "
            + numberText(given));
    }
    omega_ = hasPeriod ? 2*pi/given : 2*pi*given;

    phase_ = dict.found("phase")
      ? dict.getDimensioned<scalar>("phase", dimensions::none()) : 0;
    if (std::abs(phase_) > 2*pi)
    {
        // Most often degrees meant (units applies to the amplitude only).
        const entry& e = *dict.findEntry("phase");
        warning("Keyword 'phase' in dictionary \"" + dict.name() + "\": "
            + numberText(phase_) + " is in radians, more than a turn; for "
            + numberText(phase_) + " degrees write "
            + numberText(phase_*pi/180), e.file(), e.line());
    }
    startTime_ = dict.found("startTime")
      ? dict.getDimensioned<scalar>("startTime", dimensions::time()) : 0;
    rampTime_ = dict.found("rampTime")
      ? dict.getDimensioned<scalar>("rampTime", dimensions::time()) : 0;
    if (!(rampTime_ >= 0))
    {
        dict.fatalAt("rampTime", "Keyword 'rampTime' in dictionary \""
            + dict.name() + "\": the ramp duration must be >= 0 (0: no"
              " ramp), found " + numberText(rampTime_));
    }
}


void timeFunction::readWavemaker(const dictionary& dict,
                                 const fs::path& caseDir, const bool flap)
{
    readSinusoid(dict, 1, dimensions::length(), false);
    const scalar height =
        dict.getDimensioned<scalar>("waveHeight", dimensions::length());
    const scalar depth =
        dict.getDimensioned<scalar>("depth", dimensions::length());
    wavemakerDepth_ = depth;
    for (const auto& [key, v] : {std::pair<const char*, scalar>{"waveHeight",
        height}, {"depth", depth}})
    {
        if (!(v > 0))
        {
            dict.fatalAt(key, "Keyword '" + std::string(key) + "' in"
                " dictionary \"" + dict.name() + "\": must be positive,"
                " found " + numberText(v));
        }
    }
    // |g| as the solver reads it (the solver checks its plane).
    const scalar g = mag(readGravity(caseDir, 0));
    if (!(g > 0))
    {
        dict.fatalAt("type", "Dictionary \"" + dict.name() + "\": a"
            " wavemaker needs gravity, and constant/g gives none");
    }
    // Numbers no wave has (w^2 d/g overflowing or underflowing, a stroke
    // beyond the largest number) are errors, never a NaN or infinite
    // paddle.
    const std::string periodKey = dict.found("period") ? "period"
                                                        : "frequency";
    const scalar k = waveNumber(omega_, depth, g);
    if (!(k*depth > 0 && std::isfinite(k*depth)))
    {
        dict.fatalAt(periodKey, "Keyword '" + periodKey + "' in dictionary"
            " \"" + dict.name() + "\": linear theory gives no wave of period "
            + numberText(2*pi/omega_) + " s in " + numberText(depth)
            + " m of water (|g| " + numberText(g) + "): kd = "
            + numberText(k*depth) + " is not a positive finite number");
    }
    const scalar heightOverStroke = flap ? flapHeightOverStroke(k*depth)
                                         : pistonHeightOverStroke(k*depth);
    const scalar stroke = height/heightOverStroke;
    if (!(std::isfinite(stroke) && stroke > 0))
    {
        dict.fatalAt("waveHeight", "Keyword 'waveHeight' in dictionary \""
            + dict.name() + "\": " + numberText(height) + " m needs a stroke"
              " of " + numberText(height) + "/" + numberText(heightOverStroke)
            + " m (H/S at kd = " + numberText(k*depth) + "), not a finite"
              " number");
    }
    // A flap's stroke is its travel at the still-water level, a depth
    // above its hinge.
    amplitude_ = flap ? std::atan(stroke/(2*depth)) : stroke/2;
    const scalar wavelength = 2*pi/k;

    std::ostringstream os;
    os << (flap ? "flapWave" : "pistonWave") << " of height " << height
       << " m, period " << 2*pi/omega_ << " s in depth " << depth
       << " m (|g| " << g << "): k = " << k << " 1/m, wavelength "
       << wavelength << " m, kd = " << k*depth << ", H/S = "
       << heightOverStroke << ", stroke " << stroke << " m";
    if (flap)
    {
        os << " at the still-water level (angle amplitude "
           << amplitude_*180/pi << " degrees)";
    }
    os << ", Ursell number H L^2/d^3 = "
       << height*wavelength*wavelength/(depth*depth*depth);
    note_ = os.str();

    const scalar breaking = micheBreakingHeight(k, depth);
    if (height > breaking)
    {
        const entry& e = dict.lookupEntry("waveHeight");
        warning("Keyword 'waveHeight' in dictionary \"" + dict.name()
            + "\": " + numberText(height) + " m is above the breaking"
              " height " + numberText(breaking) + " m of a wave of period "
            + numberText(2*pi/omega_) + " s in " + numberText(depth)
            + " m of water (Miche: H/L = 0.142 tanh kd); the waves will"
              " break, and linear theory does not give their height",
            e.file(), e.line());
    }
    // Independent of the breaking check: a wave can be both too high and
    // need too long a stroke, and each warning asks for another change.
    if (stroke > 0.5*depth)
    {
        // Linear wavemaker theory takes the paddle's motion as small
        // against the depth (a long shallow-water wave needs a long
        // stroke): past half the depth its height is not what it gives.
        const entry& e = dict.lookupEntry("waveHeight");
        warning("Keyword 'waveHeight' in dictionary \"" + dict.name()
            + "\": " + numberText(height) + " m needs a stroke of "
            + numberText(stroke) + " m" + (flap ? " at the still-water"
              " level (" + numberText(amplitude_*180/pi) + " degrees each"
              " way)" : "") + ", more than half the depth "
            + numberText(depth) + " m: linear wavemaker theory assumes a"
              " small paddle motion, so the waves' height will differ"
              " from the one asked for; and check the paddle has room",
            e.file(), e.line());
    }
}


void timeFunction::readTable
(
    const dictionary& dict,
    const fs::path& caseDir,
    const scalar scale
)
{
    type_ = kind::table;

    const fs::path given = dict.get<std::string>("file");
    const fs::path file = given.is_absolute() ? given : caseDir/given;
    const std::string fileName = file.string();
    if (!fs::is_regular_file(file))
    {
        dict.fatalAt("file", "Keyword 'file' in dictionary \"" + dict.name()
            + "\": table " + fileName + " does not exist (a relative path"
              " is taken from the case directory)");
    }
    std::ifstream in(file);
    if (!in)
    {
        dict.fatalAt("file", "Keyword 'file': cannot read " + fileName);
    }

    // Columns by name (a CSV with a header), by number from 0 (a table
    // without one, as OpenFOAM's csvFile: timeColumn 0; valueColumn 2; for
    // a "t x y z" motion file), or the first two of each row.
    const auto isIndex = [&](const std::string& key)
    {
        const entry* e = dict.findEntry(key);
        return e && !e->isDict() && e->tokens().size() == 1
            && e->tokens()[0].type == token::kind::integer;
    };
    const bool byIndex = isIndex("timeColumn") || isIndex("valueColumn");
    const bool named = !byIndex && (dict.found("timeColumn")
        || dict.found("valueColumn") || dict.found("select"));
    std::size_t timeCol = 0;
    std::size_t valueCol = 1;
    std::string timeName = "time";
    std::string valueName = "value";
    if (byIndex)
    {
        if (dict.found("select"))
        {
            dict.fatalAt("select", "Keyword 'select' in dictionary \""
                + dict.name() + "\": it picks rows by the header's column"
                  " names; give timeColumn and valueColumn as names too");
        }
        for (const char* key : {"timeColumn", "valueColumn"})
        {
            const label c = dict.get<label>(key);   // both, as numbers
            if (c < 0)
            {
                dict.fatalAt(key, "Keyword '" + std::string(key) + "' in"
                    " dictionary \"" + dict.name() + "\": a column number"
                    " counts from 0, found " + std::to_string(c));
            }
            (std::string(key) == "timeColumn" ? timeCol : valueCol) =
                std::size_t(c);
        }
        timeName = "column " + std::to_string(timeCol);
        valueName = "column " + std::to_string(valueCol);
    }
    std::vector<std::string> header;
    // (column, wanted text) pairs of select
    std::vector<std::pair<std::size_t, std::string>> filter;

    auto columnOf = [&](const dictionary& d, const std::string& key,
                        const std::string& name, const int headerLine)
    {
        const auto it = std::find(header.begin(), header.end(), name);
        if (it == header.end())
        {
            d.fatalAt(key, "Keyword '" + key + "' in dictionary \""
                + d.name() + "\": no column '" + name + "' in the header of "
                + fileName + " (line " + std::to_string(headerLine)
                + "); its columns are " + str(header));
        }
        return std::size_t(it - header.begin());
    };

    std::string line;
    int lineNo = 0;
    int headerLine = 0;
    scalar lastTime = 0;
    int lastLine = 0;
    while (std::getline(in, line))
    {
        ++lineNo;
        const std::string text = trim(line);
        if (text.empty() || text[0] == '#') continue;
        const std::vector<std::string> cells = splitCells(text);

        if (named && header.empty())
        {
            header = cells;
            headerLine = lineNo;
            timeName = dict.get<std::string>("timeColumn");
            valueName = dict.get<std::string>("valueColumn");
            timeCol = columnOf(dict, "timeColumn", timeName, headerLine);
            valueCol = columnOf(dict, "valueColumn", valueName, headerLine);
            if (const dictionary* sel = dict.findDict("select"))
            {
                if (sel->keys().empty())
                {
                    // Every row kept: a shared file's cases run into each
                    // other (times going back), named far from the cause.
                    dict.fatalAt("select", "Keyword 'select' in dictionary"
                        " \"" + dict.name() + "\" is empty: give the"
                          " columns and texts of the rows to keep,"
                          " select { column text; }, or leave it out");
                }
                for (const std::string& key : sel->keys())
                {
                    const std::vector<token>& toks =
                        sel->lookupEntry(key).tokens();
                    if (toks.size() != 1)
                    {
                        sel->fatalAt(key, "Keyword '" + key + "' in"
                            " dictionary \"" + sel->name() + "\": expected"
                            " one value (the text of the cell to keep)");
                    }
                    filter.emplace_back
                    (
                        columnOf(*sel, key, key, headerLine),
                        toks[0].text
                    );
                }
            }
            else if (dict.found("select"))
            {
                dict.fatalAt("select", "Keyword 'select' in dictionary \""
                    + dict.name() + "\": expected a sub-dictionary"
                      " { column value; ... }");
            }
            continue;
        }

        if (named)
        {
            if (cells.size() != header.size())
            {
                fatalIOError(fileName, lineNo, "Row of " + fileName + " has "
                    + std::to_string(cells.size()) + " cells; the header"
                      " (line " + std::to_string(headerLine) + ") has "
                    + std::to_string(header.size()), "file");
            }
            const bool keep = std::all_of(filter.begin(), filter.end(),
                [&](const auto& f) { return cells[f.first] == f.second; });
            if (!keep) continue;
        }
        else if (byIndex)
        {
            if (cells.size() <= std::max(timeCol, valueCol))
            {
                fatalIOError(fileName, lineNo, "Table " + fileName + ": row"
                    " of " + std::to_string(cells.size()) + " cells "
                    + str(cells) + " has no column "
                    + std::to_string(std::max(timeCol, valueCol))
                    + " (columns count from 0)", "file");
            }
        }
        else if (cells.size() != 2)
        {
            fatalIOError(fileName, lineNo, "Table " + fileName + ": expected"
                " two columns, time and value, found "
                + std::to_string(cells.size()) + " cells "
                + str(cells) + " (a CSV with a header names its"
                  " columns with timeColumn and valueColumn)", "file");
        }

        auto number = [&](const std::size_t col, const std::string& name)
        {
            scalar x = 0;
            if (!parseNumber(cells[col], x))
            {
                fatalIOError(fileName, lineNo, "Table " + fileName
                    + ": cell '" + cells[col] + "' of column " + name
                    + " is not a number"
                    + (named ? std::string() : " (a header row? name the"
                       " columns with timeColumn and valueColumn)"), name);
            }
            return x;
        };
        const scalar t = number(timeCol, timeName);
        const scalar v = number(valueCol, valueName);

        if (!times_.empty() && !(t > lastTime))
        {
            fatalIOError(fileName, lineNo, "Table " + fileName + ": time "
                + numberText(t) + " is not greater than the time "
                + numberText(lastTime) + " of line "
                + std::to_string(lastLine) + "; times must increase"
                  " strictly"
                + (named && filter.empty() ? std::string(". A table of"
                   " several series (one per case in a column) needs"
                   " select { <column> <text>; } to pick one") : ""),
                timeName);
        }
        times_.push_back(t);
        values_.push_back(scale*v);
        lastTime = t;
        lastLine = lineNo;
    }

    if (named && header.empty())
    {
        dict.fatalAt("file", "Keyword 'file' in dictionary \"" + dict.name()
            + "\": " + fileName + " has no header row (timeColumn and"
              " valueColumn name columns of the header)");
    }
    if (times_.empty() && !filter.empty())
    {
        dict.fatalAt("select", "Keyword 'select' in dictionary \""
            + dict.name() + "\": no row of " + fileName + " matches it");
    }
    if (times_.size() < 2)
    {
        dict.fatalAt("file", "Keyword 'file' in dictionary \"" + dict.name()
            + "\": table " + fileName + " has "
            + std::to_string(times_.size()) + " row"
            + (times_.size() == 1 ? "" : "s")
            + (filter.empty() ? "" : " matching select")
            + "; interpolation needs at least 2");
    }
    setCurvatures();
}


void timeFunction::setCurvatures()
{
    // Three-point second difference, exact for a parabola on unequal
    // intervals; the end knots take their neighbour's.
    const std::size_t n = times_.size();
    curvatures_.assign(n, 0);
    for (std::size_t i = 1; i + 1 < n; ++i)
    {
        curvatures_[i] = 2*(slope(i) - slope(i - 1))
                        /(times_[i + 1] - times_[i - 1]);
    }
    if (n > 2)
    {
        curvatures_[0] = curvatures_[1];
        curvatures_[n - 1] = curvatures_[n - 2];
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

std::size_t timeFunction::segment(const scalar t) const
{
    // The last knot <= t, kept off the final knot so that [i, i+1] exists.
    const auto it = std::upper_bound(times_.begin(), times_.end(), t);
    const std::size_t i = it == times_.begin() ? 0 : it - times_.begin() - 1;
    return std::min(i, times_.size() - 2);
}


timeFunction::rampTerms timeFunction::rampAt(const scalar tau) const
{
    // (1 - cos(pi s))/2 over s = tau/rampTime in [0, 1], then 1.
    if (!(rampTime_ > 0) || tau >= rampTime_)
    {
        return {1, 0, 0};
    }
    const scalar k = pi/rampTime_;
    return {0.5*(1 - std::cos(k*tau)), 0.5*k*std::sin(k*tau),
            0.5*k*k*std::cos(k*tau)};
}


scalar timeFunction::slope(const std::size_t i) const
{
    return (values_[i + 1] - values_[i])/(times_[i + 1] - times_[i]);
}


scalar timeFunction::value(const scalar t) const
{
    switch (type_)
    {
        case kind::constant:
            return constant_;

        case kind::sinusoid:
        {
            if (t < startTime_) return 0;
            const scalar tau = t - startTime_;
            return amplitude_*rampAt(tau).value*std::sin(omega_*tau + phase_);
        }

        case kind::table:
        {
            if (t <= times_.front()) return values_.front();
            if (t >= times_.back()) return values_.back();
            const std::size_t i = segment(t);
            return values_[i] + (t - times_[i])*slope(i);
        }
    }
    return 0;
}


scalar timeFunction::derivative(const scalar t) const
{
    switch (type_)
    {
        case kind::constant:
            return 0;

        case kind::sinusoid:
        {
            if (t < startTime_) return 0;
            const scalar tau = t - startTime_;
            const scalar arg = omega_*tau + phase_;
            const rampTerms r = rampAt(tau);
            return amplitude_
               *(r.rate*std::sin(arg) + r.value*omega_*std::cos(arg));
        }

        case kind::table:
        {
            // Held constant outside the table.
            if (t < times_.front() || t > times_.back()) return 0;
            const std::size_t i = segment(t);
            if (t == times_[i] && i > 0)
            {
                // Interior knot: three-point derivative, each slope
                // weighted by the other interval (exact for a parabola).
                const scalar h0 = times_[i] - times_[i - 1];
                const scalar h1 = times_[i + 1] - times_[i];
                return (h1*slope(i - 1) + h0*slope(i))/(h0 + h1);
            }
            // Inside a segment, or an end knot: its segment's slope.
            return slope(i);
        }
    }
    return 0;
}


scalar timeFunction::secondDerivative(const scalar t) const
{
    switch (type_)
    {
        case kind::constant:
            return 0;

        case kind::sinusoid:
        {
            if (t < startTime_) return 0;
            const scalar tau = t - startTime_;
            const scalar arg = omega_*tau + phase_;
            const rampTerms r = rampAt(tau);
            return amplitude_
               *(
                    (r.curvature - r.value*omega_*omega_)*std::sin(arg)
                  + 2*r.rate*omega_*std::cos(arg)
                );
        }

        case kind::table:
        {
            if (t < times_.front() || t > times_.back()) return 0;
            const std::size_t i = segment(t);
            const scalar w = (t - times_[i])/(times_[i + 1] - times_[i]);
            return (1 - w)*curvatures_[i] + w*curvatures_[i + 1];
        }
    }
    return 0;
}

} // End namespace sphvcpm
