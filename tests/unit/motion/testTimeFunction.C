/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Functions of time for prescribed motions: constants and units, tables
// (interpolation, held ends, the derivative at knots second-order on equal
// and unequal intervals, the second derivative second-order on equal ones),
// the shared rolling-tank record read as a CSV with select, sinusoids with a
// ramp against finite differences, and every bad input as a FatalError
// naming file, line and keyword.

#include "dictionary.H"
#include "../testTools.H"
#include "timeFunction.H"
#include "waveTheory.H"

#include "../testPrecision.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

using namespace sphvcpm;

namespace
{

// * * * * * * * * * * * * * * * * Helpers  * * * * * * * * * * * * * * * * //

constexpr scalar pi = 3.14159265358979323846;
constexpr scalar degree = pi/180;

// Writes constant/motion holding "f { <body> }" (the body's first line is
// line 3 of the file) and reads f.
timeFunction readFunction(const test::scratchDir& dir,
                          const std::string& body, const bool isAngle)
{
    const auto file = dir.write("constant/motion", "f\n{\n" + body + "}\n");
    const dictionary d = dictionary::fromFile(file);
    return timeFunction::read(d.subDict("f"), dir.path(), isAngle);
}

std::string motionFile(const test::scratchDir& dir)
{
    return (dir.path()/"constant/motion").string();
}

// A table of f sampled at times t, as "t value" lines.
std::string sampled(const std::vector<scalar>& t,
                    const std::function<scalar(scalar)>& f)
{
    std::ostringstream os;
    os.precision(17);
    for (const scalar ti : t) os << ti << ' ' << f(ti) << '\n';
    return os.str();
}

// The largest error of the table's derivative at its interior knots
// against df.
scalar knotDerivativeError(const timeFunction& table,
                           const std::function<scalar(scalar)>& df)
{
    scalar err = 0;
    const auto& t = table.times();
    for (std::size_t i = 1; i + 1 < t.size(); ++i)
    {
        err = std::max(err, std::abs(table.derivative(t[i]) - df(t[i])));
    }
    return err;
}

std::string fullPath(const std::string& rel)
{
    return std::string(SPHVCPM_TEST_DATA) + "/" + rel;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constant  * * * * * * * * * * * * * * * //

TEST(timeFunction, constantAndUnits)
{
    test::scratchDir dir("tfConstant");
    const timeFunction offset =
        readFunction(dir, "type constant;\nvalue 0.25;\n", false);
    EXPECT_EQ(offset.type(), timeFunction::kind::constant);
    EXPECT_EQ(offset.value(-3), 0.25);
    EXPECT_EQ(offset.value(7), 0.25);
    EXPECT_EQ(offset.derivative(1), 0);

    const timeFunction deg =
        readFunction(dir, "type constant;\nvalue 90;\nunits degrees;\n",
                     true);
    EXPECT_DOUBLE_EQ(deg.value(0), pi/2);
    const timeFunction rad =
        readFunction(dir, "type constant;\nvalue 1.5;\nunits radians;\n",
                     true);
    EXPECT_DOUBLE_EQ(rad.value(0), 1.5);

    EXPECT_EQ(timeFunction().value(2), 0);
    EXPECT_EQ(timeFunction(3).value(2), 3);
}


// * * * * * * * * * * * * * * * * * Tables  * * * * * * * * * * * * * * * * //

// Piecewise-linear data: exact values between knots, held ends, segment
// slopes, the weighted knot slope, whitespace and comma separators.
TEST(timeFunction, tableLinear)
{
    SPHVCPM_DOUBLE_ONLY();   // digits of a double (time is scalar)
    test::scratchDir dir("tfLinear");
    dir.write("constant/a.dat",
        "# time value\n\n0 1\n  1\t3  \n# a comment between rows\n3 -1\n");
    dir.write("constant/b.csv", "0,1\n1, 3\n3 ,-1\n");
    for (const char* name : {"constant/a.dat", "constant/b.csv"})
    {
        SCOPED_TRACE(name);
        const timeFunction f = readFunction(dir, "type table;\nfile \""
            + std::string(name) + "\";\n", false);
        ASSERT_EQ(f.times().size(), 3u);
        EXPECT_DOUBLE_EQ(f.value(0.5), 2);
        EXPECT_DOUBLE_EQ(f.value(1), 3);
        EXPECT_DOUBLE_EQ(f.value(2), 1);
        EXPECT_DOUBLE_EQ(f.value(2.5), 0);
        // Held constant outside, with no velocity.
        EXPECT_EQ(f.value(-1), 1);
        EXPECT_EQ(f.value(10), -1);
        EXPECT_EQ(f.derivative(-1e-9), 0);
        EXPECT_EQ(f.derivative(3 + 1e-9), 0);
        // Segment slopes, end knots included.
        EXPECT_DOUBLE_EQ(f.derivative(0), 2);
        EXPECT_DOUBLE_EQ(f.derivative(0.3), 2);
        EXPECT_DOUBLE_EQ(f.derivative(2.9), -2);
        EXPECT_DOUBLE_EQ(f.derivative(3), -2);
        // Interior knot, intervals 1 and 2: (2*2 + 1*(-2))/3.
        EXPECT_DOUBLE_EQ(f.derivative(1), 2.0/3.0);
        // Second difference 2 (-2 - 2)/3 at the knot, copied to the ends.
        EXPECT_DOUBLE_EQ(f.secondDerivative(1), -8.0/3.0);
        EXPECT_DOUBLE_EQ(f.secondDerivative(0), -8.0/3.0);
        EXPECT_DOUBLE_EQ(f.secondDerivative(2.2), -8.0/3.0);
        EXPECT_EQ(f.secondDerivative(3.1), 0);
    }

    // Equal intervals: the plain average of the two slopes.
    dir.write("constant/c.dat", "0 0\n1 2\n2 0\n");
    const timeFunction g =
        readFunction(dir, "type table;\nfile \"constant/c.dat\";\n", false);
    EXPECT_DOUBLE_EQ(g.derivative(1), 0);

    // An absolute path, and degrees.
    const auto abs = dir.write("abs.dat", "0 0\n2 180\n");
    const timeFunction h = readFunction(dir, "type table;\nfile \""
        + abs.string() + "\";\nunits degrees;\n", true);
    EXPECT_DOUBLE_EQ(h.value(1), pi/2);
    EXPECT_DOUBLE_EQ(h.derivative(1), pi/2);
}


// A sampled sinusoid: the knot derivative converges at second order, on
// equal intervals and on alternating unequal ones; values between knots
// too.
TEST(timeFunction, tableSampledSinusoidSecondOrder)
{
    SPHVCPM_DOUBLE_ONLY();   // digits of a double (time is scalar)
    test::scratchDir dir("tfSine");
    const auto f = [](scalar t) { return std::sin(2*t) + 0.5*t; };
    const auto df = [](scalar t) { return 2*std::cos(2*t) + 0.5; };

    for (const bool unequal : {false, true})
    {
        SCOPED_TRACE(unequal ? "unequal intervals" : "equal intervals");
        std::vector<scalar> derivErr, valueErr;
        for (const scalar dt : {0.04, 0.02, 0.01})
        {
            std::vector<scalar> t;
            scalar ti = 0;
            for (int i = 0; ti < 3; ++i)
            {
                t.push_back(ti);
                ti += unequal ? (i % 2 ? 1.5*dt : 0.5*dt) : dt;
            }
            dir.write("constant/sine.dat", sampled(t, f));
            const timeFunction table = readFunction(dir,
                "type table;\nfile \"constant/sine.dat\";\n", false);
            derivErr.push_back(knotDerivativeError(table, df));

            scalar err = 0;
            for (std::size_t i = 0; i + 1 < t.size(); ++i)
            {
                const scalar mid = 0.5*(t[i] + t[i + 1]);
                err = std::max<scalar>(err,
                                       std::abs(table.value(mid) - f(mid)));
            }
            valueErr.push_back(err);
        }
        for (std::size_t k = 0; k + 1 < derivErr.size(); ++k)
        {
            // Halving dt divides a second-order error by 4.
            EXPECT_GT(derivErr[k]/derivErr[k + 1], 3.5) << derivErr[k];
            EXPECT_LT(derivErr[k]/derivErr[k + 1], 4.5) << derivErr[k];
            EXPECT_GT(valueErr[k]/valueErr[k + 1], 3.5) << valueErr[k];
        }
        // Leading term on equal intervals: dt^2 |f'''|/6 <= 8 dt^2/6.
        EXPECT_LT(derivErr.back(), 8*0.01*0.01);
    }

    // The acceleration estimate, at and between knots (equal intervals).
    const auto d2f = [](scalar t) { return -4*std::sin(2*t); };
    std::vector<scalar> accelErr;
    for (const scalar dt : {0.04, 0.02, 0.01})
    {
        std::vector<scalar> t;
        for (int i = 0; i*dt < 3; ++i) t.push_back(i*dt);
        dir.write("constant/sine.dat", sampled(t, f));
        const timeFunction table = readFunction(dir,
            "type table;\nfile \"constant/sine.dat\";\n", false);
        scalar err = 0;
        for (std::size_t i = 1; i + 2 < t.size(); ++i)
        {
            for (const scalar tt : {t[i], scalar(0.5*(t[i] + t[i + 1]))})
            {
                err = std::max(err,
                    std::abs(table.secondDerivative(tt) - d2f(tt)));
            }
        }
        accelErr.push_back(err);
    }
    EXPECT_GT(accelErr[0]/accelErr[1], 3.5) << accelErr[0];
    EXPECT_GT(accelErr[1]/accelErr[2], 3.5) << accelErr[1];
}


// The shared roll record of the rolling tank (docs/validation), used
// directly: a CSV with a header, two cases in one file.
TEST(timeFunction, rollingTankRecord)
{
    SPHVCPM_DOUBLE_ONLY();   // digits of a double (time is scalar)
    test::scratchDir dir("tfRoll");
    const std::string csv =
        fullPath("motion/ROLLING_TANK_IDELSOHN_REFERENCE.csv");
    const timeFunction deep = readFunction(dir, "type table;\nfile \"" + csv
        + "\";\ntimeColumn t_s;\nvalueColumn roll_angle_deg;\n"
          "select { case deep_oil_bottom_clamped; }\nunits degrees;\n",
        true);
    ASSERT_EQ(deep.times().size(), 499u);
    // Without select the two cases' rows run back in time: the error
    // says how to pick one.
    const FatalError both = test::catchFatal([&]
    {
        readFunction(dir, "type table;\nfile \"" + csv + "\";\ntimeColumn"
            " t_s;\nvalueColumn roll_angle_deg;\nunits degrees;\n", true);
    });
    test::expectMessage(both, {"times must increase strictly",
        "needs select { <column> <text>; } to pick one"});
    EXPECT_DOUBLE_EQ(deep.times().front(), 0.011045301);
    EXPECT_DOUBLE_EQ(deep.times().back(), 4.9862958);

    // Rows of the file: time, angle in degrees.
    const std::pair<scalar, scalar> rows[] =
    {
        {0.011045301, 0.019399923},
        {0.06, 0.089068404},
        {0.1, 0.17864913},
        {0.99, -2.4787633},
        {2.49, -3.2209232},
        {4.98, -2.3795712},
        {4.9862958, -2.244881}
    };
    for (const auto& [t, angle] : rows)
    {
        EXPECT_NEAR(deep.value(t), angle*degree, 1e-15) << "t = " << t;
    }
    // Held at the first and last samples outside the record.
    EXPECT_DOUBLE_EQ(deep.value(0), 0.019399923*degree);
    EXPECT_DOUBLE_EQ(deep.value(6), -2.244881*degree);
    // Between two rows: the linear interpolant.
    EXPECT_NEAR(deep.value(0.065), 0.5*(0.089068404 + 0.10726816)*degree,
                1e-15);
    // The roll rate peaks near 2 pi 3.96 deg / 1.214 s = 0.36 rad/s.
    scalar peakRate = 0;
    for (const scalar t : deep.times())
    {
        peakRate = std::max(peakRate, std::abs(deep.derivative(t)));
    }
    EXPECT_NEAR(peakRate, 2*pi*3.96*degree/1.214, 0.05);

    // The other case of the same file.
    const timeFunction shallow = readFunction(dir, "type table;\nfile \""
        + csv + "\";\ntimeColumn t_s;\nvalueColumn roll_angle_deg;\n"
          "select { case shallow_water_hanging_baffle; }\n"
          "units degrees;\n", true);
    ASSERT_EQ(shallow.times().size(), 599u);
    EXPECT_NEAR(shallow.value(3), -1.8424545*degree, 1e-15);
    EXPECT_NEAR(shallow.value(0.0099958897), -0.0013518935*degree, 1e-15);
}


// * * * * * * * * * * * * * * * * Sinusoids * * * * * * * * * * * * * * * //

TEST(timeFunction, sinusoidWithRamp)
{
    SPHVCPM_DOUBLE_ONLY();   // digits of a double (time is scalar)
    test::scratchDir dir("tfSinusoid");
    const scalar A = 4, T = 1.214, phase = 0.3, t0 = 0.5, ramp = 0.8;
    const timeFunction f = readFunction(dir, "type sinusoid;\namplitude 4;\n"
        "period 1.214;\nphase 0.3;\nstartTime 0.5;\nrampTime 0.8;\n"
        "units degrees;\n", true);
    EXPECT_EQ(f.type(), timeFunction::kind::sinusoid);

    // At rest before the start; from rest at the start (the ramp's value
    // and slope are 0 there).
    EXPECT_EQ(f.value(0.2), 0);
    EXPECT_EQ(f.derivative(0.2), 0);
    EXPECT_NEAR(f.value(t0), 0, 1e-15);
    EXPECT_NEAR(f.derivative(t0), 0, 1e-15);

    // After the ramp: the full sinusoid.
    for (const scalar t : {1.3, 1.7, 3.1})
    {
        const scalar arg = 2*pi*(t - t0)/T + phase;
        EXPECT_NEAR(f.value(t), A*degree*std::sin(arg), 1e-14);
        EXPECT_NEAR(f.derivative(t), A*degree*2*pi/T*std::cos(arg), 1e-13);
    }
    // Inside the ramp: (1 - cos(pi s))/2 times the sinusoid.
    const scalar tr = 0.9;
    const scalar s = (tr - t0)/ramp;
    EXPECT_NEAR(f.value(tr), A*degree*0.5*(1 - std::cos(pi*s))
        *std::sin(2*pi*(tr - t0)/T + phase), 1e-14);

    // The exact derivative (product rule in the ramp) against central
    // differences, across the ramp's end.
    const scalar h = 1e-6;
    for (scalar t = t0 + 0.01; t < 3; t += 0.0537)
    {
        const scalar fd = (f.value(t + h) - f.value(t - h))/(2*h);
        EXPECT_NEAR(f.derivative(t), fd, 1e-8) << "t = " << t;
    }
    // The second derivative against central differences of the first.
    for (scalar t = t0 + 0.01; t < 3; t += 0.0537)
    {
        const scalar fd = (f.derivative(t + h) - f.derivative(t - h))/(2*h);
        EXPECT_NEAR(f.secondDerivative(t), fd, 1e-7) << "t = " << t;
    }
    EXPECT_EQ(f.secondDerivative(0.2), 0);
    // Continuous velocity where the ramp ends.
    EXPECT_NEAR(f.derivative(t0 + ramp - 1e-9), f.derivative(t0 + ramp + 1e-9),
                1e-7);

    // frequency instead of period; no ramp; radians; an offset (no units).
    const timeFunction g = readFunction(dir, "type sinusoid;\namplitude 0.01;"
        "\nfrequency 2;\n", false);
    EXPECT_NEAR(g.value(0.125), 0.01, 1e-15);
    EXPECT_NEAR(g.derivative(0), 0.01*4*pi, 1e-15);
}


// * * * * * * * * * * * * * * * * * Errors  * * * * * * * * * * * * * * * * //

TEST(timeFunction, tableColumnsByNumber)
{
    // A "t x y z" motion file without a header: the columns by number from
    // 0, as OpenFOAM's csvFile; z here, with a degree value scaled.
    test::scratchDir dir("tfColumns");
    dir.write("constant/xyz.dat", "# t x y z\n0 9 9 0\n1 9 9 2\n2 9 9 6\n");
    const timeFunction z = readFunction(dir, "type table;\nfile"
        " \"constant/xyz.dat\";\ntimeColumn 0;\nvalueColumn 3;\n", false);
    ASSERT_EQ(z.times().size(), 3u);
    EXPECT_DOUBLE_EQ(z.value(0.5), 1);
    EXPECT_DOUBLE_EQ(z.value(1.5), 4);
    const timeFunction a = readFunction(dir, "type table;\nfile"
        " \"constant/xyz.dat\";\ntimeColumn 0;\nvalueColumn 3;\n"
        "units degrees;\n", true);
    EXPECT_NEAR(a.value(2), 6*degree, 1e-15);

    // DualSPHysics's semicolon CSV, with its header: by name and by number.
    dir.write("constant/piston.csv",
              "time [s];x [m]\n0;0\n0.5;0.1\n1;0.3\n");
    const timeFunction named = readFunction(dir, "type table;\nfile"
        " \"constant/piston.csv\";\ntimeColumn \"time [s]\";\n"
        "valueColumn \"x [m]\";\n", false);
    EXPECT_DOUBLE_EQ(named.value(0.75), 0.2);
    dir.write("constant/pistonNoHeader.csv", "0;0\n0.5;0.1\n1;0.3;\n");
    EXPECT_THROW(readFunction(dir, "type table;\nfile"
        " \"constant/pistonNoHeader.csv\";\n", false), FatalError);
    // ... and a spreadsheet's with decimal commas.
    dir.write("constant/pistonNoHeader.csv", "0;0\n0,5;0,1\n1;0,3\n");
    EXPECT_DOUBLE_EQ(readFunction(dir, "type table;\nfile"
        " \"constant/pistonNoHeader.csv\";\n", false).value(0.25), 0.05);

    const std::string motion = motionFile(dir);
    const auto fails = [&](const std::string& body, const std::string& file,
                           const int line,
                           const std::vector<std::string>& parts)
    {
        SCOPED_TRACE(body);
        const FatalError err = test::catchFatal
        (
            [&] { readFunction(dir, body, false); }
        );
        test::expectError(err, file, line, parts);
    };
    fails("type table;\nfile \"constant/xyz.dat\";\ntimeColumn 0;\n"
          "valueColumn 4;\n", (dir.path()/"constant/xyz.dat").string(), 2,
          {"has no column 4", "columns count from 0"});
    fails("type table;\nfile \"constant/xyz.dat\";\ntimeColumn 0;\n"
          "valueColumn -1;\n", motion, 6, {"counts from 0, found -1"});
    fails("type table;\nfile \"constant/xyz.dat\";\ntimeColumn 0;\n"
          "valueColumn 1;\nselect { x 9; }\n", motion, 7,
          {"'select'", "give timeColumn and valueColumn as names"});
}


// A pistonWave is the sinusoid whose stroke gives the wave height asked
// for, with |g| from constant/g.
TEST(timeFunction, pistonWave)
{
    test::scratchDir dir("pistonWave");
    const std::string body = "type pistonWave;\nwaveHeight 0.0349;\n"
        "depth 0.25;\nperiod 1;\nrampTime 2;\n";
    const timeFunction f = readFunction(dir, body, false);
    const scalar k = waveNumber(2*pi, 0.25, 9.81);
    const scalar amplitude = 0.0349/(2*pistonHeightOverStroke(k*0.25));
    EXPECT_NEAR(amplitude, 0.015, 2e-5);
    std::ostringstream a;
    a.precision(17);
    a << amplitude;
    const timeFunction s = readFunction(dir, "type sinusoid;\namplitude "
        + a.str() + ";\nperiod 1;\nrampTime 2;\n", false);
    for (const scalar t : {0.0, 0.3, 1.7, 2.2, 5.05})
    {
        EXPECT_NEAR(f.value(t), s.value(t), 1e-9) << t;
        EXPECT_NEAR(f.derivative(t), s.derivative(t), 1e-8) << t;
    }
    EXPECT_NE(f.note().find("stroke 0.03"), std::string::npos) << f.note();
    EXPECT_NE(f.note().find("wavelength 1.30"), std::string::npos)
        << f.note();
    EXPECT_TRUE(s.note().empty());

    // Weaker gravity: a longer wave, another stroke.
    dir.write("constant/g", "dimensions [0 1 -2 0 0 0 0];\n"
                            "value (0 0 -1.62);\n");
    const timeFunction moon = readFunction(dir, body, false);
    const scalar kMoon = waveNumber(2*pi, 0.25, 1.62);
    EXPECT_NEAR(moon.value(3.25)/f.value(3.25),
                pistonHeightOverStroke(k*0.25)
               /pistonHeightOverStroke(kMoon*0.25), 1e-9);
    std::filesystem::remove(dir.path()/"constant/g");

    // Above Miche's breaking height: a warning naming the line.
    testing::internal::CaptureStderr();
    readFunction(dir, "type pistonWave;\nwaveHeight 0.2;\ndepth 0.25;\n"
                      "period 1;\n", false);
    const std::string warned = testing::internal::GetCapturedStderr();
    EXPECT_NE(warned.find("above the breaking height"), std::string::npos)
        << warned;
    EXPECT_NE(warned.find("line 4"), std::string::npos) << warned;

    // A stroke beyond half the depth (a long wave in shallow water, here
    // 1.99 m in 0.25 m): a warning, as linear theory no longer holds.
    testing::internal::CaptureStderr();
    readFunction(dir, "type pistonWave;\nwaveHeight 0.1;\ndepth 0.25;\n"
                      "period 20;\n", false);
    const std::string long1 = testing::internal::GetCapturedStderr();
    EXPECT_NE(long1.find("more than half the depth"), std::string::npos)
        << long1;
    EXPECT_NE(long1.find("line 4"), std::string::npos) << long1;
    testing::internal::CaptureStderr();
    readFunction(dir, "type flapWave;\nwaveHeight 0.1;\ndepth 0.25;\n"
                      "period 20;\n", true);
    const std::string long2 = testing::internal::GetCapturedStderr();
    EXPECT_NE(long2.find("degrees each way"), std::string::npos) << long2;
    // Both too high and too long a stroke (0.3 m above the breaking
    // height of about 0.22 m, stroke about 6 m in 0.25 m): both warnings.
    testing::internal::CaptureStderr();
    readFunction(dir, "type pistonWave;\nwaveHeight 0.3;\ndepth 0.25;\n"
                      "period 20;\n", false);
    const std::string both = testing::internal::GetCapturedStderr();
    EXPECT_NE(both.find("above the breaking height"), std::string::npos)
        << both;
    EXPECT_NE(both.find("more than half the depth"), std::string::npos)
        << both;
    // The tutorial's wave is well inside.
    testing::internal::CaptureStderr();
    readFunction(dir, body, false);
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

// A flapWave is the angle whose travel at the still-water level, a depth
// above the hinge, is the flap's stroke for the wave asked for.
TEST(timeFunction, flapWave)
{
    test::scratchDir dir("flapWave");
    const timeFunction f = readFunction(dir, "type flapWave;\n"
        "waveHeight 0.035;\ndepth 0.25;\nperiod 1;\n", true);
    const scalar k = waveNumber(2*pi, 0.25, 9.81);
    const scalar stroke = 0.035/flapHeightOverStroke(k*0.25);
    EXPECT_NEAR(stroke, 0.0545, 1e-4);
    // At a quarter period the sinusoid (no ramp) is at its amplitude.
    EXPECT_NEAR(0.25*std::tan(f.value(0.25)), stroke/2, 1e-12);
    EXPECT_NEAR(f.value(0.75), -f.value(0.25), 1e-12);
    EXPECT_NE(f.note().find("flapWave of height 0.035"), std::string::npos)
        << f.note();
    EXPECT_NE(f.note().find("degrees"), std::string::npos) << f.note();
}

// Wavemakers in very deep and very shallow water: a finite paddle motion
// of the right size at every kd (kd = 4000 made a NaN amplitude, which
// the breaking check let through).
TEST(timeFunction, wavemakersAtEveryDepth)
{
    test::scratchDir dir("wavemakerDepths");
    const scalar g = 9.81, H = 0.001;
    for (const scalar d : {0.01, 0.25, 10.0, 1000.0})
    {
        for (const scalar T : {0.1, 1.0, 100.0})
        {
            std::ostringstream body;
            body.precision(17);
            body << "waveHeight " << H << ";\ndepth " << d << ";\nperiod "
                 << T << ";\n";
            SCOPED_TRACE(body.str());
            testing::internal::CaptureStderr();     // breaking warnings
            const timeFunction piston = readFunction(dir,
                "type pistonWave;\n" + body.str(), false);
            const timeFunction flap = readFunction(dir,
                "type flapWave;\n" + body.str(), true);
            testing::internal::GetCapturedStderr();
            const scalar kd = waveNumber(2*pi/T, d, g)*d;
            // No ramp: at a quarter period the paddle is at its amplitude.
            const scalar a = piston.value(T/4), angle = flap.value(T/4);
            ASSERT_TRUE(std::isfinite(a) && std::isfinite(angle)) << kd;
            for (const scalar t : {0.0, 0.3*T, 2.7*T})
            {
                EXPECT_TRUE(std::isfinite(piston.value(t))
                         && std::isfinite(piston.derivative(t))
                         && std::isfinite(flap.value(t))
                         && std::isfinite(flap.derivative(t))) << t;
            }
            EXPECT_NEAR(a/(H/(2*pistonHeightOverStroke(kd))), 1,
                        test::tol(1e-12, 1e-5)) << kd;
            EXPECT_NEAR(std::tan(angle)*2*d/(H/flapHeightOverStroke(kd)), 1,
                        test::tol(1e-12, 1e-5)) << kd;
            if (kd > 100)       // deep water: H/S = 2, 2 (1 - 1/kd)
            {
                EXPECT_NEAR(a, H/4, test::tol(1e-15, 1e-9)) << kd;
                EXPECT_NEAR(std::tan(angle)*2*d, H/(2*(1 - 1/kd)),
                            test::tol(1e-15, 1e-9)) << kd;
            }
        }
    }
}

TEST(timeFunction, errors)
{
    test::scratchDir dir("tfErrors");
    const std::string motion = motionFile(dir);
    auto expectFails = [&](const std::string& body, const bool isAngle,
                           const std::string& file, const int line,
                           const std::vector<std::string>& parts)
    {
        SCOPED_TRACE(body);
        const FatalError err = test::catchFatal
        (
            [&] { readFunction(dir, body, isAngle); }
        );
        test::expectError(err, file, line, parts);
    };

    // Unknown type; unknown keyword with a suggestion.
    expectFails("type spline;\n", false, motion, 3,
                {"spline", "constant", "sinusoid", "pistonWave", "flapWave", "table"});
    expectFails("type sinusoid;\namplitude 1;\npreiod 2;\n", false, motion,
                5, {"Unknown keyword 'preiod'", "Did you mean 'period'"});

    // Units: required for an angle, refused for anything else.
    expectFails("type constant;\nvalue 1;\n", true, motion, 2,
                {"is an angle", "units degrees", "units radians"});
    expectFails("type constant;\nvalue 1;\nunits degrees;\n", false, motion,
                5, {"units", "only an angle"});
    expectFails("type constant;\nvalue 1;\nunits grad;\n", true, motion, 5,
                {"grad", "degrees", "radians"});
    expectFails("type constant;\nvalue 1;\nunit degrees;\n", true, motion,
                5, {"Unknown keyword 'unit'", "Did you mean 'units'"});

    // Sinusoid: period / frequency, ramp.
    expectFails("type sinusoid;\namplitude 1;\nperiod -2;\n", false, motion,
                5, {"period", "positive", "-2"});
    expectFails("type sinusoid;\namplitude 1;\nfrequency 0;\n", false,
                motion, 5, {"frequency", "positive"});
    expectFails("type sinusoid;\namplitude 1;\nperiod 1;\nfrequency 1;\n",
                false, motion, 6, {"period or frequency, not both"});
    expectFails("type sinusoid;\namplitude 1;\n", false, motion, 2,
                {"period", "frequency"});
    expectFails("type sinusoid;\namplitude 1;\nperiod 1;\nrampTime -0.5;\n",
                false, motion, 6, {"rampTime", ">= 0", "-0.5"});

    // pistonWave: positive height and depth, no amplitude, not an angle.
    expectFails("type pistonWave;\nwaveHeight 0;\ndepth 1;\nperiod 1;\n",
                false, motion, 4, {"waveHeight", "positive"});
    expectFails("type pistonWave;\nwaveHeight 0.1;\nperiod 1;\n", false,
                motion, 2, {"depth"});
    expectFails("type pistonWave;\nwaveHeight 0.1;\ndepth -1;\nperiod 1;\n",
                false, motion, 5, {"depth", "positive", "-1"});
    expectFails("type pistonWave;\namplitude 0.1;\ndepth 1;\nperiod 1;\n",
                false, motion, 4, {"Unknown keyword 'amplitude'"});
    expectFails("type pistonWave;\nwaveHeight 0.1;\ndepth 1;\nperiod 1;\n"
                "units degrees;\n", true, motion, 3,
                {"pistonWave is the offset of a translation", "flapWave"});
    // No wave (w^2 d/g beyond the numbers), or a stroke beyond them: an
    // error naming the keyword, never a NaN or infinite paddle.
    expectFails("type pistonWave;\nwaveHeight 0.1;\ndepth 1;\n"
                "period 1e-200;\n", false, motion, 6,
                {"'period'", "no wave of period", "not a positive finite"});
    expectFails("type flapWave;\nwaveHeight 0.1;\ndepth 1;\n"
                "frequency 1e-200;\n", true, motion, 6,
                {"'frequency'", "no wave of period", "not a positive finite"});
    expectFails("type flapWave;\nwaveHeight 1e307;\ndepth 0.01;\n"
                "period 100;\n", true, motion, 4,
                {"'waveHeight'", "needs a stroke", "not a finite number"});
    // flapWave: an angle, derived in radians (no units).
    expectFails("type flapWave;\nwaveHeight 0.1;\ndepth 1;\nperiod 1;\n",
                false, motion, 3, {"flapWave is the angle of a rotation",
                                   "pistonWave"});
    expectFails("type flapWave;\nwaveHeight 0.1;\ndepth 1;\nperiod 1;\n"
                "units degrees;\n", true, motion, 7,
                {"a flapWave's angle is derived"});

    // Tables.
    expectFails("type table;\nfile \"constant/none.dat\";\n", false, motion,
                4, {"file", "none.dat", "does not exist"});

    const std::string bad = dir.write("constant/bad.dat",
        "# comment\n0 1\n1 x2\n").string();
    expectFails("type table;\nfile \"constant/bad.dat\";\n", false, bad, 3,
                {"'x2'", "not a number"});

    const std::string header = dir.write("constant/header.dat",
        "t value\n0 1\n1 2\n").string();
    expectFails("type table;\nfile \"constant/header.dat\";\n", false,
                header, 1, {"'t'", "not a number", "timeColumn"});

    const std::string three = dir.write("constant/three.dat",
        "0 1\n1 2 3\n").string();
    expectFails("type table;\nfile \"constant/three.dat\";\n", false, three,
                2, {"two columns", "3 cells"});

    dir.write("constant/one.dat", "# only one row\n0 1\n");
    expectFails("type table;\nfile \"constant/one.dat\";\n", false, motion,
                4, {"one.dat", "1 row", "at least 2"});

    const std::string back = dir.write("constant/back.dat",
        "0 1\n1 2\n\n1 3\n").string();
    expectFails("type table;\nfile \"constant/back.dat\";\n", false, back, 4,
                {"time 1", "line 2", "increase strictly"});
    const std::string down = dir.write("constant/down.dat",
        "0 1\n2 2\n1 3\n").string();
    expectFails("type table;\nfile \"constant/down.dat\";\n", false, down, 3,
                {"time 1", "time 2", "increase strictly"});

    // Named columns and select.
    const std::string csv = dir.write("constant/roll.csv",
        "case,t_s,roll_angle_deg\na,0,1\na,1,2\nb,0,3\nb,1,bad\n").string();
    const std::string columns =
        "type table;\nfile \"constant/roll.csv\";\ntimeColumn t_s;\n";
    expectFails(columns + "valueColumn roll_deg;\n", false, motion, 6,
                {"valueColumn", "roll_deg", "case t_s roll_angle_deg"});
    expectFails(columns + "valueColumn roll_angle_deg;\n"
                "select { case c; }\n", false, motion, 7,
                {"select", "no row", "roll.csv"});
    expectFails(columns + "valueColumn roll_angle_deg;\n"
                "select { }\n", false, motion, 7,
                {"'select'", "is empty", "select { column text; }"});
    expectFails(columns + "valueColumn roll_angle_deg;\n"
                "select { kase a; }\n", false, motion, 7,
                {"kase", "no column"});
    expectFails(columns + "valueColumn roll_angle_deg;\n"
                "select { case b; }\n", false, csv, 5,
                {"'bad'", "roll_angle_deg", "not a number"});
    expectFails(columns + "valueColumn roll_angle_deg;\n", false, csv, 4,
                {"time 0", "increase strictly"});
    // ... and select a reads fine.
    const timeFunction a = readFunction(dir, columns
        + "valueColumn roll_angle_deg;\nselect { case a; }\n", false);
    EXPECT_DOUBLE_EQ(a.value(0.5), 1.5);

    const std::string ragged = dir.write("constant/ragged.csv",
        "t,v\n0,1\n1\n").string();
    expectFails("type table;\nfile \"constant/ragged.csv\";\n"
                "timeColumn t;\nvalueColumn v;\n", false, ragged, 3,
                {"1 cells", "header"});
}
