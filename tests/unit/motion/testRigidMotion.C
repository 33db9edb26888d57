/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Rigid motions and the motions of a case: a quarter turn, the right-hand
// rule, distances to the axis and between points kept (a rigid motion
// strains nothing), velocity = d(position)/dt and acceleration =
// d(velocity)/dt by central differences, a steady turn's centripetal
// acceleration, rotation with translation, the transform's inverse,
// constant/motion with the rolling tank's roll record, and every bad input
// as a FatalError.

#include "dictionary.H"
#include "motionSet.H"
#include "../testTools.H"

#include "../testPrecision.H"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace sphvcpm;

namespace
{

// * * * * * * * * * * * * * * * * Helpers  * * * * * * * * * * * * * * * * //

constexpr scalar pi = 3.14159265358979323846;

// Points (double in both builds) or vectors (scalar), compared as they are.
template<class T>
void expectNear(const Vec3<T>& a, const Vec3<T>& b, const scalar tol)
{
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

// A smooth angle or offset, built as constant/motion would give it.
timeFunction sinusoid(const test::scratchDir& dir, const std::string& body,
                      const bool isAngle)
{
    const auto file = dir.write("f.dict", "f { type sinusoid; " + body
        + " }\n");
    return timeFunction::read(dictionary::fromFile(file).subDict("f"),
                              dir.path(), isAngle);
}

std::vector<point> randomPoints(const int n, const unsigned seed)
{
    std::mt19937 gen(seed);
    std::uniform_real_distribution<scalar> u(-1, 1);
    std::vector<point> X(n);
    for (point& p : X) p = {u(gen), u(gen), u(gen)};
    return X;
}

// Velocity and acceleration against central differences of position and
// velocity, relative to the scale of the motion.
void expectRatesMatch(const rigidMotion& m, const std::vector<point>& X,
                          const scalar t, const scalar scale)
{
    const scalar h = 1e-6;
    for (const point& p : X)
    {
        const vec3 fd =
            toVec3(m.position(p, t + h) - m.position(p, t - h))/(2*h);
        const vec3 u = m.velocity(p, t);
        EXPECT_LT(mag(u - fd), 1e-8*scale)
            << "t = " << t << ", |u - fd| = " << mag(u - fd);

        const vec3 fdA =
            (m.velocity(p, t + h) - m.velocity(p, t - h))/(2*h);
        const vec3 a = m.acceleration(p, t);
        EXPECT_LT(mag(a - fdA), 1e-7*scale)
            << "t = " << t << ", |a - fd| = " << mag(a - fdA);
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Rotation * * * * * * * * * * * * * * * * //

TEST(rigidMotion, quarterTurnAndRightHandRule)
{
    SPHVCPM_DOUBLE_ONLY();   // digits of a double (time is scalar)
    const rigidMotion about0({0, 0, 0}, {0, 0, 2}, timeFunction(pi/2));
    expectNear(about0.position({1, 0, 0}, 0), {0, 1, 0}, 1e-15);
    expectNear(about0.position({0, 1, 0}, 0), {-1, 0, 0}, 1e-15);
    expectNear(about0.position({0, 0, 1}, 0), {0, 0, 1}, 1e-15);

    // About an axis through (1, 1, 0).
    const rigidMotion about11({1, 1, 0}, {0, 0, 1}, timeFunction(pi/2));
    expectNear(about11.position({2, 1, 5}, 3), {1, 2, 5}, 1e-15);

    // About x: y goes to z.
    const rigidMotion aboutX({0, 0, 0}, {1, 0, 0}, timeFunction(pi/2));
    expectNear(aboutX.position({0, 1, 0}, 0), {0, 0, 1}, 1e-15);

    // A positive rate about z moves (1, 0, 0) towards +y.
    test::scratchDir dir("rmRate");
    const rigidMotion turning({0, 0, 0}, {0, 0, 1},
        sinusoid(dir, "amplitude 0.1; period 1; units radians;", true));
    const vec3 u = turning.velocity({1, 0, 0}, 0);
    EXPECT_NEAR(u.y, 0.1*2*pi, 1e-14);
    EXPECT_NEAR(u.x, 0, 1e-15);
}


// Distances to the axis and between points are kept at every time (no
// strain), and the velocity is the time derivative of the position.
TEST(rigidMotion, rotationIsRigidAndVelocityIsRate)
{
    SPHVCPM_DOUBLE_ONLY();   // digits of a double (time is scalar)
    test::scratchDir dir("rmRigid");
    const vec3 origin{0.3, -0.2, 0.1};
    const vec3 axis{1, 2, -0.5};
    const rigidMotion m(origin, axis, sinusoid(dir,
        "amplitude 30; period 1.3; phase 0.2; startTime 0.1; rampTime 0.5;"
        " units degrees;", true));

    const std::vector<point> X = randomPoints(20, 7);
    const vec3 k = axis/mag(axis);
    for (const scalar t : {0.0, 0.23, 0.47, 0.8, 1.9})
    {
        const rigidTransform T = m.transform(t);
        for (std::size_t i = 0; i < X.size(); ++i)
        {
            const point x = T.apply(X[i]);
            EXPECT_NEAR(mag(x - origin), mag(X[i] - origin), 1e-14);
            // The same point of the axis, the same distance from it.
            EXPECT_NEAR(dot(x - origin, toPoint(k)),
                        dot(X[i] - origin, toPoint(k)), 1e-14);
            for (std::size_t j = 0; j < i; ++j)
            {
                EXPECT_NEAR(mag(x - T.apply(X[j])), mag(X[i] - X[j]), 1e-14);
            }
        }
        expectRatesMatch(m, X, t, 1);
    }
}


// x = origin + d + R (X - origin): rotation about the axis through origin,
// then translation; inverse and velocity of a moved point.
TEST(rigidMotion, rotationWithTranslation)
{
    SPHVCPM_DOUBLE_ONLY();   // digits of a double (time is scalar)
    test::scratchDir dir("rmBoth");
    rigidMotion quarter({1, 0, 0}, {0, 0, 1}, timeFunction(pi/2));
    quarter.setTranslation({2, 0, 0}, timeFunction(0.5));
    EXPECT_TRUE(quarter.rotates());
    EXPECT_TRUE(quarter.translates());
    expectNear(quarter.direction(), {1, 0, 0}, 0);
    // (2,0,0) -> rotated about (1,0,0) to (1,1,0) -> shifted to (1.5,1,0).
    expectNear(quarter.position({2, 0, 0}, 1), {1.5, 1, 0}, 1e-15);

    rigidMotion m({0.3045, 0, 0}, {0, 0, 1}, sinusoid(dir,
        "amplitude 4; period 1.214; rampTime 0.6; units degrees;", true));
    m.setTranslation({1, 1, 0}, sinusoid(dir,
        "amplitude 0.05; frequency 0.7; phase 1; startTime 0.2;", false));

    const std::vector<point> X = randomPoints(20, 11);
    for (const scalar t : {0.1, 0.35, 0.9, 2.2})
    {
        const rigidTransform T = m.transform(t);
        const point d = toPoint(m.offset(t)*vec3{1, 1, 0}/std::sqrt(2.0));
        expectNear(T.translation, d, 1e-15);
        for (const point& p : X)
        {
            const point x = T.apply(p);
            // The rotation part alone keeps the distance to the axis.
            EXPECT_NEAR(mag(x - d - T.origin), mag(p - T.origin), 1e-14);
            expectNear(T.reference(x), p, 1e-14);
            expectNear(T.velocityAtPosition(x), T.velocityAt(p), 1e-14);
            expectNear(T.accelerationAtPosition(x), T.accelerationAt(p),
                       1e-14);
        }
        expectRatesMatch(m, X, t, 1);
    }

    // Translation alone.
    const rigidMotion slide({0, 0, 3}, sinusoid(dir,
        "amplitude 0.2; period 2;", false));
    expectNear(slide.position({1, 2, 3}, 0.5), {1, 2, 3.2}, 1e-15);
    expectNear(slide.velocity({1, 2, 3}, 0), {0, 0, 0.2*pi}, 1e-15);
    EXPECT_FALSE(slide.rotates());
}


// A steady turn: the acceleration is centripetal, -omega^2 times the arm.
// A 2D case's motion with its origin off the plane, or an axis a rounding
// away from z: restricted to the plane, points of z = 0 stay at exactly 0
// at every angle (R_zz = cos + (1 - cos) is not always exactly 1, which
// once lifted a 2D rolling tank's particles off the plane).
// A direction is normalised by its largest component first: (1e200 0 0)
// squared overflowed its length to inf, and the paddle it drove stood still.
TEST(rigidMotion, hugeDirectionIsNotLost)
{
    rigidMotion m({0, 0, 0}, {0, 0, 1}, timeFunction(0.0));
    m.setTranslation({1e200, -1e200, 0}, timeFunction(0.25));
    EXPECT_NEAR(m.direction().x, 1/std::sqrt(2.0), 1e-15);
    EXPECT_NEAR(m.direction().y, -1/std::sqrt(2.0), 1e-15);
    const point moved = m.transform(0).apply({0, 0, 0});
    EXPECT_NEAR(moved.x, 0.25/std::sqrt(2.0), 1e-15);
    EXPECT_NEAR(moved.y, -0.25/std::sqrt(2.0), 1e-15);

    EXPECT_EQ(mag(unitVector(vec3{0, 0, 0})), 0);
    EXPECT_EQ(mag(unitVector(vec3{std::nan(""), 1, 0})), 0);
    EXPECT_EQ(unitVector(vec3{0, 3e-300, 0}).y, 1);
}


TEST(rigidMotion, restrictedToThePlane)
{
    for (const scalar angleDeg : {0.0, 61.0, 100.0, 137.0, 199.0, 271.0})
    {
        rigidMotion m({0.3045, 0, 0.005}, {1e-13, 0, 1},
                      timeFunction(angleDeg*pi/180));
        m.setTranslation({1, 2, 1e-14}, timeFunction(0.25));
        m.restrictToPlane();
        EXPECT_EQ(m.origin().z, 0);
        EXPECT_EQ(m.axis().x, 0);
        EXPECT_EQ(m.axis().z, 1);
        EXPECT_EQ(m.direction().z, 0);
        const rigidTransform T = m.transform(0);
        for (const point& p : randomPoints(20, 5))
        {
            const point X{p.x, p.y, 0};
            EXPECT_EQ(T.apply(X).z, 0) << angleDeg;
            EXPECT_EQ(T.velocityAt(X).z, 0) << angleDeg;
        }
    }
}


TEST(rigidMotion, steadyTurnIsCentripetal)
{
    test::scratchDir dir("rmSteady");
    dir.write("constant/turn.dat", "0 0\n10 20\n");
    const auto file = dir.write("f.dict",
        "f { type table; file \"constant/turn.dat\"; units radians; }\n");
    const rigidMotion m({1, 0, 0}, {0, 0, 1}, timeFunction::read
    (
        dictionary::fromFile(file).subDict("f"), dir.path(), true
    ));
    for (const scalar t : {0.3, 2.0, 7.1})
    {
        const vec3 arm = toVec3(m.position({3, 0, 0}, t) - point{1, 0, 0});
        expectNear(m.acceleration({3, 0, 0}, t), -4.0*arm, 1e-13);
        expectNear(m.velocity({3, 0, 0}, t), 2.0*vec3{-arm.y, arm.x, 0},
                   1e-13);
    }
}


// * * * * * * * * * * * * * * * * constant/motion  * * * * * * * * * * * * //

// The rolling tank: tank and plate clamp rotated about the bottom mid-point
// by the measured roll, a gate translated by a sinusoid.
TEST(motionSet, rollingTank)
{
    SPHVCPM_DOUBLE_ONLY();   // digits of a double (time is scalar)
    test::scratchDir dir("msTank");
    const std::string csv = std::string(SPHVCPM_TEST_DATA)
        + "/motion/ROLLING_TANK_IDELSOHN_REFERENCE.csv";
    dir.write("constant/motion",
        "FoamFile { format ascii; class dictionary; object motion; }\n"
        "roll\n"
        "{\n"
        "    bodies (tank plate);\n"
        "    origin (0.3045 0 0);\n"
        "    axis (0 0 1);\n"
        "    angle\n"
        "    {\n"
        "        type table; file \"" + csv + "\";\n"
        "        timeColumn t_s; valueColumn roll_angle_deg;\n"
        "        select { case deep_oil_bottom_clamped; }\n"
        "        units degrees;\n"
        "    }\n"
        "}\n"
        "shake\n"
        "{\n"
        "    bodies (gate);\n"
        "    direction (2 0 0);\n"
        "    offset { type sinusoid; amplitude 0.01; period 0.5;"
        " rampTime 1; }\n"
        "}\n");
    const motionSet set = motionSet::read(dir.path());
    ASSERT_EQ(set.motions().size(), 2u);
    EXPECT_EQ(set.motions()[0].name, "roll");
    EXPECT_EQ(set.bodies(), (std::vector<std::string>{"tank", "plate",
                                                       "gate"}));
    EXPECT_EQ(set.motionOf("fluid"), nullptr);
    ASSERT_NE(set.motionOf("tank"), nullptr);
    EXPECT_EQ(set.motionOf("tank"), set.motionOf("plate"));

    // At a sample of the record the tank is turned by the listed angle.
    const rigidMotion& roll = *set.motionOf("tank");
    const scalar theta = -3.2209232*pi/180;   // t = 2.49 s
    const point corner{0.609, 0.3445, 0};
    const point r = corner - point{0.3045, 0, 0};
    const point expected = point{0.3045, 0, 0}
        + point{std::cos(theta)*r.x - std::sin(theta)*r.y,
               std::sin(theta)*r.x + std::cos(theta)*r.y, 0};
    expectNear(roll.position(corner, 2.49), expected, 1e-15);
    EXPECT_NEAR(roll.angle(2.49), theta, 1e-15);

    const rigidMotion& shake = *set.motionOf("gate");
    EXPECT_FALSE(shake.rotates());
    EXPECT_NEAR(shake.position({0, 0, 0}, 1.125).x, 0.01, 1e-15);

    // The caller says which bodies may move.
    const std::vector<std::string> all{"tank", "plate", "gate", "fluid"};
    set.checkBodies({"tank", "plate", "gate", "fluid"}, all, "a wall or solid");
    const FatalError err = test::catchFatal([&]
    {
        set.checkBodies({"tank", "gate"}, all,
                        "a wall body or a clamped solid");
    });
    test::expectError(err, (dir.path()/"constant/motion").string(), 4,
        {"plate", "a wall body or a clamped solid", "(tank gate)"});
    // A body the case does not have: the closest name.
    const FatalError missing = test::catchFatal([&]
    {
        set.checkBodies({"tank", "plates", "gate"}, {"tank", "plates", "gate"},
                        "a wall body or a clamped solid");
    });
    test::expectError(missing, (dir.path()/"constant/motion").string(), 4,
        {"the case has no body plate", "did you mean plates?",
         "(tank plates gate)"});

    EXPECT_TRUE(motionSet::readIfPresent(dir.path()/"nowhere").empty());
}


TEST(motionSet, errors)
{
    test::scratchDir dir("msErrors");
    const std::string file = (dir.path()/"constant/motion").string();
    auto expectFails = [&](const std::string& text, const int line,
                           const std::vector<std::string>& parts)
    {
        SCOPED_TRACE(text);
        dir.write("constant/motion", text);
        const FatalError err =
            test::catchFatal([&] { motionSet::read(dir.path()); });
        test::expectError(err, file, line, parts);
    };
    const std::string angle = "angle { type constant; value 0.1;"
        " units radians; }\n";

    // Present but empty (a truncated file): not the same as no motion.
    expectFails("", 0, {"defines no motion", "remove the file"});
    expectFails("// only a comment\n", 0, {"defines no motion"});
    // Zero axis; zero direction.
    expectFails("m\n{\nbodies (a);\norigin (0 0 0);\naxis (0 0 0);\n"
                + angle + "}\n", 5, {"axis", "zero vector"});
    expectFails("m\n{\nbodies (a);\ndirection (0 0 0);\n"
                "offset { type constant; value 1; }\n}\n", 4,
                {"direction", "zero vector"});
    expectFails("m\n{\nbodies (a);\ndirection (1e-300 0 0);\n"
                "offset { type constant; value 1; }\n}\n", 4,
                {"direction", "zero vector"});
    // Nothing to move by; a lone axis.
    expectFails("m\n{\nbodies (a);\norigin (0 0 0);\n}\n", 2,
                {"moves nothing", "angle", "offset"});
    expectFails("m\n{\nbodies (a);\naxis (0 0 1);\ndirection (1 0 0);\n"
                "offset { type constant; value 1; }\n}\n", 4,
                {"axis", "no angle"});
    // Missing origin with an angle.
    expectFails("m\n{\nbodies (a);\naxis (0 0 1);\n" + angle + "}\n", 2,
                {"origin"});
    // A misspelt keyword, with the closest suggestion.
    expectFails("m\n{\nbodies (a);\norigin (0 0 0);\naxsi (0 0 1);\n"
                + angle + "}\n", 5,
                {"Unknown keyword 'axsi'", "Did you mean 'axis'"});
    // Bodies: missing, empty, twice in one motion, in two motions.
    expectFails("m\n{\norigin (0 0 0);\naxis (0 0 1);\n" + angle + "}\n", 2,
                {"bodies"});
    expectFails("m\n{\nbodies ();\norigin (0 0 0);\naxis (0 0 1);\n"
                + angle + "}\n", 3, {"names no body"});
    expectFails("m\n{\nbodies (a b a);\norigin (0 0 0);\naxis (0 0 1);\n"
                + angle + "}\n", 3, {"body a is named twice"});
    expectFails("m\n{\nbodies (a b);\norigin (0 0 0);\naxis (0 0 1);\n"
                + angle + "}\nn\n{\n\nbodies (c b);\norigin (0 0 0);\n"
                  "axis (1 0 0);\n" + angle + "}\n", 11,
                {"body b", "motion m", "line 3", "one motion"});
    // An entry that is not a motion; an error inside a time function.
    expectFails("speed 3;\n", 1, {"speed", "sub-dictionary"});
    expectFails("m\n{\nbodies (a);\norigin (0 0 0);\naxis (0 0 1);\n"
                "angle { type constant; value 0.1; }\n}\n", 6, {"units"});

    // No constant/motion at all.
    const FatalError missing = test::catchFatal
    (
        [&] { motionSet::read(dir.path()/"nowhere"); }
    );
    EXPECT_NE(missing.message().find("does not exist"), std::string::npos);

    // Zero vectors built in code.
    EXPECT_NE(test::catchFatal([]
    {
        rigidMotion({0, 0, 0}, {0, 0, 0}, timeFunction(1));
    }).message().find("axis"), std::string::npos);
    EXPECT_NE(test::catchFatal([]
    {
        rigidMotion({0, 0, 0}, timeFunction(1));
    }).message().find("direction"), std::string::npos);
}
