#include "foamFile.H"
#include "primitives.H"
#include "version.H"

#include <ostream>

namespace sphvcpm
{

std::string archString()
{
    return "LSB;label=" + std::to_string(8*sizeof(label))
         + ";scalar=" + std::to_string(8*sizeof(fileScalar));
}

void writeFoamFileBanner(std::ostream& os)
{
    os  << "/*--------------------------------*- C++ -*----------------------------------*\\\n"
        << "  =========                 |\n"
        << "  \\\\      /  S PH           | sphvcpm: SPH-VCPM fluid-structure interaction\n"
        << "   \\\\    /   V CPM          | Version:  " << SPHVCPM_VERSION << "\n"
        << "    \\\\  /    F SI           |\n"
        << "     \\\\/     M esh-less     |\n"
        << "\\*---------------------------------------------------------------------------*/\n";
}

static void headerEntry(std::ostream& os, const std::string& key,
                        const std::string& value)
{
    os << "    " << key << std::string(key.size() < 12 ? 12 - key.size() : 1, ' ')
       << value << ";\n";
}

void writeFoamFileHeader(std::ostream& os, const foamFileHeader& header)
{
    writeFoamFileBanner(os);
    os << "FoamFile\n{\n";
    headerEntry(os, "version", "2.0");
    headerEntry(os, "format", header.format);
    headerEntry(os, "class", header.className);
    if (header.format == "binary")
    {
        headerEntry(os, "arch",
            "\"" + (header.arch.empty() ? archString() : header.arch) + "\"");
    }
    if (!header.location.empty())
    {
        headerEntry(os, "location", "\"" + header.location + "\"");
    }
    headerEntry(os, "object", header.object);
    os << "}\n"
       << "// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //\n\n";
}

void writeFoamFileEnd(std::ostream& os)
{
    os << "\n\n// ************************************************************************* //\n";
}

} // End namespace sphvcpm
