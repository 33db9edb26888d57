/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// The VCPM solid against analysis (docs/vcpm.md, Model and Tests):
// constants and bad input, bond counts, force = -dU/dx by finite
// differences, momentum conservation, rigid rotation, the affine patch test
// (energy and virial stress equal their continuum values for each
// admissible nu), serial = OpenMP, and bounded energy at the stable time
// step, and a clamped column relaxed under gravity with damping.

#include "error.H"
#include "vcpmBeam.H"
#include "vcpmSolid.H"
#include "../testPrecision.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

using namespace sphvcpm;

namespace
{

// * * * * * * * * * * * * * * * * Helpers  * * * * * * * * * * * * * * * * //

std::vector<point> block(const int nx, const int ny, const int nz,
                         const scalar l0)
{
    std::vector<point> X;
    for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
    {
        X.push_back({i*l0, j*l0, k*l0});
    }
    return X;
}

void perturb(std::vector<point>& x, const scalar amplitude, const int nDim,
             const unsigned seed)
{
    std::mt19937 gen(seed);
    std::uniform_real_distribution<scalar> u(-amplitude, amplitude);
    for (point& p : x)
    {
        p.x += u(gen);
        p.y += u(gen);
        if (nDim == 3) p.z += u(gen);
    }
}

// A solid of nx x ny (x nz) particles, spacing l0.
vcpmSolid makeSolid(const vcpmMaterial& m, const int nx, const int ny,
                    const int nz)
{
    return vcpmSolid(m, block(nx, ny, m.nDim() == 3 ? nz : 1, m.l0));
}

vcpmMaterial material(const vcpmLattice lattice, const planeModel plane,
                      const scalar nu, const scalar l0 = 0.01,
                      const bool surface = false)
{
    vcpmMaterial m(2e6, nu, 1100, lattice, l0, plane, 0.1);
    m.surfaceCorrection = surface;
    return m;
}

const vcpmLattice sq = vcpmLattice::square2D;
const vcpmLattice sc = vcpmLattice::simpleCubic3D;
const planeModel pStress = planeModel::planeStress;
const planeModel pStrain = planeModel::planeStrain;

scalar maxMag(const std::vector<vec3>& f)
{
    scalar m = 0;
    for (const vec3& v : f) m = std::max(m, mag(v));
    return m;
}

// Continuum stress C:eps of the material (2D: the in-plane components).
stressTensor hooke(const vcpmMaterial& m, const scalar e[3][3])
{
    const scalar mu = m.E/(2*(1 + m.nu));
    scalar lambda = m.E*m.nu/((1 + m.nu)*(1 - 2*m.nu));
    scalar tr = e[0][0] + e[1][1] + e[2][2];
    if (m.nDim() == 2)
    {
        tr = e[0][0] + e[1][1];
        if (m.plane == pStress) lambda = m.E*m.nu/(1 - m.nu*m.nu);
    }
    stressTensor s{lambda*tr + 2*mu*e[0][0], 2*mu*e[0][1], 2*mu*e[0][2],
                   lambda*tr + 2*mu*e[1][1], 2*mu*e[1][2],
                   lambda*tr + 2*mu*e[2][2]};
    if (m.nDim() == 2)
    {
        s.xz = s.yz = s.zz = 0;
    }
    return s;
}

scalar maxAbs(const stressTensor& s)
{
    return std::max({std::abs(s.xx), std::abs(s.xy), std::abs(s.xz),
                     std::abs(s.yy), std::abs(s.yz), std::abs(s.zz)});
}

stressTensor minus(const stressTensor& a, const stressTensor& b)
{
    return {a.xx - b.xx, a.xy - b.xy, a.xz - b.xz,
            a.yy - b.yy, a.yz - b.yz, a.zz - b.zz};
}

// Particles at least two lattice steps from every face: their bonds and
// their partners' bonds are complete.
std::vector<label> interior(const vcpmSolid& s)
{
    point lo = s.reference()[0], hi = lo;
    for (const point& p : s.reference())
    {
        for (int d = 0; d < 3; ++d)
        {
            lo[d] = std::min(lo[d], p[d]);
            hi[d] = std::max(hi[d], p[d]);
        }
    }
    const scalar l0 = s.material().l0;
    std::vector<label> in;
    for (label p = 0; p < s.size(); ++p)
    {
        bool deep = true;
        for (int d = 0; d < s.material().nDim(); ++d)
        {
            const point& X = s.reference()[p];
            deep = deep && X[d] > lo[d] + 1.5*l0 && X[d] < hi[d] - 1.5*l0;
        }
        if (deep) in.push_back(p);
    }
    return in;
}

struct latticeCase
{
    vcpmLattice lattice;
    planeModel plane;
    scalar nu;
    bool surface = false;       // surface correction
};

// The largest difference between the solid's forces at its current
// positions and -dU/dx by central differences of step 1e-6 l0, relative
// to the largest force.
scalar forceGradientError(vcpmSolid& s, const scalar l0, const int nDim)
{
    s.computeForces(serialExec{});
    const std::vector<vec3> f = s.force;
    const scalar h = 1e-6*l0;
    scalar maxErr = 0;
    for (label p = 0; p < s.size(); ++p)
    {
        for (int d = 0; d < nDim; ++d)
        {
            const scalar x0 = s.position[p][d];
            s.position[p][d] = x0 + h;
            const scalar Up = s.elasticEnergy(serialExec{});
            s.position[p][d] = x0 - h;
            const scalar Um = s.elasticEnergy(serialExec{});
            s.position[p][d] = x0;
            maxErr = std::max(maxErr, std::abs(-(Up - Um)/(2*h) - f[p][d]));
        }
    }
    return maxErr/maxMag(f);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Material * * * * * * * * * * * * * * * * //

TEST(vcpmMaterial, closedFormsMatchCubicMapping)
{
    // docs/vcpm.md, Model: k1 = (C11 - C12)/2, k2 = C44/2,
    // T = (C12 - C44)/12 (square, times t); R (C11 - C12 - C44), R C44,
    // R (C12 - C44)/18 (SC).
    for (const scalar nu : {-0.3, 0.0, 0.25, 0.3, 0.45, 0.49})
    {
        for (const planeModel pl : {pStress, pStrain})
        {
            const vcpmMaterial m = material(sq, pl, nu);
            const scalar t = m.thickness;
            const scalar rel = test::tol(1e-12, 1e-6);
            EXPECT_NEAR(m.k1, t*(m.C11 - m.C12)/2, rel*m.k1);
            EXPECT_NEAR(m.k2, t*m.C44/2, rel*m.k2);
            EXPECT_NEAR(m.T, t*(m.C12 - m.C44)/12, rel*m.k1);
        }
        const vcpmMaterial m = material(sc, pStrain, nu);
        const scalar R = m.l0/2;
        const scalar rel = test::tol(1e-12, 1e-6);
        EXPECT_NEAR(m.k1, R*(m.C11 - m.C12 - m.C44), rel*m.k1);
        EXPECT_NEAR(m.k2, R*m.C44, rel*m.k2);
        EXPECT_NEAR(m.T, R*(m.C12 - m.C44)/18, rel*m.k1);
    }
}

TEST(vcpmMaterial, stableStepAndMass)
{
    const vcpmMaterial m = material(sc, pStrain, 0.3);
    EXPECT_SCALAR_EQ(m.mass, 1100*1e-6);
    const scalar cp = std::sqrt(m.E*0.7/(1.3*0.4*1100));
    EXPECT_NEAR(m.stableTimeStep(), 0.5*0.01/cp, test::tol(1e-15, 1e-11));
    const vcpmMaterial p = material(sq, pStress, 0.3);
    EXPECT_NEAR(p.pWaveSpeed, std::sqrt(2e6/(1 - 0.09)/1100),
                test::tol(1e-12, 1e-4));
    EXPECT_SCALAR_EQ(p.mass, 1100*1e-4*0.1);
}

// Near nu = 0.5 the lattice damping governs the stable step: a perturbed
// plane-strain block at nu = 0.49999 with the default damping stays
// bounded at vcpmSolid::stableTimeStep and blows up at the undamped
// C_s l0/c_p (the step the solver took before, which stopped the run in
// its first steps). Far from 0.5 the two steps are one.
TEST(vcpmSolid, stableStepWithLatticeDampingNearIncompressible)
{
    SPHVCPM_DOUBLE_ONLY();
    const auto maxSpeed = [](const scalar nu, const bool dampedStep)
    {
        const vcpmMaterial m = material(sq, pStrain, nu);
        vcpmSolid s = makeSolid(m, 8, 8, 1);
        s.latticeDamping = 0.02;
        perturb(s.position, 1e-4*m.l0, 2, 3);
        const scalar dt =
            dampedStep ? s.stableTimeStep() : m.stableTimeStep();
        s.computeForces(openmpExec{});
        scalar most = 0;
        for (int n = 0; n < 2000; ++n)
        {
            s.step(openmpExec{}, dt);
            for (const vec3& u : s.velocity)
            {
                most = std::isfinite(mag(u)) ? std::max(most, mag(u))
                                             : vGreat;
            }
        }
        return most;
    };
    const vcpmMaterial nearHalf = material(sq, pStrain, 0.49999);
    const scalar cp = nearHalf.pWaveSpeed;
    // Bounded: below the speed a strain of the perturbation gives, c_p e.
    EXPECT_LT(maxSpeed(0.49999, true), 1e-4*cp);
    EXPECT_GT(maxSpeed(0.49999, false), 1e3*cp);
    for (const scalar nu : {0.0, 0.3, 0.49})
    {
        const vcpmMaterial m = material(sq, pStrain, nu);
        vcpmSolid s = makeSolid(m, 4, 4, 1);
        s.latticeDamping = 0.02;
        EXPECT_EQ(s.stableTimeStep(), m.stableTimeStep()) << nu;
    }
}

TEST(vcpmMaterial, badInputNamesTheKeyword)
{
    auto keywordOf = [](auto make) -> std::string
    {
        try { make(); }
        catch (const FatalError& e) { return e.keyword(); }
        return "none";
    };
    EXPECT_EQ(keywordOf([]{ material(sc, pStrain, 0.5); }), "nu");
    EXPECT_EQ(keywordOf([]{ material(sc, pStrain, -0.5); }), "nu");
    EXPECT_EQ(keywordOf([]{ material(sq, pStrain, 0.55); }), "nu");
    EXPECT_EQ(keywordOf([]{ material(sq, pStress, -0.4); }), "nu");
    EXPECT_EQ(keywordOf([]{ material(sq, pStress, -0.3); }), "none");
    EXPECT_EQ(keywordOf([]{ material(sc, pStrain, -0.45); }), "none");
    EXPECT_EQ(keywordOf([]{ vcpmMaterial(0, 0.3, 1000, sc, 0.01); }), "E");
    EXPECT_EQ(keywordOf([]{ vcpmMaterial(1e6, 0.3, -1, sc, 0.01); }), "rho");
    EXPECT_EQ(keywordOf([]{ vcpmMaterial(1e6, 0.3, 1, sc, 0); }), "dp");
    EXPECT_EQ(keywordOf([]{ vcpmMaterial::latticeNamed("hex"); }), "lattice");
}


// * * * * * * * * * * * * * * * * Bond list  * * * * * * * * * * * * * * * //

TEST(vcpmBondList, countsPerLayer)
{
    const scalar l0 = 0.01;
    const bondList b3(block(5, 5, 5, l0), l0);
    const label centre = 2 + 5*2 + 25*2;
    EXPECT_EQ(b3.nBondsOf(centre, 0), 6);
    EXPECT_EQ(b3.nBondsOf(centre, 1), 12);
    EXPECT_EQ(b3.nBondsOf(0, 0), 3);
    EXPECT_EQ(b3.nBondsOf(0, 1), 3);
    // 3 axes x 4 x 5 x 5 layer-1; 3 planes x 2 diagonals x 4 x 4 x 5 layer-2.
    EXPECT_EQ(b3.nBonds(), 300 + 480);
    EXPECT_TRUE(b3.withoutSecondLayer().empty());

    const bondList b2(block(4, 3, 1, l0), l0);
    EXPECT_EQ(b2.nBondsOf(1 + 4, 0), 4);
    EXPECT_EQ(b2.nBondsOf(1 + 4, 1), 4);
    EXPECT_EQ(b2.nBonds(), (3*3 + 4*2) + 2*3*2);
    for (label k = 0; k < b2.nBonds(); ++k)
    {
        EXPECT_LT(b2.first()[k], b2.second()[k]);
    }

    // A single row has no diagonals: too thin.
    const bondList row(block(6, 1, 1, l0), l0);
    EXPECT_EQ(label(row.withoutSecondLayer().size()), 6);
}

TEST(vcpmBondList, rejectsOverlappingParticles)
{
    std::vector<point> X = block(3, 3, 1, 0.01);
    X.push_back({0.001, 0, 0});
    EXPECT_THROW(bondList(X, 0.01), FatalError);
}


// * * * * * * * * * * * * * * * * * Forces * * * * * * * * * * * * * * * * //

class vcpmLatticeCases : public ::testing::TestWithParam<latticeCase> {};

TEST_P(vcpmLatticeCases, forceIsMinusEnergyGradient)
{
    // Strains of 1e-6 to 1e-3 on positions of order 1: float resolves
    // only eps |x|/l0 ~ 1e-5 of strain (docs/solver.md, Precision).
    SPHVCPM_DOUBLE_ONLY();
    const latticeCase c = GetParam();
    const vcpmMaterial m = material(c.lattice, c.plane, c.nu, 0.01, c.surface);
    vcpmSolid s = makeSolid(m, 5, 4, 4);
    perturb(s.position, 0.05*m.l0, m.nDim(), 7);
    const scalar rel = forceGradientError(s, m.l0, m.nDim());
    std::printf("force vs -dU/dx: max relative error %.2e\n", rel);
    EXPECT_LT(rel, 1e-8);
}

TEST_P(vcpmLatticeCases, momentumConserved)
{
    const latticeCase c = GetParam();
    const vcpmMaterial m = material(c.lattice, c.plane, c.nu, 0.01, c.surface);
    vcpmSolid s = makeSolid(m, 6, 5, 4);
    perturb(s.position, 0.05*m.l0, m.nDim(), 11);
    s.computeForces(openmpExec{});
    vec3 F{0, 0, 0}, M{0, 0, 0};
    scalar scaleF = 0, scaleM = 0;
    for (label p = 0; p < s.size(); ++p)
    {
        F += s.force[p];
        M += cross(toVec3(s.position[p]), s.force[p]);
        scaleF += mag(s.force[p]);
        scaleM += mag(s.position[p])*mag(s.force[p]);
    }
    std::printf("|sum f|/sum|f| = %.1e, |sum x x f|/sum|x||f| = %.1e\n",
                mag(F)/scaleF, mag(M)/scaleM);
    EXPECT_LT(mag(F), test::tol(1e-14, 1e-6)*scaleF);
    EXPECT_LT(mag(M), test::tol(1e-14, 1e-6)*scaleM);
}

TEST_P(vcpmLatticeCases, rigidRotationIsStressFree)
{
    // Strains of 1e-6 to 1e-3 on positions of order 1: float resolves
    // only eps |x|/l0 ~ 1e-5 of strain (docs/solver.md, Precision).
    SPHVCPM_DOUBLE_ONLY();
    const latticeCase c = GetParam();
    const vcpmMaterial m = material(c.lattice, c.plane, c.nu, 0.01, c.surface);
    vcpmSolid s = makeSolid(m, 5, 4, 4);
    // 90 degrees about z (2D) or about (1, 1, 1)/sqrt(3) (3D), plus a shift.
    for (point& x : s.position)
    {
        if (m.nDim() == 2) x = point{-x.y, x.x, 0} + point{0.3, -0.2, 0};
        else
        {
            const point n{1/std::sqrt(3.0), 1/std::sqrt(3.0), 1/std::sqrt(3.0)};
            x = dot(n, x)*n + cross(n, x) + point{0.3, -0.2, 0.1};
        }
    }
    s.computeForces(serialExec{});
    std::vector<stressTensor> sigma;
    s.stress(serialExec{}, sigma);
    scalar maxS = 0;
    for (const stressTensor& t : sigma) maxS = std::max(maxS, maxAbs(t));
    // Scales: the force of a 1 % bond strain, the stress E.
    std::printf("rotation: max|f|/(k1 l0) = %.1e, max|sigma|/E = %.1e\n",
                maxMag(s.force)/(m.k1*m.l0), maxS/m.E);
    EXPECT_LT(maxMag(s.force), 1e-10*m.k1*m.l0);
    EXPECT_LT(maxS, 1e-10*m.E);
}

TEST_P(vcpmLatticeCases, serialEqualsOpenMP)
{
    const latticeCase c = GetParam();
    const vcpmMaterial m = material(c.lattice, c.plane, c.nu, 0.01, c.surface);
    vcpmSolid a = makeSolid(m, 9, 8, 7);
    perturb(a.position, 0.02*m.l0, m.nDim(), 3);
    vcpmSolid b = a;
    a.computeForces(serialExec{});
    b.computeForces(openmpExec{});
    for (label p = 0; p < a.size(); ++p)
    {
        ASSERT_EQ(a.force[p], b.force[p]);
    }
}


// * * * * * * * * * * * * * * * Patch test * * * * * * * * * * * * * * * * //

// Affine strain of the whole block: every interior particle has the energy
// density 1/2 eps:C:eps and the virial stress C:eps (docs/vcpm.md, Model;
// Choices, Stress).
TEST_P(vcpmLatticeCases, affineStrainGivesContinuumStressAndEnergy)
{
    // Strains of 1e-6 to 1e-3 on positions of order 1: float resolves
    // only eps |x|/l0 ~ 1e-5 of strain (docs/solver.md, Precision).
    SPHVCPM_DOUBLE_ONLY();
    const latticeCase c = GetParam();
    const vcpmMaterial m = material(c.lattice, c.plane, c.nu, 0.01, c.surface);
    vcpmSolid s = makeSolid(m, 7, 7, 7);
    const scalar a = 1e-8;
    scalar e[3][3] = {{3*a, 1.5*a, -a}, {1.5*a, -2*a, 0.5*a}, {-a, 0.5*a, a}};
    if (m.nDim() == 2)
    {
        e[0][2] = e[1][2] = e[2][0] = e[2][1] = e[2][2] = 0;
    }
    for (label p = 0; p < s.size(); ++p)
    {
        const point X = s.reference()[p];
        for (int i = 0; i < 3; ++i)
        {
            s.position[p][i] = X[i] + e[i][0]*X.x + e[i][1]*X.y + e[i][2]*X.z;
        }
    }
    std::vector<stressTensor> sigma;
    s.stress(serialExec{}, sigma);
    const stressTensor exact = hooke(m, e);
    const elasticEnergyOp energy{s.bonds().view(), s.constants(),
                                 s.position.data(), s.stretchSum.data()};
    scalar W = 0;    // 1/2 sigma:eps
    W += 0.5*(exact.xx*e[0][0] + exact.yy*e[1][1] + exact.zz*e[2][2]);
    W += exact.xy*e[0][1] + exact.xz*e[0][2] + exact.yz*e[1][2];

    scalar errS = 0, errW = 0;
    const std::vector<label> in = interior(s);
    ASSERT_FALSE(in.empty());
    for (const label p : in)
    {
        errS = std::max(errS, maxAbs(minus(sigma[p], exact))/maxAbs(exact));
        errW = std::max(errW, std::abs(energy(p)/m.cellVolume - W)/W);
    }
    std::printf("affine strain nu = %g: stress error %.1e, energy error %.1e\n",
                c.nu, errS, errW);
    EXPECT_LT(errS, 1e-6);
    EXPECT_LT(errW, 1e-6);
}

// Uniaxial stress as an affine state: the lateral strain -nu eps (3D, plane
// stress) or -nu/(1 - nu) eps (plane strain) leaves the lateral stresses
// zero and sigma_xx = E' eps, E' = E or E/(1 - nu^2).
TEST_P(vcpmLatticeCases, uniaxialStressPoissonContraction)
{
    // Strains of 1e-6 to 1e-3 on positions of order 1: float resolves
    // only eps |x|/l0 ~ 1e-5 of strain (docs/solver.md, Precision).
    SPHVCPM_DOUBLE_ONLY();
    const latticeCase c = GetParam();
    const vcpmMaterial m = material(c.lattice, c.plane, c.nu, 0.01, c.surface);
    vcpmSolid s = makeSolid(m, 7, 7, 7);
    const scalar eps = 1e-8;
    const bool strain2D = m.nDim() == 2 && m.plane == pStrain;
    const scalar lateral = strain2D ? -m.nu/(1 - m.nu)*eps : -m.nu*eps;
    const scalar Eeff = strain2D ? m.E/(1 - m.nu*m.nu) : m.E;
    for (label p = 0; p < s.size(); ++p)
    {
        const point X = s.reference()[p];
        s.position[p] = {X.x*(1 + eps), X.y*(1 + lateral),
                         X.z*(1 + (m.nDim() == 3 ? lateral : 0))};
    }
    std::vector<stressTensor> sigma;
    s.stress(serialExec{}, sigma);
    scalar errAxial = 0, errLateral = 0;
    const std::vector<label> in = interior(s);
    ASSERT_FALSE(in.empty());
    for (const label p : in)
    {
        errAxial = std::max(errAxial, std::abs(sigma[p].xx/(Eeff*eps) - 1));
        errLateral = std::max({errLateral, std::abs(sigma[p].yy/sigma[p].xx),
                               std::abs(sigma[p].zz/sigma[p].xx)});
    }
    std::printf("uniaxial nu = %g: sigma_xx error %.1e, lateral/axial %.1e\n",
                c.nu, errAxial, errLateral);
    EXPECT_LT(errAxial, 1e-6);
    EXPECT_LT(errLateral, 1e-6);
}


// * * * * * * * * * * * * * * * Time stepping  * * * * * * * * * * * * * * //

// A free block, randomly displaced, run 2000 undamped steps at the formula's
// step. The plain energy K + U of velocity Verlet oscillates (by about 15 %
// here, the random start excites the highest modes); the quantity the scheme
// conserves on a linear system is H = K + U - dt^2/8 sum |f|^2/m, which
// must not move by more than 1e-6 (strains of 1e-6 keep the geometric
// nonlinearity below that).
TEST_P(vcpmLatticeCases, energyBoundedAtStableStep)
{
    // Strains of 1e-6 to 1e-3 on positions of order 1: float resolves
    // only eps |x|/l0 ~ 1e-5 of strain (docs/solver.md, Precision).
    SPHVCPM_DOUBLE_ONLY();
    const latticeCase c = GetParam();
    const vcpmMaterial m = material(c.lattice, c.plane, c.nu, 0.01, c.surface);
    vcpmSolid s = makeSolid(m, 8, 6, 5);
    perturb(s.position, 1e-6*m.l0, m.nDim(), 5);
    const scalar dt = m.stableTimeStep();
    auto energies = [&](scalar& plain, scalar& shadow)
    {
        scalar f2 = 0;
        for (const vec3& f : s.force) f2 += magSqr(f);
        plain = s.kineticEnergy() + s.elasticEnergy(openmpExec{});
        shadow = plain - dt*dt/(8*m.mass)*f2;
    };
    s.computeForces(openmpExec{});
    scalar E0, H0;
    energies(E0, H0);
    scalar maxE = 0, maxH = 0;
    for (int n = 1; n <= 2000; ++n)
    {
        s.step(openmpExec{}, dt);
        scalar E, H;
        energies(E, H);
        maxE = std::max(maxE, std::abs(E - E0)/E0);
        maxH = std::max(maxH, std::abs(H - H0)/H0);
    }
    std::printf("dt = %.3e: max |E - E0|/E0 = %.2e, max |H - H0|/H0 = %.2e\n",
                dt, maxE, maxH);
    EXPECT_LT(maxE, 0.25);
    EXPECT_LT(maxH, 1e-6);
}

// Lattice damping (bondForceOp): a free block whose particles move in a
// checkerboard (the highest mode of the first-neighbour chains, omega =
// 2 omega_s, omega_s = sqrt(2 k1/m)) loses its energy at least at the
// ratio zeta in the bulk: e^{-4 zeta omega_s t} = 0.04 of it is left
// after omega_s t = 40 at zeta = 0.02; the faces' particles have one bond
// across and half the damping, which leaves about 0.09 in this block of 8
// rows. Undamped it keeps it (H, the energy that velocity Verlet
// conserves). Momentum is kept exactly, and a rigid
// rotation gives no damping force.
TEST_P(vcpmLatticeCases, latticeDampingTakesTheHighestMode)
{
    SPHVCPM_DOUBLE_ONLY();
    const latticeCase c = GetParam();
    const vcpmMaterial m = material(c.lattice, c.plane, c.nu, 0.01, c.surface);
    const scalar omegaS = std::sqrt(2*m.k1/m.mass);
    auto checkerboard = [&](const scalar zeta, scalar& left, vec3& momentum)
    {
        vcpmSolid s = makeSolid(m, 10, 8, 6);
        s.latticeDamping = zeta;
        for (label p = 0; p < s.size(); ++p)
        {
            const point X = s.reference()[p]/double(m.l0);
            const long parity = std::lround(X.x + X.y + X.z) % 2;
            s.velocity[p].y = parity ? 1e-3 : -1e-3;
        }
        const scalar dt = m.stableTimeStep();
        auto shadow = [&]()
        {
            scalar f2 = 0;
            for (const vec3& f : s.force) f2 += magSqr(f);
            return s.kineticEnergy() + s.elasticEnergy(openmpExec{})
                 - dt*dt/(8*m.mass)*f2;
        };
        s.computeForces(openmpExec{});
        const scalar H0 = shadow();
        const long nSteps = std::lround(40/omegaS/dt);
        for (long n = 0; n < nSteps; ++n) s.step(openmpExec{}, dt);
        left = shadow()/H0;
        momentum = {0, 0, 0};
        for (const vec3& v : s.velocity) momentum += m.mass*v;
    };
    scalar undamped, damped;
    vec3 p0, p1;
    checkerboard(0, undamped, p0);
    checkerboard(0.02, damped, p1);
    std::printf("checkerboard after omega_s t = 40: energy left %.6f "
                "undamped, %.3e with lattice damping 0.02\n", undamped,
                damped);
    EXPECT_NEAR(undamped, 1, 1e-6);
    EXPECT_LT(damped, 0.1);
    // Damping forces cancel pairwise: the momentum is the undamped run's.
    const scalar particles = m.nDim() == 3 ? 480 : 80;
    EXPECT_LT(mag(p1 - p0), 1e-12*particles*m.mass*1e-3);

    // A rigid rotation (about z, plus a translation) and its velocity:
    // the forces equal those at rest to round-off.
    vcpmSolid s = makeSolid(m, 5, 4, 4);
    s.latticeDamping = 0.02;
    perturb(s.position, 0.05*m.l0, m.nDim(), 3);
    s.computeForces(serialExec{});
    const std::vector<vec3> atRest = s.force;
    const vec3 w{0, 0, 50};
    for (label p = 0; p < s.size(); ++p)
    {
        s.velocity[p] = cross(w, toVec3(s.position[p])) + vec3{0.1, -0.2, 0};
    }
    s.computeForces(serialExec{});
    scalar diff = 0;
    for (label p = 0; p < s.size(); ++p)
    {
        diff = std::max(diff, mag(s.force[p] - atRest[p]));
    }
    std::printf("rigid rotation: max |f - f_rest|/max|f_rest| = %.1e\n",
                diff/maxMag(atRest));
    EXPECT_LT(diff, 1e-10*maxMag(atRest));
}

// The collapse check (collapsedBondOp): no bond of a strained lattice is
// flagged; a particle pushed most of the way onto its neighbour is, by the
// bond between them.
TEST_P(vcpmLatticeCases, collapsedBondIsFound)
{
    const latticeCase c = GetParam();
    const vcpmMaterial m = material(c.lattice, c.plane, c.nu, 0.01, c.surface);
    vcpmSolid s = makeSolid(m, 5, 4, 3);
    perturb(s.position, 0.1*m.l0, m.nDim(), 7);
    const bondView b = s.bonds().view();
    auto first = [&]()
    {
        return parallelReduce(serialExec{}, b.nBonds,
            collapsedBondOp{b, s.position.data(), 0.25}, b.nBonds, minOp());
    };
    EXPECT_EQ(first(), b.nBonds);
    // Particle 1 to within 0.2 l0 of particle 0 (its neighbour along x).
    s.position[1] = s.position[0] + vec3{0.2*m.l0, 0, 0};
    const label k = first();
    ASSERT_LT(k, b.nBonds);
    EXPECT_EQ(std::min(b.first[k], b.second[k]), 0);
    EXPECT_EQ(std::max(b.first[k], b.second[k]), 1);
}

// Clamps, gravity and damping: a plane-strain column with nu = 0, its two
// bottom layers clamped, relaxes under its own weight to the top
// displacement of the discrete chain, rho g l0^2 N (N + 1)/(2 E) for N free
// layers, within 1 % (measured -0.73 %: the free sides are slightly soft,
// docs/vcpm.md, Tests). The chain formula is the plain lattice's, so the
// surface correction is off here (with it the mirror-weighted top face
// makes the column 1.2 % stiffer than the chain; it is no longer a chain).
TEST(vcpmSolid, dampedColumnUnderGravity)
{
    vcpmMaterial m(1e6, 0.0, 1000, sq, 0.01, pStrain, 1);
    m.surfaceCorrection = false;
    const std::vector<point> X = block(6, 22, 1, m.l0);
    std::vector<std::uint8_t> clamps(X.size());
    for (std::size_t p = 0; p < X.size(); ++p) clamps[p] = X[p].y < 1.5*m.l0;
    vcpmSolid s(m, X, clamps);
    const int N = 20;
    s.gravity = {0, -9.81, 0};
    // About critical damping of the first mode, omega1 = pi c/(2 H).
    const scalar H = N*m.l0;
    s.damping = 2*M_PI*std::sqrt(m.E/m.rho)/(2*H);
    const scalar dt = m.stableTimeStep(0.3);
    s.computeForces(openmpExec{});
    for (int n = 0; n < 20000; ++n)
    {
        s.step(openmpExec{}, dt);
    }
    scalar uTop = 0, maxV = 0;
    label nTop = 0;
    for (label p = 0; p < s.size(); ++p)
    {
        maxV = std::max(maxV, mag(s.velocity[p]));
        if (s.reference()[p].y > (N + 0.5)*m.l0)
        {
            uTop += s.position[p].y - s.reference()[p].y;
            ++nTop;
        }
        if (s.clamped()[p])
        {
            ASSERT_EQ(s.position[p], s.reference()[p]);
        }
    }
    uTop /= nTop;
    const scalar exact = -m.rho*9.81*m.l0*m.l0*N*(N + 1)/(2*m.E);
    std::printf("column: u_top = %.5e, chain %.5e, error %.2e, max |v| %.1e\n",
                uTop, exact, uTop/exact - 1, maxV);
    EXPECT_NEAR(uTop/exact, 1, 0.01);
}

// * * * * * * * * * * * * * * * *  Clamps * * * * * * * * * * * * * * * * //

// A clamp vector of the wrong size is an error naming both sizes, with the
// surface correction on (the bond list's clamp roots) and off (the bonds
// never see the clamps; the step reads one flag per particle).
TEST(vcpmSolid, wrongClampCountIsFatal)
{
    for (const bool surface : {false, true})
    {
        SCOPED_TRACE(surface ? "surface correction on" : "off");
        const vcpmMaterial m = material(sq, pStrain, 0.3, 0.01, surface);
        const std::vector<point> X = block(4, 3, 1, m.l0);
        const std::vector<std::uint8_t> clamps(X.size() - 1, 1);
        try
        {
            vcpmSolid s(m, X, clamps);
            ADD_FAILURE() << "no error for 11 clamp flags on 12 particles";
        }
        catch (const FatalError& e)
        {
            EXPECT_NE(e.message().find("11 clamp flags for 12 particles"),
                      std::string::npos) << e.message();
        }
        // No flags: none clamped; one per particle: taken as given.
        EXPECT_EQ(vcpmSolid(m, X).clamped(),
                  std::vector<std::uint8_t>(X.size(), 0));
        std::vector<std::uint8_t> some(X.size(), 0);
        some[0] = some[4] = 1;
        EXPECT_EQ(vcpmSolid(m, X, some).clamped(), some);
    }
    // The bond list says what it got and what it expected.
    const std::vector<point> X = block(4, 3, 1, 0.01);
    try
    {
        const std::function<scalar(label)> gammaOf =
            [](label) { return scalar(0.2); };
        bondList(X, 0.01, gammaOf, std::vector<std::uint8_t>(5, 0));
        ADD_FAILURE() << "no error for 5 clamp flags on 12 particles";
    }
    catch (const FatalError& e)
    {
        EXPECT_NE(e.message().find("got 5 clamp flags, expected 12"),
                  std::string::npos) << e.message();
    }
}

namespace
{

// A block of nx x ny (x nz) particles with the two columns x < 1.5 l0
// clamped (a slab in 3D).
std::vector<std::uint8_t> clampedSlab(const std::vector<point>& X,
                                      const scalar l0)
{
    return clampedBehind(X, 1.5*l0);
}

} // End anonymous namespace

// bondList::correctClampRoots, against the same bond list without clamps:
// on a bond from a clamped to a free particle the free end's weight doubles
// (2, or 4 where the free particle is also a surface end of the bond, its
// mirror weight), the clamped end's is 0 and the pair factor doubles; every
// other bond is unchanged, the surface shifts included.
TEST(vcpmClampRoots, weightsAndPairFactors)
{
    const scalar l0 = 0.01;
    // gamma grows with the layers, so that the shifts differ bond to bond.
    // (A std::function: a bare lambda would also convert to the bool of
    // the other constructor.)
    const std::function<scalar(label)> gammaOf =
        [](const label n) { return scalar(0.05*n); };
    for (const int nz : {1, 4})
    {
        SCOPED_TRACE(nz == 1 ? "2D" : "3D");
        const std::vector<point> X = block(5, 4, nz, l0);
        const std::vector<std::uint8_t> clamps = clampedSlab(X, l0);
        const bondList plain(X, l0, gammaOf, std::vector<std::uint8_t>{});
        const bondList b(X, l0, gammaOf, clamps);
        ASSERT_EQ(b.nBonds(), plain.nBonds());
        label nRoots = 0, nFour = 0;
        for (label k = 0; k < b.nBonds(); ++k)
        {
            ASSERT_EQ(b.first()[k], plain.first()[k]);
            ASSERT_EQ(b.second()[k], plain.second()[k]);
            const bool ci = clamps[b.first()[k]], cj = clamps[b.second()[k]];
            if (ci == cj)
            {
                EXPECT_EQ(b.weight()[2*k], plain.weight()[2*k]) << k;
                EXPECT_EQ(b.weight()[2*k + 1], plain.weight()[2*k + 1]) << k;
                EXPECT_EQ(b.pairFactor()[k], plain.pairFactor()[k]) << k;
                continue;
            }
            ++nRoots;
            const std::size_t freeEnd = 2*std::size_t(k) + (ci ? 1 : 0);
            const std::size_t clampedEnd = 2*std::size_t(k) + (ci ? 0 : 1);
            const scalar w0 = plain.weight()[freeEnd];
            ASSERT_TRUE(w0 == 1 || w0 == 2) << k;
            EXPECT_EQ(b.weight()[freeEnd], 2*w0) << k;
            EXPECT_EQ(b.weight()[clampedEnd], 0) << k;
            EXPECT_EQ(b.pairFactor()[k], 2*plain.pairFactor()[k]) << k;
            nFour += w0 == 2;
        }
        // Between the columns x = 1 and 2: the layer-1 bonds along x, one
        // per row, and 2 (ny - 1) diagonals per xy plane (and per xz plane
        // in 3D).
        const label rows = 4*nz;
        const label diagonals = 2*3*nz + (nz > 1 ? 2*(nz - 1)*4 : 0);
        EXPECT_EQ(nRoots, rows + diagonals);
        // The diagonals onto a free particle of an outer face (y or z at
        // the block's end) have no opposite bond there: weight 4.
        EXPECT_GT(nFour, 0);
    }
}

// With the clamp roots the forces are still -dU/dx (weights 0 and 4 and
// the doubled pair factors included), and a rigid translation and rotation
// of the whole body, clamps moved with it, gives no force.
TEST(vcpmClampRoots, forceIsMinusEnergyGradientAndRigidMotionIsFree)
{
    // Strains of 1e-6 to 1e-3 on positions of order 1: float resolves
    // only eps |x|/l0 ~ 1e-5 of strain (docs/solver.md, Precision).
    SPHVCPM_DOUBLE_ONLY();
    for (const vcpmLattice lat : {sq, sc})
    {
        SCOPED_TRACE(lat == sc ? "3D" : "2D");
        const vcpmMaterial m = material(lat, pStrain, 0.3, 0.01, true);
        const std::vector<point> X =
            block(5, 4, m.nDim() == 3 ? 4 : 1, m.l0);
        vcpmSolid s(m, X, clampedSlab(X, m.l0));
        const vcpmSolid plain(m, X);
        label roots = 0;
        for (label k = 0; k < s.bonds().nBonds(); ++k)
        {
            roots += s.bonds().pairFactor()[k]
                  != plain.bonds().pairFactor()[k];
        }
        ASSERT_GT(roots, 0);

        perturb(s.position, 0.05*m.l0, m.nDim(), 17);
        const scalar rel = forceGradientError(s, m.l0, m.nDim());
        std::printf("clamp roots, %s: force vs -dU/dx max relative error "
                    "%.2e\n", lat == sc ? "3D" : "2D", rel);
        EXPECT_LT(rel, 1e-8);

        // 90 degrees about z (2D) or about (1, 1, 1)/sqrt(3) (3D), plus a
        // shift, of every particle, the clamped ones too.
        for (label p = 0; p < s.size(); ++p)
        {
            const point x = X[p];
            if (m.nDim() == 2) s.position[p] = point{-x.y, x.x, 0}
                                             + point{0.3, -0.2, 0};
            else
            {
                const scalar c = 1/std::sqrt(3.0);
                const point n{c, c, c};
                s.position[p] = dot(n, x)*n + cross(n, x)
                              + point{0.3, -0.2, 0.1};
            }
        }
        s.computeForces(serialExec{});
        std::printf("clamp roots, %s: rigid motion max|f|/(k1 l0) = %.1e\n",
                    lat == sc ? "3D" : "2D", maxMag(s.force)/(m.k1*m.l0));
        EXPECT_LT(maxMag(s.force), 1e-10*m.k1*m.l0);
    }
}

// Issue 4's patch test on the default path (surface correction on): a free
// 2D block, 40 x 8 particles, pulled by a uniform traction sigma0 on its
// two end columns (force sigma0 l0 t per particle) and relaxed with
// damping. Over its middle half (every particle, the free faces included)
// the virial stress must be uniform, sigma_xx = sigma0 and sigma_yy =
// sigma_xy = 0 within 1 % of sigma0, and the strains those of uniaxial
// stress within 1 %: eps_xx = sigma0/E', Poisson contraction -eps_yy/eps_xx
// = nu (plane stress) or nu/(1 - nu) (plane strain). Without the
// correction (printed only) the faces are soft and the stress is not
// uniform.
namespace
{

struct tensionResult
{
    bool converged;
    int steps;
    scalar stressError, axialError, poissonError;
};

tensionResult uniformTension(const scalar nu, const planeModel plane,
                             const bool surface)
{
    const int nx = 40, ny = 8;
    vcpmMaterial m(2e6, nu, 1000, sq, 0.01, plane, 1);
    m.surfaceCorrection = surface;
    vcpmSolid s(m, block(nx, ny, 1, m.l0));
    const scalar sigma0 = 1e-6*m.E;
    const scalar Lx = (nx - 1)*m.l0;
    for (label p = 0; p < s.size(); ++p)
    {
        const long i = std::lround(s.reference()[p].x/m.l0);
        if (i == 0) s.externalForce[p].x = -sigma0*m.l0*m.thickness;
        if (i == nx - 1) s.externalForce[p].x = sigma0*m.l0*m.thickness;
    }
    // Critical damping of the first free-free axial mode.
    s.damping = 2*M_PI*m.pWaveSpeed/Lx;
    const scalar dt = m.stableTimeStep(0.5);
    s.computeForces(serialExec{});
    tensionResult r{false, 0, 0, 0, 0};
    for (int it = 0; it < 100000 && !r.converged; ++it)
    {
        s.step(serialExec{}, dt);
        r.steps = it + 1;
        if (it % 500 == 499)
        {
            scalar vMax = 0;
            for (const vec3& v : s.velocity) vMax = std::max(vMax, mag(v));
            // 1e-7 of the velocity scale of the strain, eps c (round-off
            // in the bond lengths is about 1e-9 of the strain).
            r.converged = vMax < 1e-7*sigma0/m.E*m.pWaveSpeed;
        }
    }
    std::vector<stressTensor> sigma;
    s.stress(serialExec{}, sigma);

    const bool strain2D = plane == pStrain;
    const scalar Eb = strain2D ? m.E/(1 - nu*nu) : m.E;
    const scalar nuP = strain2D ? nu/(1 - nu) : nu;
    const scalar xc = 0.5*Lx;
    // Mean displacements: of columns i1, i2 (x) and of the top and bottom
    // rows over the middle half (y).
    const long i1 = nx/4, i2 = nx - 1 - nx/4;
    scalar u1 = 0, u2 = 0, top = 0, bottom = 0;
    label n1 = 0, n2 = 0, nTop = 0, nBottom = 0;
    for (label p = 0; p < s.size(); ++p)
    {
        const point& X = s.reference()[p];
        const vec3 u = toVec3(s.position[p] - X);
        const long i = std::lround(X.x/m.l0), j = std::lround(X.y/m.l0);
        if (i == i1) { u1 += u.x; ++n1; }
        if (i == i2) { u2 += u.x; ++n2; }
        if (std::abs(X.x - xc) > 0.25*Lx) continue;
        r.stressError = std::max({r.stressError,
            std::abs(sigma[p].xx/sigma0 - 1), std::abs(sigma[p].yy/sigma0),
            std::abs(sigma[p].xy/sigma0)});
        if (j == ny - 1) { top += u.y; ++nTop; }
        if (j == 0) { bottom += u.y; ++nBottom; }
    }
    const scalar epsXX = (u2/n2 - u1/n1)/((i2 - i1)*m.l0);
    const scalar epsYY = (top/nTop - bottom/nBottom)/((ny - 1)*m.l0);
    r.axialError = epsXX/(sigma0/Eb) - 1;
    r.poissonError = nu > 0 ? -epsYY/epsXX/nuP - 1 : epsYY/epsXX;
    return r;
}

} // End anonymous namespace

TEST(vcpmSolid, uniformTensionPatch)
{
    // Strains of 1e-6 to 1e-3 on positions of order 1: float resolves
    // only eps |x|/l0 ~ 1e-5 of strain (docs/solver.md, Precision).
    SPHVCPM_DOUBLE_ONLY();
    for (const planeModel plane : {pStrain, pStress})
    {
        for (const scalar nu : {0.0, 0.25, 0.3, 0.45, 0.49})
        {
            const tensionResult on = uniformTension(nu, plane,
                vcpmMaterial::defaultSurfaceCorrection);
            const tensionResult off = uniformTension(nu, plane, false);
            std::printf("uniform tension, %s, nu = %g (%d steps): stress "
                "%.1e, eps_xx %+.1e, Poisson %+.1e (surface correction on); "
                "%.1e, %+.1e, %+.1e (off)\n",
                plane == pStrain ? "plane strain" : "plane stress", nu,
                on.steps,
                on.stressError, on.axialError, on.poissonError,
                off.stressError, off.axialError, off.poissonError);
            EXPECT_TRUE(on.converged);
            EXPECT_LT(on.stressError, 0.01);
            EXPECT_LT(std::abs(on.axialError), 0.01);
            EXPECT_LT(std::abs(on.poissonError), 0.01);
        }
    }
}

INSTANTIATE_TEST_SUITE_P
(
    lattices, vcpmLatticeCases,
    ::testing::Values
    (
        latticeCase{sc, pStrain, 0.0}, latticeCase{sc, pStrain, 0.25},
        latticeCase{sc, pStrain, 0.3}, latticeCase{sc, pStrain, 0.45},
        latticeCase{sc, pStrain, 0.49},
        latticeCase{sq, pStrain, 0.0}, latticeCase{sq, pStrain, 0.25},
        latticeCase{sq, pStrain, 0.3}, latticeCase{sq, pStrain, 0.45},
        latticeCase{sq, pStrain, 0.49},
        latticeCase{sq, pStress, 0.0}, latticeCase{sq, pStress, 0.25},
        latticeCase{sq, pStress, 0.3}, latticeCase{sq, pStress, 0.45},
        latticeCase{sq, pStress, 0.49}
    )
);


// Static cantilever, STATIC_CANTILEVER.md set A: L = 0.2, H = 0.02,
// E = 2 MPa, nu = 0.3975, self-weight at g = 0.0981, two columns clamped in
// the support, relaxed with damping (critical for the first bending mode)
// until max |v| < 1e-9 m/s. Returns the centreline deflection of the tip
// column (x = L - l0/2; mean of the column).
namespace
{

struct cantileverSetA
{
    static constexpr scalar L = 0.2, H = 0.02, g = 0.0981;
    scalar nu;      // set A's 0.3975 unless given
    vcpmMaterial m;
    scalar w = 0, vMax = 0;

    cantileverSetA(const int n, const planeModel plane, const bool surface,
                   const scalar poisson = 0.3975)
    :
        nu(poisson),
        m(2e6, nu, 1000, sq, H/n, plane, 1)
    {
        m.surfaceCorrection = surface;
        const scalar l0 = m.l0;
        const std::vector<point> X =
            cantileverLattice(label(std::lround(L/l0)), n, 2, l0);
        vcpmSolid s(m, X, clampedBehind(X));
        s.gravity = {0, -g, 0};
        const scalar omega1 = 1.8751*1.8751/(L*L)*std::sqrt(EI()/(m.rho*H));
        s.damping = 2*omega1;
        const scalar dt = m.stableTimeStep(0.5);
        s.computeForces(openmpExec{});
        for (int it = 0; it < 200000; ++it)
        {
            s.step(openmpExec{}, dt);
            if (it % 1000 == 999)
            {
                vMax = 0;
                for (const vec3& v : s.velocity) vMax = std::max(vMax, mag(v));
                if (vMax < 1e-9) break;
            }
        }
        label nTip = 0;
        for (label p = 0; p < s.size(); ++p)
        {
            if (s.reference()[p].x > L - l0)
            {
                w += s.position[p].y - s.reference()[p].y;
                ++nTip;
            }
        }
        w /= nTip;
    }

    scalar Eb() const
    {
        return m.plane == pStrain ? m.E/(1 - nu*nu) : m.E;
    }
    scalar EI() const { return Eb()*H*H*H/12; }
    scalar kGA() const { return 5.0/6.0*m.E/(2*(1 + nu))*H; }
    scalar q() const { return -m.rho*g*H; }
    // Beam theory at x (kGA <= 0: Euler-Bernoulli).
    scalar beam(const scalar x, const bool shear) const
    {
        return cantileverDeflection(x, L, q(), EI(), shear ? kGA() : 0);
    }
    scalar xTip() const { return L - 0.5*m.l0; }
};

} // End anonymous namespace

// Issue 4's check on the default path (surface correction on): the tip
// deflection of set A within 3 % of the reference's Timoshenko value, in
// plane strain (the reference's 2D default) and plane stress, at H/l0 = 5
// (measured -0.04 % plane strain, +0.07 % plane stress since the shift is
// calibrated at the member's thickness and the clamp roots are corrected;
// +2.19 % before). Checked twice: against Timoshenko at the tip column's x
// (the strict comparison, here within 0.5 %) and the tip column against
// the tabulated w_tip at x = L (STATIC_CANTILEVER_REFERENCE.csv; the
// column sits l0/2 inside the tip, 1.3 % short of it). No stiffness model
// enters.
TEST(vcpmSolid, staticCantileverSetA)
{
    // Strains of 1e-6 to 1e-3 on positions of order 1: float resolves
    // only eps |x|/l0 ~ 1e-5 of strain (docs/solver.md, Precision).
    SPHVCPM_DOUBLE_ONLY();
    ASSERT_TRUE(vcpmMaterial::defaultSurfaceCorrection);
    const int n = 5;
    // STATIC_CANTILEVER.md set A, Timoshenko w_tip: plane strain, stress.
    const scalar reference[2] = {2.5109e-4, 2.9759e-4};
    for (const planeModel plane : {pStrain, pStress})
    {
        const cantileverSetA c(n, plane,
                               vcpmMaterial::defaultSurfaceCorrection);
        ASSERT_LT(c.vMax, 1e-9);
        const scalar ref = reference[plane == pStress];
        // Our beam formula reproduces the tabulated value at x = L.
        EXPECT_NEAR(-c.beam(c.L, true)/ref, 1, 2e-4);
        const scalar wT = c.beam(c.xTip(), true);
        std::printf("cantilever set A, n = %d, %s, surface correction on: "
                    "w = %.5e, Timoshenko at the tip column %.5e (%+.2f %%), "
                    "reference w_tip %.4e (%+.2f %%)\n", n,
                    plane == pStrain ? "plane strain" : "plane stress", c.w,
                    wT, 100*(c.w/wT - 1), -ref, 100*(-c.w/ref - 1));
        EXPECT_LT(std::abs(c.w/wT - 1), 0.005);
        EXPECT_LT(std::abs(-c.w/ref - 1), 0.03);
        // And the corrected error model (0.1/n^3 here): within 1 %.
        const scalar ratio = 1 + thinMemberStiffnessError(n, c.m);
        const scalar wB = c.beam(c.xTip(), false);
        EXPECT_NEAR(c.w/(wB/ratio + wT - wB), 1, 0.01);
    }
}

// The plain lattice (surfaceCorrection off) at the same 5 layers: 18.7 %
// too soft against Timoshenko (docs/vcpm.md, Static cantilever and thin
// members; the static CG solve of benchmarks/vcpmThinMembers gives the
// same), and its error model thinMemberStiffnessError(off) puts the
// deflection within 1 % (measured +0.39 %).
TEST(vcpmSolid, staticCantileverSetAUncorrected)
{
    // Strains of 1e-6 to 1e-3 on positions of order 1: float resolves
    // only eps |x|/l0 ~ 1e-5 of strain (docs/solver.md, Precision).
    SPHVCPM_DOUBLE_ONLY();
    const int n = 5;
    const cantileverSetA c(n, pStrain, false);
    ASSERT_LT(c.vMax, 1e-9);
    const scalar wB = c.beam(c.xTip(), false), wT = c.beam(c.xTip(), true);
    const scalar ratio = wB/(c.w - (wT - wB));
    const scalar predicted = 1 + thinMemberStiffnessError(n, c.m);
    const scalar wCorrected = wB/predicted + (wT - wB);
    std::printf("cantilever n = %d, surface correction off: w = %.5e, "
                "Timoshenko %.5e (%+.2f %%), EI ratio %.4f, predicted %.4f, "
                "w/(predicted) %+.2f %%\n", n, c.w, wT, 100*(c.w/wT - 1),
                ratio, predicted, 100*(c.w/wCorrected - 1));
    // A regression pin of the plain lattice's measured softness (docs/
    // vcpm.md), then the physics check: corrected by the error model, the
    // deflection is beam theory's.
    EXPECT_NEAR(c.w/wT - 1, 0.1866, 0.005);
    EXPECT_NEAR(c.w/wCorrected, 1, 0.01);
}

// The error models (docs/vcpm.md). Off: too soft, less so with more
// layers; two table values; 18 layers for 5 % at nu = 0.3 plane stress.
// On: the envelope a/n^3 of the measured errors (within 0.3 % from n = 3
// in plane stress and plane strain to nu = 0.4: a = 0.1, 3 layers for
// 1 %); plane strain 0.45: 1.8 % at n = 3 (a = 0.5: 3 layers for 3 %, 4
// for 1 %); 0.49: 23 % at 3, 10 % at 4, 3 % at 5 (a = 8.1: 6 for 5 %, 7
// for 3 %).
TEST(vcpmSolid, thinMemberStiffnessError)
{
    // Strains of 1e-6 to 1e-3 on positions of order 1: float resolves
    // only eps |x|/l0 ~ 1e-5 of strain (docs/solver.md, Precision).
    SPHVCPM_DOUBLE_ONLY();
    for (const bool surface : {false, true})
    {
        scalar last = -1;
        for (const int n : {2, 3, 4, 6, 8, 12, 16, 32})
        {
            const scalar e = thinMemberStiffnessError(n, 0.3, pStress, surface);
            EXPECT_LT(e, 0);
            EXPECT_GT(e, last);
            last = e;
        }
        EXPECT_EQ(thinMemberStiffnessError(1, 0.3, pStress, surface), -1);
    }
    // Regression pins: the fit against two measured rows of docs/vcpm.md
    // (EI_lattice/EI of the plain lattice, vcpmThinMembers), so that a
    // change of the fit's constants shows.
    EXPECT_NEAR(thinMemberStiffnessError(4, 0.3, pStress, false),
                0.7632 - 1, 0.005);
    EXPECT_NEAR(thinMemberStiffnessError(8, 0.0, pStress, false),
                0.9517 - 1, 0.005);
    EXPECT_EQ(minimumLayers(0.05, 0.3, pStress, false), 18);

    for (const scalar nu : {0.0, 0.3, 0.3975, 0.45, 0.49})
    {
        for (const planeModel pl : {pStress, pStrain})
        {
            if (pl == pStrain && nu > 0.4) continue;
            EXPECT_NEAR(thinMemberStiffnessError(3, nu, pl, true), 0,
                        0.004);
            EXPECT_NEAR(thinMemberStiffnessError(5, nu, pl, true), 0,
                        0.001);
            EXPECT_EQ(minimumLayers(0.01, nu, pl, true), 3);
        }
    }
    EXPECT_EQ(minimumLayers(0.03, 0.45, pStrain, true), 3);
    EXPECT_EQ(minimumLayers(0.01, 0.45, pStrain, true), 4);
    EXPECT_EQ(minimumLayers(0.05, 0.49, pStrain, true), 6);
    EXPECT_EQ(minimumLayers(0.03, 0.49, pStrain, true), 7);
    // Covers what was measured (benchmarks/vcpmThinMembers, set A).
    EXPECT_LT(thinMemberStiffnessError(3, 0.45, pStrain, true), -0.018);
    EXPECT_LT(thinMemberStiffnessError(3, 0.47, pStrain, true), -0.053);
    EXPECT_LT(thinMemberStiffnessError(4, 0.48, pStrain, true), -0.0275);
    EXPECT_LT(thinMemberStiffnessError(3, 0.49, pStrain, true), -0.23);
    EXPECT_LT(thinMemberStiffnessError(4, 0.49, pStrain, true), -0.102);

    // Two layers with the correction: the model is the lattice's measured
    // EI ratio, soft (-44 % at nu = 0.3 plane strain) but stiff near
    // incompressibility in plane strain (+37 % at 0.47, x3.5 at 0.49).
    // Checked against the lattice itself: the cantilever relaxed here.
    for (const auto& [nu, pl] : std::vector<std::pair<scalar, planeModel>>{
             {0.3, pStrain}, {0.47, pStrain}, {0.3, pStress}})
    {
        const cantileverSetA c(2, pl, true, nu);
        ASSERT_LT(c.vMax, 1e-9);
        const scalar wB = c.beam(c.xTip(), false);
        const scalar wT = c.beam(c.xTip(), true);
        const scalar measured = wB/(c.w - (wT - wB));
        const scalar model = 1 + thinMemberStiffnessError(2, nu, pl, true);
        std::printf("two layers, nu = %.2f, %s: EI ratio %.4f, model %.4f\n",
                    nu, pl == pStrain ? "plane strain" : "plane stress",
                    measured, model);
        EXPECT_NEAR(measured/model, 1, 0.02);
    }
    EXPECT_GT(thinMemberStiffnessError(2, 0.47, pStrain, true), 0.3);
    EXPECT_LT(thinMemberStiffnessError(2, 0.3, pStrain, true), -0.4);

    // The material overloads follow its flag.
    vcpmMaterial m(2e6, 0.3, 1000, sq, 0.01, pStrain, 1);
    EXPECT_TRUE(m.surfaceCorrection);
    EXPECT_EQ(thinMemberStiffnessError(5, m),
              thinMemberStiffnessError(5, 0.3, pStrain, true));
    m.surfaceCorrection = false;
    EXPECT_EQ(minimumLayers(0.05, m), minimumLayers(0.05, 0.3, pStrain, false));
}


// * * * * * * * * * * * * *  Surface correction  * * * * * * * * * * * * * //

// The force, momentum, rotation, patch and energy tests with the surface
// correction on (mirror weights and the second-moment shift at every face
// of the block).
INSTANTIATE_TEST_SUITE_P
(
    surfaceCorrected, vcpmLatticeCases,
    ::testing::Values
    (
        latticeCase{sc, pStrain, 0.0, true}, latticeCase{sc, pStrain, 0.25, true},
        latticeCase{sc, pStrain, 0.3, true}, latticeCase{sc, pStrain, 0.45, true},
        latticeCase{sc, pStrain, 0.49, true},
        latticeCase{sq, pStrain, 0.0, true}, latticeCase{sq, pStrain, 0.25, true},
        latticeCase{sq, pStrain, 0.3, true}, latticeCase{sq, pStrain, 0.45, true},
        latticeCase{sq, pStrain, 0.49, true},
        latticeCase{sq, pStress, 0.0, true}, latticeCase{sq, pStress, 0.25, true},
        latticeCase{sq, pStress, 0.3, true}, latticeCase{sq, pStress, 0.45, true},
        latticeCase{sq, pStress, 0.49, true}
    )
);

namespace
{

// Tip-column centreline deflection of the relaxed 2D cantilever of set A
// (L = 0.2, H = 0.02, E = 2 MPa, self-weight at g = 0.0981, plane strain,
// n layers, 2 clamped columns) over Timoshenko at that column's x, minus 1.
scalar cantileverError(const scalar nu, const int n, const bool surface)
{
    const scalar L = 0.2, H = 0.02, g = 0.0981;
    const scalar l0 = H/n;
    vcpmMaterial m(2e6, nu, 1000, sq, l0, pStrain, 1);
    m.surfaceCorrection = surface;
    const std::vector<point> X =
        cantileverLattice(label(std::lround(L/l0)), n, 2, l0);
    vcpmSolid s(m, X, clampedBehind(X));
    s.gravity = {0, -g, 0};
    const scalar EI = m.E/(1 - nu*nu)*H*H*H/12;
    s.damping = 2*1.8751*1.8751/(L*L)*std::sqrt(EI/(m.rho*H));
    const scalar dt = m.stableTimeStep(0.5);
    s.computeForces(openmpExec{});
    scalar vMax = 0;
    for (int it = 0; it < 200000; ++it)
    {
        s.step(openmpExec{}, dt);
        if (it % 1000 == 999)
        {
            vMax = 0;
            for (const vec3& v : s.velocity) vMax = std::max(vMax, mag(v));
            if (vMax < 1e-9) break;
        }
    }
    EXPECT_LT(vMax, 1e-9);
    scalar w = 0;
    label nTip = 0;
    for (label p = 0; p < s.size(); ++p)
    {
        if (s.reference()[p].x > L - l0)
        {
            w += s.position[p].y - s.reference()[p].y;
            ++nTip;
        }
    }
    w /= nTip;
    const scalar kGA = 5.0/6.0*m.E/(2*(1 + nu))*H;
    const scalar wT = cantileverDeflection(L - 0.5*l0, L, -m.rho*g*H, EI, kGA);
    return w/wT - 1;
}

} // End anonymous namespace

// The set-A geometry, plane strain, over the nu: with the
// correction at 5 layers within 1 % of Timoshenko (static solve of
// benchmarks/vcpmThinMembers: +0.07, +0.06, -0.06 % at nu = 0, 0.3, 0.45),
// and at 0.49, where the error model asks for 7 layers for 3 % (gamma
// floored at 0 at few layers; 5 layers -3.0 %, 6 -1.3 %), within 3 % at
// 7. Without the correction 10-24 % soft at nu <= 0.3 and 41 % stiff at
// 0.49.
TEST(vcpmSurfaceCorrection, cantileverFiveLayers)
{
    // Strains of 1e-6 to 1e-3 on positions of order 1: float resolves
    // only eps |x|/l0 ~ 1e-5 of strain (docs/solver.md, Precision).
    SPHVCPM_DOUBLE_ONLY();
    for (const scalar nu : {0.0, 0.25, 0.3, 0.45, 0.49})
    {
        const int n = nu < 0.46 ? 5 : 7;
        ASSERT_EQ(minimumLayers(nu < 0.46 ? 0.01 : 0.03, nu, pStrain, true),
                  nu < 0.46 ? (nu > 0.4 ? 4 : 3) : 7);
        const scalar on = cantileverError(nu, n, true);
        std::printf("cantilever n = %d, nu = %g, plane strain: %+.2f %% "
                    "against Timoshenko with the surface correction\n",
                    n, nu, 100*on);
        EXPECT_LT(std::abs(on), nu < 0.46 ? 0.01 : 0.03);
    }
}

// The calibration in 3D: a simple-cubic plate strip 5 layers thick, bent
// affinely (cylindrical bending, eps_zz = 0): with the correction the
// energy of its middle column is the continuum 1/2 E/(1 - nu^2) I k^2 (the
// shift is calibrated on a strip as thick as the member, found by the bond
// list), 10-16 % low without at nu = 0, 0.3 (+3 % at 0.45).
TEST(vcpmSurfaceCorrection, simpleCubicPlateStrip)
{
    // Strains of 1e-6 to 1e-3 on positions of order 1: float resolves
    // only eps |x|/l0 ~ 1e-5 of strain (docs/solver.md, Precision).
    SPHVCPM_DOUBLE_ONLY();
    const int nx = 5, ny = 5, nz = 5;
    for (const scalar nu : {0.0, 0.3, 0.45})
    {
        scalar ratio[2];
        for (const bool surface : {false, true})
        {
            const vcpmMaterial m = material(sc, pStrain, nu, 0.01, surface);
            vcpmSolid s(m, block(nx, ny, nz, m.l0));
            const scalar kappa = 1e-6/m.l0, nuP = nu/(1 - nu);
            const point c{nx/2*m.l0, 0.5*(ny - 1)*m.l0, nz/2*m.l0};
            for (label p = 0; p < s.size(); ++p)
            {
                const vec3 X = toVec3(s.reference()[p] - c);
                s.position[p] = s.reference()[p] + kappa*vec3{X.x*X.y,
                    -0.5*(X.x*X.x + nuP*X.y*X.y), 0};
            }
            s.elasticEnergy(serialExec{});
            const elasticEnergyOp U{s.bonds().view(), s.constants(),
                                    s.position.data(), s.stretchSum.data()};
            scalar sum = 0;
            for (label p = 0; p < s.size(); ++p)
            {
                const vec3 X = toVec3(s.reference()[p] - c);
                if (std::abs(X.x) + std::abs(X.z) < 0.1*m.l0) sum += U(p);
            }
            const scalar H = ny*m.l0;
            ratio[surface] = sum/(0.5*m.E/(1 - nu*nu)*H*H*H/12*kappa*kappa
                                  *m.l0*m.l0);
        }
        std::printf("3D plate strip n = 5, nu = %g: bending energy / "
                    "continuum %.4f (off), %.4f (on)\n", nu, ratio[0],
                    ratio[1]);
        EXPECT_NEAR(ratio[1], 1, 1e-6);
        EXPECT_LT(std::abs(ratio[1] - 1), std::abs(ratio[0] - 1));
    }
}

// The mirror weights alone (no shift): under a uniform strain every face
// particle of a free block has the bulk energy density (edges and corners
// also miss bond pairs, bond and opposite both, which no mirror restores).
TEST(vcpmSurfaceCorrection, uniformStrainEnergyOnFaces)
{
    // Strains of 1e-6 to 1e-3 on positions of order 1: float resolves
    // only eps |x|/l0 ~ 1e-5 of strain (docs/solver.md, Precision).
    SPHVCPM_DOUBLE_ONLY();
    for (const vcpmLattice lat : {sc, sq})
    {
        const vcpmMaterial m = material(lat, pStrain, 0.3, 0.01, true);
        vcpmSolid s = makeSolid(m, 6, 5, 4);
        const scalar a = 1e-8;
        const scalar e[3][3] = {{3*a, 1.5*a, lat == sc ? -a : 0},
                                {1.5*a, -2*a, lat == sc ? 0.5*a : 0},
                                {lat == sc ? -a : 0, lat == sc ? 0.5*a : 0,
                                 lat == sc ? a : 0}};
        for (label p = 0; p < s.size(); ++p)
        {
            const point X = s.reference()[p];
            for (int i = 0; i < 3; ++i)
            {
                s.position[p][i] =
                    X[i] + e[i][0]*X.x + e[i][1]*X.y + e[i][2]*X.z;
            }
        }
        const bondList b(s.reference(), m.l0, [](label) { return 0.0; }, {});
        parallelFor(serialExec{}, s.size(), stretchSumOp{b.view(),
            s.position.data(), s.stretchSum.data()});
        const elasticEnergyOp U{b.view(), s.constants(),
                                s.position.data(), s.stretchSum.data()};
        const stressTensor t = hooke(m, e);
        const scalar W = 0.5*(t.xx*e[0][0] + t.yy*e[1][1] + t.zz*e[2][2])
                       + t.xy*e[0][1] + t.xz*e[0][2] + t.yz*e[1][2];
        scalar err = 0;
        const int nd = m.nDim();
        const int size[3] = {6, 5, 4};
        for (label p = 0; p < s.size(); ++p)
        {
            int onBoundary = 0;
            for (int d = 0; d < nd; ++d)
            {
                const long i = std::lround(s.reference()[p][d]/m.l0);
                onBoundary += i == 0 || i == size[d] - 1;
            }
            if (onBoundary > 1) continue;
            err = std::max(err, std::abs(U(p)/m.cellVolume - W)/W);
        }
        std::printf("uniform strain, %s: max face particle energy error %.1e\n",
                    lat == sc ? "SC" : "square", err);
        EXPECT_LT(err, 1e-6);
    }
}
