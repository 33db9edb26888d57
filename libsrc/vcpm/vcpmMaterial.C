/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
#include "vcpmMaterial.H"

#include "error.H"
#include "dictionary.H"

#include <cmath>
#include <sstream>

namespace sphvcpm
{

void vcpmMaterial::admissibleNu(const vcpmLattice lattice,
                                const planeModel plane, scalar& lower,
                                scalar& upper)
{
    // Lower bounds from k_L + N_L T_L > 0 (docs/vcpm.md, Choices); the
    // upper bound 1/2 is the continuum one (plane stress alone would allow
    // up to 1).
    upper = 0.5;
    lower = lattice == vcpmLattice::square2D
         && plane == planeModel::planeStress ? -1.0/3.0 : -0.5;
}


vcpmMaterial::vcpmMaterial(const scalar E_, const scalar nu_,
                           const scalar rho_, const vcpmLattice lattice_,
                           const scalar l0_, const planeModel plane_,
                           const scalar thickness_)
:
    E(E_), nu(nu_), rho(rho_), lattice(lattice_), plane(plane_), l0(l0_),
    thickness(thickness_)
{
    auto bad = [](const std::string& keyword, const scalar value,
                  const std::string& why)
    {
        std::ostringstream os;
        os << "VCPM solid: " << keyword << " = " << value << ' ' << why;
        throw FatalError(os.str(), "", 0, keyword);
    };

    if (!(E > 0)) bad("E", E, "must be positive");
    if (!(rho > 0)) bad("rho", rho, "must be positive");
    if (!(l0 > 0)) bad("dp", l0, "(particle spacing) must be positive");
    if (!(thickness > 0)) bad("thickness", thickness, "must be positive");

    scalar lower, upper;
    admissibleNu(lattice, plane, lower, upper);
    if (!(nu > lower && nu < upper))
    {
        std::ostringstream why;
        why << "is outside the admissible range (" << lower << ", " << upper
            << ") of the "
            << (lattice == vcpmLattice::square2D
                ? (plane == planeModel::planeStress
                   ? "square2D plane-stress" : "square2D plane-strain")
                : "simpleCubic3D")
            << " lattice (its springs need k + N T > 0; docs/vcpm.md, Choices)";
        bad("nu", nu, why.str());
    }

    const scalar mu = E/(2*(1 + nu));
    const bool planeStress =
        lattice == vcpmLattice::square2D && plane == planeModel::planeStress;
    if (planeStress)
    {
        C11 = E/(1 - nu*nu);
        C12 = nu*E/(1 - nu*nu);
    }
    else
    {
        C11 = E*(1 - nu)/((1 + nu)*(1 - 2*nu));
        C12 = E*nu/((1 + nu)*(1 - 2*nu));
    }
    C44 = mu;
    pWaveSpeed = std::sqrt(C11/rho);

    // Closed forms for isotropic materials (docs/vcpm.md, Model).
    if (lattice == vcpmLattice::square2D)
    {
        const scalar t = thickness;
        k1 = t*E/(2*(1 + nu));
        k2 = t*E/(4*(1 + nu));
        T = planeStress
          ? t*E*(3*nu - 1)/(24*(1 - nu*nu))
          : t*E*(4*nu - 1)/(24*(1 + nu)*(1 - 2*nu));
        cellVolume = l0*l0*t;
    }
    else
    {
        const scalar R = l0/2;
        k1 = E*R/(2*(1 + nu));
        k2 = k1;
        T = E*R*(4*nu - 1)/(36*(1 + nu)*(1 - 2*nu));
        cellVolume = l0*l0*l0;
    }
    mass = rho*cellVolume;
}


vcpmMaterial vcpmMaterial::read
(
    const dictionary& props,
    const std::string& solidName,
    const int nDimensions,
    const scalar rho,
    const scalar l0
)
{
    const std::string expected = nDimensions == 2 ? "square2D"
                                                  : "simpleCubic3D";
    const std::string latticeName =
        props.getWordOrDefault("lattice", {"simpleCubic3D", "square2D"},
                               expected);
    if (latticeName != expected)
    {
        props.fatalAt("lattice", "Keyword 'lattice': solid '" + solidName
            + "' is " + std::to_string(nDimensions) + "D, which needs"
              " lattice " + expected + ", not " + latticeName);
    }
    if (nDimensions == 3 && props.found("plane"))
    {
        props.fatalAt("plane", "Keyword 'plane': solid '" + solidName
            + "' is 3D; planeStress or planeStrain only closes a 2D lattice");
    }
    const std::string plane = props.getWordOrDefault("plane",
        {"planeStrain", "planeStress"}, "planeStrain");

    // Missing E or nu: the lookup's error names the file and keyword.
    const scalar E = props.getDimensioned<scalar>("E", dimensions::pressure());
    const scalar nu = props.get<scalar>("nu");
    const bool surface = props.getOrDefault<bool>("surfaceCorrection",
                                                  defaultSurfaceCorrection);
    try
    {
        vcpmMaterial m(E, nu, rho, latticeNamed(latticeName), l0,
                       planeNamed(plane));
        m.surfaceCorrection = surface;
        return m;
    }
    catch (const FatalError& err)
    {
        // The constructor names the keyword; say which solid and where.
        const std::string key = err.keyword();
        props.fatalAt(props.found(key) ? key : "E", "Keyword '" + key
            + "' of solid '" + solidName + "': " + err.message());
    }
}


vcpmLattice vcpmMaterial::latticeNamed(const std::string& name)
{
    if (name == "square2D") return vcpmLattice::square2D;
    if (name == "simpleCubic3D") return vcpmLattice::simpleCubic3D;
    throw FatalError("VCPM solid: unknown lattice " + name
      + " (square2D or simpleCubic3D)", "", 0, "lattice");
}


planeModel vcpmMaterial::planeNamed(const std::string& name)
{
    if (name == "planeStress") return planeModel::planeStress;
    if (name == "planeStrain") return planeModel::planeStrain;
    throw FatalError("VCPM solid: unknown plane model " + name
      + " (planeStress or planeStrain)", "", 0, "plane");
}

} // End namespace sphvcpm
