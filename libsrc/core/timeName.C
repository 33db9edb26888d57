/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Time names as OpenFOAM's Time::timeName prints them: an ostream with the
// floatfield set to timeFormat and setprecision(timePrecision).

#include "timeName.H"
#include "error.H"

#include <charconv>
#include <cmath>
#include <ios>
#include <sstream>

namespace sphvcpm
{

timeFormat timeFormatFromName(const std::string& name)
{
    if (name == "general")
    {
        return timeFormat::general;
    }
    if (name == "fixed")
    {
        return timeFormat::fixed;
    }
    if (name == "scientific")
    {
        return timeFormat::scientific;
    }
    fatalError("Unknown timeFormat '" + name
        + "'\nValid timeFormats are: general fixed scientific");
}


std::string timeName(double t, timeFormat format, int precision)
{
    if (!std::isfinite(t))
    {
        fatalError("Cannot name a time directory after a non-finite time ("
            + std::to_string(t) + ")");
    }
    // OpenFOAM accepts any precision; beyond 30 digits it is only noise.
    if (precision < 0 || precision > 30)
    {
        fatalError("timePrecision " + std::to_string(precision)
            + " is out of range: expected 0 to 30");
    }
    // -0 would name a directory "-0" next to "0".
    if (t == 0)
    {
        t = 0;
    }

    std::ostringstream os;
    if (format == timeFormat::fixed)
    {
        os.setf(std::ios_base::fixed, std::ios_base::floatfield);
    }
    else if (format == timeFormat::scientific)
    {
        os.setf(std::ios_base::scientific, std::ios_base::floatfield);
    }
    os.precision(precision);
    os << t;
    return os.str();
}


bool parseTimeName(const std::string& name, double& t)
{
    // Plain decimal or exponent notation only: from_chars refuses a
    // leading '+', blanks and hex floats, and the whole name must be read.
    // A leading '.' is a hidden directory (".5" is never a time name).
    const char* first = name.data();
    const char* last = first + name.size();
    if (first == last || *first == '.')
    {
        return false;
    }
    double value = 0;
    const auto [ptr, ec] = std::from_chars(first, last, value);
    if (ec != std::errc() || ptr != last || !std::isfinite(value))
    {
        return false;
    }
    t = value;
    return true;
}

} // End namespace sphvcpm
