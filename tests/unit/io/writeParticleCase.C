/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Test helper (not installed with the applications): writes time
// directories of a small known case through writeTimeDirectory, so the
// particlesToVTK script test needs neither generateParticles nor a solver.
//
// Bodies, with k the particle number and t the time:
//   water (fluid) nx x ny lattice: position ((i+1/2)dp, (j+1/2)dp - t, z),
//         U (k/1000, -t, 0), rho 1000 + k + t, p (k mod 7)/2 + t,
//         flag k mod 3, id k
//   tank (wall)   (nx + 6) x 3 below the water: position, rho 1000 + k, id k
// z is 0 in 2D and 0.1 + t in 3D; dp = 0.01; time index = round(t/0.001).
// checkVtk.py computes the same values.

#include "argList.H"
#include "error.H"
#include "timeDirectory.H"

#include <cmath>
#include <iostream>
#include <string>

using namespace sphvcpm;

namespace
{

constexpr scalar dp = 0.01;

particleBody water(label nx, label ny, int nDim, scalar t)
{
    particleBody body("water", bodyType::fluid, nDim, dp);
    body.resize(nx*ny);
    auto& U = body.addVectorField("U");
    auto& rho = body.addScalarField("rho");
    auto& p = body.addScalarField("p");
    auto& flag = body.addLabelField("flag");
    auto& position = body.position();
    auto& id = body.id();
    for (label k = 0; k < nx*ny; ++k)
    {
        const label i = k % nx, j = k / nx;
        position[k] = {(i + 0.5)*dp, (j + 0.5)*dp - t,
                       nDim == 3 ? 0.1 + t : 0.0};
        U[k] = {k/1000.0, -t, 0.0};
        rho[k] = 1000.0 + k + t;
        p[k] = (k % 7)/2.0 + t;
        flag[k] = k % 3;
        id[k] = k;
    }
    body.setNextId(nx*ny);
    return body;
}

particleBody tank(label nx, int nDim, scalar t)
{
    const label n = (nx + 6)*3;
    particleBody body("tank", bodyType::wall, nDim, dp);
    body.resize(n);
    auto& rho = body.addScalarField("rho");
    auto& position = body.position();
    auto& id = body.id();
    for (label k = 0; k < n; ++k)
    {
        const label i = k % (nx + 6), j = k / (nx + 6);
        position[k] = {(i - 2.5)*dp, (j - 2.5)*dp,
                       nDim == 3 ? 0.1 + t : 0.0};
        rho[k] = 1000.0 + k;
        id[k] = k;
    }
    body.setNextId(n);
    return body;
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    return runGuarded([&]()
    {
        argList args("writeParticleCase",
            "Test helper: write time directories of a known water + tank"
            " case");
        args.addOption("times", "list", "time names to write, e.g. '(0 0.1)'");
        args.addOption("nx", "n", "water particles along x (default 20)");
        args.addOption("ny", "n", "water particles along y (default 10)");
        args.addOption("nDimensions", "2|3", "default 2");
        args.addOption("format", "ascii|binary", "default binary");
        if (!args.parse(argc, argv))
        {
            return 0;
        }
        const label nx = std::stoi(args.optionOrDefault("nx", "20"));
        const label ny = std::stoi(args.optionOrDefault("ny", "10"));
        const int nDim = std::stoi(args.optionOrDefault("nDimensions", "2"));
        const writeFormat format =
            writeFormatFromName(args.optionOrDefault("format", "binary"));

        std::string list = args.optionOrDefault("times", "(0 0.1 0.2)");
        for (char& c : list)
        {
            if (c == '(' || c == ')' || c == ',')
            {
                c = ' ';
            }
        }
        std::size_t pos = 0;
        while ((pos = list.find_first_not_of(' ', pos)) != std::string::npos)
        {
            const std::size_t end = list.find(' ', pos);
            timeState state;
            state.name = list.substr(pos, end - pos);
            pos = end;
            state.value = std::stod(state.name);
            state.index = label(std::llround(state.value/0.001));
            state.deltaT = state.deltaT0 = 0.001;
            writeTimeDirectory(args.casePath(), state,
                {tank(nx, nDim, state.value), water(nx, ny, nDim,
                 state.value)}, format);
            std::cout << "wrote " << state.name << " (index " << state.index
                      << ")" << std::endl;
        }
        return 0;
    });
}
