/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// vcpmThinMembers [-relax] [-3d] [-layers "2 4 8"]
//                 [-nu 0.3 -plane stress|strain] [-surface on|off|both]
//
// -3d: a simple-cubic beam of square section n x n (-plane is ignored),
// against Timoshenko with E and Cowper's shear coefficient.
//
// -surface: the surface correction of bondList.H (default both: each case
// without, then with; docs/vcpm.md "Surface correction"); with it the
// surface shift gamma of an n-layer member is printed (the correction also
// stiffens the bonds into the clamp: bondList.H, clamp roots) and "fit" is
// the corrected model of thinMemberStiffnessError. BEAM_L=0.8 in the
// environment makes the beam longer (L/H = 40) to separate the clamp root.
//
// Bending stiffness of the square VCPM lattice against the number of layers
// n through the thickness (docs/vcpm.md, Static cantilever and thin
// members), from the static tip deflection of the cantilever of
// STATIC_CANTILEVER.md set A (L = 0.2 m, H = 0.02 m, E = 2 MPa,
// rho = 1000, self-weight at g = 0.0981, l0 = H/n, 2 clamped columns in
// the support). The static state is solved by conjugate
// gradients with the lattice forces as the operator (the deflection is
// small enough, w/L ~ 1e-3, for the linear problem); -relax uses damped
// dynamic relaxation instead (much slower; a cross-check).
//
// Prints per n: the tip-column deflection, its error against Timoshenko
// (beam theory at the tip column's x), the bending-stiffness ratio
// EI_lattice/EI = w_bending/(w - w_shear), and the effective thickness
// deficit c in EI_lattice = E (n - c)^3 l0^3/12, with the ratio that
// thinMemberStiffnessError predicts ("fit"; "-" with -3d: that model is
// the square lattice's). A benchmark: nothing is asserted.

#include "vcpmBeam.H"
#include "vcpmSolid.H"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

using namespace sphvcpm;

namespace
{

const scalar L = std::getenv("BEAM_L") ? std::atof(std::getenv("BEAM_L")) : 0.2, H = 0.02, E = 2e6, rho = 1000, g = 0.0981;
const label nClamp = 2;

// Static displacement by CG on K u = m g; K v = -f(X + s v)/s with s so small
// (1e-7 l0) that the geometric nonlinearity is far below the tolerance.
int solveStatic(vcpmSolid& s, std::vector<vec3>& u)
{
    const label n = s.size();
    const scalar l0 = s.material().l0;
    const vec3 load = s.material().mass*vec3{0, -g, 0};
    s.gravity = {0, 0, 0};

    auto apply = [&](const std::vector<vec3>& v, std::vector<vec3>& Av)
    {
        scalar vMax = 0;
        for (const vec3& a : v) vMax = std::max(vMax, mag(a));
        const scalar h = vMax > 0 ? 1e-7*l0/vMax : 1;
        for (label p = 0; p < n; ++p)
        {
            s.position[p] = s.reference()[p] + h*v[p];
        }
        s.computeForces(openmpExec{});
        for (label p = 0; p < n; ++p)
        {
            Av[p] = s.clamped()[p] ? vec3{0, 0, 0} : -s.force[p]/h;
        }
    };
    auto dotAll = [&](const std::vector<vec3>& a, const std::vector<vec3>& b)
    {
        scalar d = 0;
        for (label p = 0; p < n; ++p) d += dot(a[p], b[p]);
        return d;
    };

    u.assign(n, vec3{0, 0, 0});
    std::vector<vec3> r(n), d(n), Ad(n);
    for (label p = 0; p < n; ++p)
    {
        r[p] = s.clamped()[p] ? vec3{0, 0, 0} : load;
    }
    d = r;
    const scalar rr0 = dotAll(r, r);
    scalar rr = rr0;
    int it = 0;
    for (; it < 200000 && rr > 1e-24*rr0; ++it)
    {
        apply(d, Ad);
        const scalar alpha = rr/dotAll(d, Ad);
        for (label p = 0; p < n; ++p)
        {
            u[p] += alpha*d[p];
            r[p] -= alpha*Ad[p];
        }
        const scalar rrNew = dotAll(r, r);
        for (label p = 0; p < n; ++p) d[p] = r[p] + (rrNew/rr)*d[p];
        rr = rrNew;
    }
    return it;
}

// Damped dynamic relaxation (the path the unit test takes): damping about
// critical for the first bending mode, run until max |v| < 1e-9 m/s.
int relax(vcpmSolid& s, std::vector<vec3>& u)
{
    const vcpmMaterial& m = s.material();
    // Bending modulus E' in both plane models: C11 - C12^2/C11.
    const scalar Eb = m.C11 - m.C12*m.C12/m.C11;
    const scalar omega1 =
        1.8751*1.8751/(L*L)*std::sqrt(Eb*H*H/(12*rho));
    s.gravity = {0, -g, 0};
    s.damping = 2*omega1;
    const scalar dt = m.stableTimeStep(0.5);
    s.computeForces(openmpExec{});
    int it = 0;
    for (; it < 5000000; ++it)
    {
        s.step(openmpExec{}, dt);
        if (it % 1000 == 0)
        {
            scalar vMax = 0;
            for (const vec3& v : s.velocity) vMax = std::max(vMax, mag(v));
            if (it > 0 && vMax < 1e-9) break;
        }
    }
    u = s.displacement();
    return it;
}

void run(const std::vector<int>& layers, const scalar nu,
         const planeModel plane, const bool dynamic, const bool surface,
         const bool threeD)
{
    std::printf("\nnu = %g, %s, %s, surface correction %s\n", nu,
        threeD ? "3D, square section n x n"
      : plane == planeModel::planeStress ? "plane stress" : "plane strain",
        dynamic ? "damped dynamic relaxation" : "static (CG)",
        surface ? "on" : "off");
    std::printf("| n | gamma | particles | iterations | w_tip (m) "
                "| Timoshenko (m) | error | EI_lattice/EI | fit | c | s |\n"
                "|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const int n : layers)
    {
        const scalar l0 = H/n;
        const label nL = label(std::lround(L/l0));
        vcpmMaterial m(E, nu, rho, threeD ? vcpmLattice::simpleCubic3D
                       : vcpmLattice::square2D, l0, plane, 1);
        m.surfaceCorrection = surface;
        std::vector<point> X = cantileverLattice(nL, n, nClamp, l0);
        if (threeD)
        {
            // n copies across z: a beam of square section.
            const std::vector<point> plane2D = X;
            X.clear();
            for (int k = 0; k < n; ++k)
            for (const point& p : plane2D)
            {
                X.push_back({p.x, p.y, (k + 0.5 - 0.5*n)*l0});
            }
        }
        vcpmSolid s(m, X, clampedBehind(X));
        const auto t0 = std::chrono::steady_clock::now();
        std::vector<vec3> u;
        const int it = dynamic ? relax(s, u) : solveStatic(s, u);
        const scalar sec = std::chrono::duration<scalar>
            (std::chrono::steady_clock::now() - t0).count();

        // Mean over the tip column = centreline deflection there.
        scalar w = 0;
        label nTip = 0;
        for (label p = 0; p < s.size(); ++p)
        {
            if (s.reference()[p].x > L - l0)
            {
                w += u[p].y;
                ++nTip;
            }
        }
        w /= nTip;

        // 3D: a beam of square section, E itself, Cowper's shear
        // coefficient 10 (1 + nu)/(12 + 11 nu); 2D: per unit depth.
        const scalar Eb = threeD || plane == planeModel::planeStress
            ? E : E/(1 - nu*nu);
        const scalar depth = threeD ? H : 1;
        const scalar EI = Eb*depth*H*H*H/12;
        const scalar kappa = threeD ? 10*(1 + nu)/(12 + 11*nu) : 5.0/6.0;
        const scalar kGA = kappa*E/(2*(1 + nu))*depth*H;
        const scalar q = -rho*g*depth*H;
        const scalar xTip = L - 0.5*l0;
        const scalar wB = cantileverDeflection(xTip, L, q, EI, 0);
        const scalar wT = cantileverDeflection(xTip, L, q, EI, kGA);
        const scalar ratio = wB/(w - (wT - wB));
        const scalar c = n*(1 - std::cbrt(ratio));
        // The error model is the square lattice's (2D): none for -3d.
        char fit[32] = "-";
        if (!threeD)
        {
            std::snprintf(fit, sizeof fit, "%.4f",
                1 + thinMemberStiffnessError(n, nu, plane, surface));
        }
        std::printf("| %d | %s | %ld | %d | %.5e | %.5e | %+.2f %% | %.4f "
                    "| %s | %.3f | %.1f |\n", n,
                    surface ? std::to_string(surfaceShift(m, n)).substr(0, 6)
                              .c_str() : "-",
                    long(s.size()), it, w, wT,
                    100*(w/wT - 1), ratio, fit, c, sec);
        std::fflush(stdout);
    }
}

} // End namespace


int main(int argc, char* argv[])
{
    bool dynamic = false, threeD = false;
    std::vector<bool> surfaces{false, true};
    std::vector<int> layers{2, 3, 4, 5, 6, 8, 10, 12, 16, 20};
    std::vector<std::pair<scalar, planeModel>> cases
    {
        {0.3, planeModel::planeStress}, {0.0, planeModel::planeStress},
        {0.3, planeModel::planeStrain}, {0.3975, planeModel::planeStrain}
    };
    bool caseGiven = false;
    // A benchmark of the lattice, not of a case: no -case, no banner; bad
    // arguments are named, never taken for something else.
    const char* usage =
        "usage: vcpmThinMembers [-relax] [-3d] [-layers \"2 4 8\"]"
        " [-nu NU [-plane stress|strain]]... [-surface on|off|both]\n"
        "Bending stiffness of the VCPM lattice against the number of layers"
        " (docs/vcpm.md, \"Static cantilever and thin members\").\n";
    auto bad = [&](const std::string& what)
    {
        std::fprintf(stderr, "vcpmThinMembers: %s\n%s", what.c_str(), usage);
        std::exit(1);
    };
    for (int i = 1; i < argc; ++i)
    {
        const std::string a = argv[i];
        const bool hasValue = i + 1 < argc;
        if (a == "-help" || a == "--help" || a == "-h")
        {
            std::printf("%s", usage);
            return 0;
        }
        else if (a == "-relax") dynamic = true;
        else if (a == "-3d") threeD = true;
        else if (a == "-surface" && hasValue)
        {
            const std::string v = argv[++i];
            if (v != "on" && v != "off" && v != "both")
            {
                bad("-surface " + v + ": expected on, off or both");
            }
            surfaces = v == "both" ? std::vector<bool>{false, true}
                                   : std::vector<bool>{v == "on"};
        }
        else if (a == "-layers" && hasValue)
        {
            layers.clear();
            std::istringstream is(argv[++i]);
            std::string word;
            while (is >> word)
            {
                char* end = nullptr;
                const long n = std::strtol(word.c_str(), &end, 10);
                if (*end != '\0' || n < 2 || n > 1000)
                {
                    bad("-layers: '" + word + "' is not a number of layers"
                        " from 2 to 1000");
                }
                layers.push_back(int(n));
            }
            if (layers.empty())
            {
                bad("-layers: no number of layers given");
            }
        }
        else if (a == "-nu" && hasValue)
        {
            if (!caseGiven) cases.clear();
            caseGiven = true;
            char* end = nullptr;
            const double nu = std::strtod(argv[++i], &end);
            if (*end != '\0' || !(nu > -1 && nu < 0.5))
            {
                bad(std::string("-nu ") + argv[i] + ": expected a Poisson"
                    " ratio in (-1, 0.5)");
            }
            cases.push_back({scalar(nu), planeModel::planeStress});
        }
        else if (a == "-plane" && hasValue)
        {
            const std::string v = argv[++i];
            if (!caseGiven)
            {
                bad("-plane " + v + " before any -nu: it sets the plane"
                    " model of the -nu before it");
            }
            if (v != "stress" && v != "strain")
            {
                bad("-plane " + v + ": expected stress or strain");
            }
            cases.back().second = v == "strain" ? planeModel::planeStrain
                                                : planeModel::planeStress;
        }
        else
        {
            bad("unknown option or missing value: '" + a + "'");
        }
    }
    std::printf("Cantilever L = %g m, H = %g m, E = %g Pa, rho = %g, g = %g, "
                "%ld clamped columns\n", L, H, E, rho, g, long(nClamp));
    for (const auto& c : cases)
    {
        for (const bool on : surfaces)
        {
            run(layers, c.first, c.second, dynamic, on, threeD);
        }
    }
    return 0;
}
