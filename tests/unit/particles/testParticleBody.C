/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// particleBody: construction, the field registry and its errors, resizing
// with fresh ids, and reorder/remove carrying ids and fields together.

#include "particleBody.H"
#include "testParticleTools.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

using namespace sphvcpm;
using test::catchFatal;
using test::expectMessage;

namespace
{

// Values that tell which particle (by id) they belong to.
vec3 positionOf(label id)
{
    return {scalar(id), 2.0*id, -0.5*id};
}

scalar rhoOf(label id)
{
    return 1000 + 0.25*id;
}

label tagOf(label id)
{
    return 7*id - 3;
}

particleBody taggedBody(label n)
{
    particleBody body("water", bodyType::fluid, 3, 0.01);
    body.resize(n);
    auto& rho = body.addScalarField("rho");
    auto& U = body.addVectorField("U");
    auto& tag = body.addLabelField("tag");
    for (label i = 0; i < n; ++i)
    {
        const label id = body.id()[i];
        body.position()[i] = toPoint(positionOf(id));
        rho[i] = rhoOf(id);
        U[i] = -positionOf(id);
        tag[i] = tagOf(id);
    }
    return body;
}

// Every field of particle i agrees with its id.
void expectTagged(const particleBody& body)
{
    for (label i = 0; i < body.size(); ++i)
    {
        const label id = body.id()[i];
        EXPECT_EQ(body.position()[i], toPoint(positionOf(id))) << i;
        EXPECT_EQ(body.scalarField("rho")[i], rhoOf(id)) << i;
        EXPECT_EQ(body.vectorField("U")[i], -positionOf(id)) << i;
        EXPECT_EQ(body.labelField("tag")[i], tagOf(id)) << i;
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Construction  * * * * * * * * * * * * * * //

TEST(particleBody, newBodyHasPositionAndId)
{
    const particleBody body("gate", bodyType::solid, 2, 0.005);
    EXPECT_EQ(body.name(), "gate");
    EXPECT_EQ(body.type(), bodyType::solid);
    EXPECT_EQ(body.nDimensions(), 2);
    EXPECT_EQ(body.dp(), scalar(0.005));
    EXPECT_EQ(body.size(), 0);
    EXPECT_EQ(body.nextId(), 0);
    EXPECT_EQ(body.fieldNames(), (std::vector<std::string>{"id", "position"}));
    EXPECT_EQ(body.kindOf("position"), fieldKind::vectorField);
    EXPECT_EQ(body.kindOf("id"), fieldKind::labelField);
}


TEST(particleBody, invalidConstruction)
{
    expectMessage(catchFatal([]{ particleBody("b", bodyType::fluid, 4, 0.1); }),
        {"Body 'b': nDimensions is 4, expected 2 or 3"});
    expectMessage(catchFatal([]{ particleBody("b", bodyType::fluid, 3, 0); }),
        {"dp is 0, expected a positive number"});
    expectMessage(catchFatal([]{ particleBody("b", bodyType::fluid, 3, NAN); }),
        {"expected a positive number"});
    for (const char* bad : {"", "uniform", ".hidden", "a/b", "a b"})
    {
        expectMessage
        (
            catchFatal([&]{ particleBody(bad, bodyType::wall, 3, 0.1); }),
            {"Invalid body name '" + std::string(bad) + "'"}
        );
    }
}


TEST(particleBody, bodyTypeNames)
{
    for (bodyType t : {bodyType::fluid, bodyType::wall, bodyType::solid})
    {
        EXPECT_EQ(bodyTypeFromName(bodyTypeName(t)), t);
    }
    expectMessage(catchFatal([]{ bodyTypeFromName("liquid"); }),
        {"Unknown body type 'liquid'", "fluid wall solid"});
}


// * * * * * * * * * * * * * * * * * Fields  * * * * * * * * * * * * * * * //

TEST(particleBody, addAndAccessFields)
{
    particleBody body("water", bodyType::fluid, 3, 0.01);
    body.resize(4);
    auto& rho = body.addScalarField("rho", 1000);
    EXPECT_EQ(rho, std::vector<scalar>(4, 1000));
    rho[2] = 999;
    // Adding again returns the same field untouched.
    EXPECT_EQ(&body.addScalarField("rho", 5), &rho);
    EXPECT_EQ(body.scalarField("rho")[2], 999);

    const auto& U = body.addVectorField("U", {1, 2, 3});
    EXPECT_EQ(U[3], (vec3{1, 2, 3}));
    body.addLabelField("cell", -1);
    EXPECT_TRUE(body.hasField("cell"));
    EXPECT_FALSE(body.hasField("p"));
    EXPECT_EQ(body.kindOf("rho"), fieldKind::scalarField);
    EXPECT_EQ(body.kindOf("U"), fieldKind::vectorField);
    EXPECT_EQ(body.kindOf("cell"), fieldKind::labelField);
    EXPECT_EQ(body.fieldNames(),
        (std::vector<std::string>{"U", "cell", "id", "position", "rho"}));

    const particleBody& cbody = body;
    EXPECT_EQ(cbody.scalarField("rho")[2], 999);
    EXPECT_EQ(cbody.labelField("cell")[0], -1);
    EXPECT_EQ(cbody.id(), (std::vector<label>{0, 1, 2, 3}));

    EXPECT_TRUE(body.removeField("cell"));
    EXPECT_FALSE(body.removeField("cell"));
    EXPECT_FALSE(body.hasField("cell"));
    expectMessage(catchFatal([&]{ body.removeField("id"); }),
        {"field 'id' cannot be removed"});
}


TEST(particleBody, missingFieldNamesBodyFieldAndFieldsPresent)
{
    particleBody body("water", bodyType::fluid, 3, 0.01);
    body.addScalarField("rho");
    const particleBody& cbody = body;

    FatalError err = catchFatal([&]{ body.scalarField("p"); });
    expectMessage(err, {"Body 'water' has no scalarField 'p'",
        "Fields of body 'water': id position rho"});
    EXPECT_FALSE(err.isIOError());

    err = catchFatal([&]{ cbody.vectorField("rho"); });
    expectMessage(err, {"Body 'water' has no vectorField 'rho'",
        "it is a scalarField"});
    err = catchFatal([&]{ cbody.labelField("position"); });
    expectMessage(err, {"no labelField 'position'", "it is a vectorField"});
    // Positions are points (double in every build): position() holds them.
    err = catchFatal([&]{ cbody.vectorField("position"); });
    expectMessage(err, {"no vectorField 'position'",
        "it is a vectorField of points, position()"});
    EXPECT_EQ(body.kindOf("position"), fieldKind::vectorField);
    err = catchFatal([&]{ body.kindOf("T"); });
    expectMessage(err, {"has no field 'T'"});
    // Adding a field under a name of another kind is the same error.
    err = catchFatal([&]{ body.addVectorField("rho"); });
    expectMessage(err, {"no vectorField 'rho'", "it is a scalarField"});

    for (const char* bad : {"bodyProperties", "a b", ".x", "a/b", ""})
    {
        err = catchFatal([&]{ body.addScalarField(bad); });
        expectMessage(err, {"invalid field name '" + std::string(bad) + "'"});
    }
}


// * * * * * * * * * * * * * * * Resize and ids  * * * * * * * * * * * * * //

TEST(particleBody, resizeAndAppendGiveFreshIds)
{
    particleBody body("water", bodyType::fluid, 2, 0.01);
    body.addScalarField("rho", 1000);
    body.resize(3);
    EXPECT_EQ(body.id(), (std::vector<label>{0, 1, 2}));
    // New particles get zero values, whatever the field's init was.
    EXPECT_EQ(body.scalarField("rho"), (std::vector<scalar>{0, 0, 0}));
    EXPECT_EQ(body.nextId(), 3);

    // Ids are not given out again after shrinking.
    body.resize(1);
    body.resize(3);
    EXPECT_EQ(body.id(), (std::vector<label>{0, 3, 4}));

    const label i = body.append({1, 2, 0});
    EXPECT_EQ(i, 3);
    EXPECT_EQ(body.size(), 4);
    EXPECT_EQ(body.position()[3], (point{1, 2, 0}));
    EXPECT_EQ(body.id()[3], 5);
    EXPECT_EQ(body.scalarField("rho")[3], 0);
    EXPECT_EQ(body.nextId(), 6);

    expectMessage(catchFatal([&]{ body.resize(-1); }),
        {"cannot resize to -1 particles"});
    body.setNextId(std::numeric_limits<label>::max() - 1);
    expectMessage(catchFatal([&]{ body.resize(10); }),
        {"would overflow a label"});
}


// * * * * * * * * * * * * * * Reorder and remove * * * * * * * * * * * * * //

TEST(particleBody, reorderKeepsIdsWithTheirParticles)
{
    particleBody body = taggedBody(50);
    std::vector<label> order(50);
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), std::mt19937(3));
    const std::vector<label> oldIds = body.id();

    body.reorder(order);
    for (label i = 0; i < 50; ++i)
    {
        EXPECT_EQ(body.id()[i], oldIds[order[i]]);
    }
    expectTagged(body);
    EXPECT_EQ(body.nextId(), 50);
}


TEST(particleBody, reorderLargeBody)
{
    // Large enough for the OpenMP gather.
    const label n = 300000;
    particleBody body = taggedBody(n);
    std::vector<label> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), std::mt19937(5));
    body.reorder(order);
    for (label i = 0; i < n; i += 997)
    {
        EXPECT_EQ(body.id()[i], order[i]);
    }
    expectTagged(body);
}


TEST(particleBody, reorderRejectsNonPermutations)
{
    particleBody body = taggedBody(4);
    expectMessage(catchFatal([&]{ body.reorder({0, 1, 2}); }),
        {"reorder with 3 indices for 4 particles"});
    expectMessage(catchFatal([&]{ body.reorder({0, 1, 1, 3}); }),
        {"reorder index 1 at 2 is repeated", "permutation of 0..3"});
    expectMessage(catchFatal([&]{ body.reorder({0, 1, 4, 3}); }),
        {"reorder index 4 at 2 is out of range"});
    expectMessage(catchFatal([&]{ body.reorder({-1, 1, 2, 3}); }),
        {"out of range"});
    // Nothing moved.
    EXPECT_EQ(body.id(), (std::vector<label>{0, 1, 2, 3}));
    expectTagged(body);
}


TEST(particleBody, removeKeepsIdsWithTheirParticles)
{
    particleBody body = taggedBody(10);
    std::vector<label> order(10);
    std::iota(order.rbegin(), order.rend(), 0);
    body.reorder(order);

    std::vector<char> flags(10, 0);
    for (label i = 0; i < 10; ++i)
    {
        flags[i] = body.id()[i] % 3 == 0;
    }
    EXPECT_EQ(body.remove(flags), 4);
    EXPECT_EQ(body.size(), 6);
    EXPECT_EQ(body.id(), (std::vector<label>{8, 7, 5, 4, 2, 1}));
    expectTagged(body);
    for (const auto& f : body.fieldNames())
    {
        const std::size_t n = body.kindOf(f) == fieldKind::scalarField
            ? body.scalarField(f).size()
            : particleBody::isPointField(f) ? body.position().size()
            : body.kindOf(f) == fieldKind::vectorField
            ? body.vectorField(f).size() : body.labelField(f).size();
        EXPECT_EQ(n, 6u) << f;
    }

    // Removed ids are not reused.
    EXPECT_EQ(body.nextId(), 10);
    body.append({0, 0, 0});
    EXPECT_EQ(body.id().back(), 10);

    EXPECT_EQ(body.remove(std::vector<char>(7, 0)), 0);
    EXPECT_EQ(body.remove(std::vector<char>(7, 1)), 7);
    EXPECT_EQ(body.size(), 0);
    expectMessage(catchFatal([&]{ body.remove({1}); }),
        {"remove with 1 flags for 0 particles"});
}
