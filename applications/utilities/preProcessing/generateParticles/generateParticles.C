/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// generateParticles: fills the bodies of system/generateParticlesDict (fluid,
// wall and solid, from boxes, spheres, cylinders, containers and closed STL
// surfaces) with particles on a lattice of spacing dp and writes them to
// 0/<body>/.

#include "argList.H"
#include "error.H"
#include "particleGenerator.H"

#include <iostream>

using namespace sphvcpm;

int main(int argc, char* argv[])
{
    return runGuarded([&]()
    {
        argList args("generateParticles",
            "Generate the particles of fluid, wall and solid bodies from"
            " system/generateParticlesDict");
        args.addOption("dict", "file",
            "read this dictionary instead of system/generateParticlesDict"
            " (relative to the case)");
        args.addNote("Writes 0/<body>/{position,U,rho,mass,id,bodyProperties}"
            " (0/ is replaced);\nwriteFormat and writePrecision come from"
            " system/controlDict when it has them.");
        if (!args.parse(argc, argv))
        {
            return 0;
        }
        args.printBanner();

        const std::string dictFile =
            args.optionOrDefault("dict", "system/generateParticlesDict");
        std::cout << "Reading " << dictFile << "\n" << std::endl;
        particleGenerator generator(args.casePath(), dictFile);

        generator.generate();
        generator.printSummary(std::cout);

        std::cout << "\nWriting 0" << std::endl;
        generator.write();

        std::cout << "\n" << executionTimeLine() << "\n\nEnd\n" << std::endl;
        return 0;
    });
}
