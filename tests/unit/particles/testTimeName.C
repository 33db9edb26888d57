/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Time names as OpenFOAM prints them (an ostream with the floatfield of
// timeFormat and setprecision(timePrecision), the same as printf's %.*g,
// %.*f and %.*e), and parsing them back.

#include "timeName.H"
#include "testParticleTools.H"

#include <gtest/gtest.h>

#include <random>

using namespace sphvcpm;
using test::catchFatal;
using test::expectMessage;

namespace
{

// The values every row of the table below names, in order.
const std::vector<double> values =
    {0, 0.05, 1e-05, 1.5, 0.1 + 0.2, 100, 1234567, 1e-4, 2.5};

struct row
{
    timeFormat format;
    int precision;
    std::vector<std::string> names;
};

// Generated with printf("%.*g" | "%.*f" | "%.*e"), which is what a C++
// ostream (and so OpenFOAM's Time::timeName) prints.
const std::vector<row> table =
    {
        {timeFormat::general, 0,
            {"0", "0.05", "1e-05", "2", "0.3", "1e+02", "1e+06", "0.0001",
             "2"}},
        {timeFormat::general, 1,
            {"0", "0.05", "1e-05", "2", "0.3", "1e+02", "1e+06", "0.0001",
             "2"}},
        {timeFormat::general, 3,
            {"0", "0.05", "1e-05", "1.5", "0.3", "100", "1.23e+06", "0.0001",
             "2.5"}},
        {timeFormat::general, 6,
            {"0", "0.05", "1e-05", "1.5", "0.3", "100", "1.23457e+06",
             "0.0001", "2.5"}},
        {timeFormat::general, 10,
            {"0", "0.05", "1e-05", "1.5", "0.3", "100", "1234567", "0.0001",
             "2.5"}},
        {timeFormat::general, 17,
            {"0", "0.050000000000000003", "1.0000000000000001e-05", "1.5",
             "0.30000000000000004", "100", "1234567", "0.0001", "2.5"}},
        {timeFormat::fixed, 0,
            {"0", "0", "0", "2", "0", "100", "1234567", "0", "2"}},
        {timeFormat::fixed, 1,
            {"0.0", "0.1", "0.0", "1.5", "0.3", "100.0", "1234567.0", "0.0",
             "2.5"}},
        {timeFormat::fixed, 3,
            {"0.000", "0.050", "0.000", "1.500", "0.300", "100.000",
             "1234567.000", "0.000", "2.500"}},
        {timeFormat::fixed, 6,
            {"0.000000", "0.050000", "0.000010", "1.500000", "0.300000",
             "100.000000", "1234567.000000", "0.000100", "2.500000"}},
        {timeFormat::fixed, 10,
            {"0.0000000000", "0.0500000000", "0.0000100000", "1.5000000000",
             "0.3000000000", "100.0000000000", "1234567.0000000000",
             "0.0001000000", "2.5000000000"}},
        {timeFormat::fixed, 17,
            {"0.00000000000000000", "0.05000000000000000",
             "0.00001000000000000", "1.50000000000000000",
             "0.30000000000000004", "100.00000000000000000",
             "1234567.00000000000000000", "0.00010000000000000",
             "2.50000000000000000"}},
        {timeFormat::scientific, 0,
            {"0e+00", "5e-02", "1e-05", "2e+00", "3e-01", "1e+02", "1e+06",
             "1e-04", "2e+00"}},
        {timeFormat::scientific, 1,
            {"0.0e+00", "5.0e-02", "1.0e-05", "1.5e+00", "3.0e-01", "1.0e+02",
             "1.2e+06", "1.0e-04", "2.5e+00"}},
        {timeFormat::scientific, 3,
            {"0.000e+00", "5.000e-02", "1.000e-05", "1.500e+00", "3.000e-01",
             "1.000e+02", "1.235e+06", "1.000e-04", "2.500e+00"}},
        {timeFormat::scientific, 6,
            {"0.000000e+00", "5.000000e-02", "1.000000e-05", "1.500000e+00",
             "3.000000e-01", "1.000000e+02", "1.234567e+06", "1.000000e-04",
             "2.500000e+00"}},
        {timeFormat::scientific, 10,
            {"0.0000000000e+00", "5.0000000000e-02", "1.0000000000e-05",
             "1.5000000000e+00", "3.0000000000e-01", "1.0000000000e+02",
             "1.2345670000e+06", "1.0000000000e-04", "2.5000000000e+00"}},
        {timeFormat::scientific, 17,
            {"0.00000000000000000e+00", "5.00000000000000028e-02",
             "1.00000000000000008e-05", "1.50000000000000000e+00",
             "3.00000000000000044e-01", "1.00000000000000000e+02",
             "1.23456700000000000e+06", "1.00000000000000005e-04",
             "2.50000000000000000e+00"}},
    };

const char* formatName(timeFormat f)
{
    return f == timeFormat::general ? "general"
         : f == timeFormat::fixed ? "fixed" : "scientific";
}

} // End anonymous namespace


TEST(timeName, likeOpenFOAM)
{
    for (const row& r : table)
    {
        ASSERT_EQ(r.names.size(), values.size());
        for (std::size_t i = 0; i < values.size(); ++i)
        {
            EXPECT_EQ(timeName(values[i], r.format, r.precision), r.names[i])
                << formatName(r.format) << " precision " << r.precision
                << " value " << values[i];
        }
    }
    // The defaults are OpenFOAM's: general, 6 digits.
    EXPECT_EQ(timeName(0.05), "0.05");
    EXPECT_EQ(timeName(1234567), "1.23457e+06");
    EXPECT_EQ(timeName(123456), "123456");
    EXPECT_EQ(timeName(-0.25), "-0.25");
    // -0 is named 0, not "-0".
    EXPECT_EQ(timeName(-0.0), "0");
    EXPECT_EQ(timeName(-0.0, timeFormat::fixed, 2), "0.00");
}


TEST(timeName, badArguments)
{
    expectMessage(catchFatal([]{ timeName(NAN); }), {"non-finite time"});
    expectMessage(catchFatal([]{ timeName(INFINITY); }), {"non-finite time"});
    expectMessage(catchFatal([]{ timeName(1, timeFormat::general, -1); }),
        {"timePrecision -1 is out of range"});
}


TEST(timeName, formatNames)
{
    EXPECT_EQ(timeFormatFromName("general"), timeFormat::general);
    EXPECT_EQ(timeFormatFromName("fixed"), timeFormat::fixed);
    EXPECT_EQ(timeFormatFromName("scientific"), timeFormat::scientific);
    expectMessage(catchFatal([]{ timeFormatFromName("engineering"); }),
        {"Unknown timeFormat 'engineering'", "general fixed scientific"});
}


TEST(timeName, parse)
{
    double t = -1;
    for (const row& r : table)
    {
        for (std::size_t i = 0; i < values.size(); ++i)
        {
            ASSERT_TRUE(parseTimeName(r.names[i], t)) << r.names[i];
        }
    }
    EXPECT_TRUE(parseTimeName("1e-05", t));
    EXPECT_EQ(t, 1e-05);
    EXPECT_TRUE(parseTimeName("-0.5", t));
    EXPECT_EQ(t, -0.5);
    EXPECT_TRUE(parseTimeName("0.30000000000000004", t));
    EXPECT_EQ(t, 0.1 + 0.2);

    t = 42;
    for
    (
        const char* bad :
        {
            "", "constant", "system", "0.orig", "1e", "1e+", " 1", "1 ",
            "+1", "nan", "inf", "-inf", "0x10", "1e400", "1,5", "1.5.2",
            "0_old", "VTK", ".5", ".0.5.tmp.12"
        }
    )
    {
        EXPECT_FALSE(parseTimeName(bad, t)) << "'" << bad << "'";
    }
    EXPECT_EQ(t, 42);
}


TEST(timeName, roundTrips)
{
    // A name parses to a time that is given the same name again, in every
    // format and precision; at 17 digits (general) the time is exact.
    std::mt19937_64 gen(11);
    std::vector<double> times(values.begin(), values.end());
    for (int i = 0; i < 300; ++i)
    {
        times.push_back(std::abs(test::randomScalar(gen)));
    }
    for (double dt : {1e-5, 0.001/3, 0.0125})
    {
        double t = 0;
        for (int i = 0; i < 100; ++i)
        {
            t += dt;
            times.push_back(t);
        }
    }
    for (double t : times)
    {
        for (timeFormat f :
            {timeFormat::general, timeFormat::fixed, timeFormat::scientific})
        {
            for (int p : {1, 3, 6, 8, 12, 17})
            {
                const std::string name = timeName(t, f, p);
                double back = -1;
                ASSERT_TRUE(parseTimeName(name, back)) << name;
                EXPECT_EQ(timeName(back, f, p), name);
            }
        }
        double back = -1;
        ASSERT_TRUE(parseTimeName(timeName(t, timeFormat::general, 17), back));
        EXPECT_EQ(back, t);
    }
}
