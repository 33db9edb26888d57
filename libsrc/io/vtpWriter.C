/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// VTK XML PolyData and ParaView series writers (see vtpWriter.H).

#include "vtpWriter.H"
#include "error.H"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>
#include <type_traits>
#include <unistd.h>

namespace sphvcpm
{

// Values go to the file straight from the fields' memory, so the host byte
// order and the field layouts must be what the XML header announces.
static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "vtpWriter writes host memory as LittleEndian");
static_assert(sizeof(label) == 4, "label fields are written as Int32");
static_assert(sizeof(vec3) == 3*sizeof(scalar)
           && std::is_standard_layout<vec3>::value,
              "vector fields are written as 3 packed scalars");

// Fields and points as the build holds them: Float32 in a single-precision
// build (VTK files are for viewing, never read back).
static constexpr const char* scalarType =
    sizeof(scalar) == 8 ? "Float64" : "Float32";

namespace
{

// Elements per chunk where values are generated rather than copied (1 MiB
// of doubles), so memory stays flat whatever the body size.
constexpr std::size_t chunkSize = 131072;

// Writes through a hidden temporary file in the target directory and
// renames it into place: rename() within one file system is atomic.
void writeAtomic(const std::filesystem::path& file,
                 const std::function<void(std::ostream&)>& write)
{
    const std::filesystem::path tmp = file.parent_path()
        / ("." + file.filename().string() + ".tmp"
         + std::to_string(::getpid()));
    try
    {
        {
            std::ofstream os(tmp, std::ios::binary | std::ios::trunc);
            if (!os)
            {
                fatalError("Cannot open " + tmp.string() + " for writing: "
                    + std::strerror(errno));
            }
            write(os);
            os.flush();
            if (!os)
            {
                fatalError("Error writing " + tmp.string() + ": "
                    + std::strerror(errno) + " (disk full?)");
            }
        }
        std::error_code ec;
        std::filesystem::rename(tmp, file, ec);
        if (ec)
        {
            fatalError("Cannot rename " + tmp.string() + " to "
                + file.string() + ": " + ec.message());
        }
    }
    catch (...)
    {
        std::error_code ec;
        std::filesystem::remove(tmp, ec);
        throw;
    }
}

std::string xmlEscape(const std::string& s)
{
    std::string out;
    for (char c : s)
    {
        switch (c)
        {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

// One DataArray: its header attributes and how to write its values.
struct dataArray
{
    std::string name;
    std::string type;         // Float64 | Int32 | Int64
    int nComponents;
    std::uint64_t nBytes;
    std::function<void(std::ostream&)> writeValues;
    std::uint64_t offset = 0; // from the first byte after '_'
};

void writeRaw(std::ostream& os, const void* data, std::size_t nBytes)
{
    if (nBytes > 0)
    {
        os.write(static_cast<const char*>(data), std::streamsize(nBytes));
    }
}

template<class T>
dataArray directArray(const std::string& name, const std::string& type,
                      int nComponents, const std::vector<T>& values)
{
    const std::uint64_t nBytes = values.size()*sizeof(T);
    return {name, type, nComponents, nBytes,
        [&values, nBytes](std::ostream& os)
        {
            writeRaw(os, values.data(), nBytes);
        }};
}

void writeDataArrayTag(std::ostream& os, const dataArray& a,
                       const std::string& indent)
{
    os << indent << "<DataArray type=\"" << a.type << "\" Name=\""
       << xmlEscape(a.name) << "\" NumberOfComponents=\"" << a.nComponents
       << "\" format=\"appended\" offset=\"" << a.offset << "\"/>\n";
}

// Writes n values first, first + step, ... as Int64, in chunks (the
// vertex cells' connectivity and every kind of cell's offsets).
std::function<void(std::ostream&)> sequence(const std::uint64_t n,
                                            const std::int64_t first,
                                            const std::int64_t step)
{
    return [n, first, step](std::ostream& os)
    {
        std::vector<std::int64_t> buf;
        buf.reserve(std::min<std::uint64_t>(n, chunkSize));
        for (std::uint64_t start = 0; start < n; start += chunkSize)
        {
            const std::uint64_t end = std::min<std::uint64_t>(n,
                start + chunkSize);
            buf.clear();
            for (std::uint64_t i = start; i < end; ++i)
            {
                buf.push_back(first + step*std::int64_t(i));
            }
            writeRaw(os, buf.data(), buf.size()*sizeof(std::int64_t));
        }
    };
}

// The cells of a piece: Verts, Lines or Polys, their number, and their
// connectivity and offsets arrays.
struct cellSection
{
    const char* name;
    std::uint64_t nCells;
    dataArray connectivity;
    dataArray offsets;
};

// The file: header, then the appended blocks in the order it lists them.
void writePolyData(const std::filesystem::path& file,
                   const std::uint64_t nPoints,
                   std::vector<dataArray> pointData, dataArray points,
                   cellSection cells, const double time,
                   const std::string& normals = "")
{
    std::vector<double> timeValue;
    if (!std::isnan(time))
    {
        timeValue.push_back(time);
    }
    dataArray timeArray = directArray("TimeValue", "Float64", 1, timeValue);

    std::vector<dataArray*> blocks;
    if (!timeValue.empty())
    {
        blocks.push_back(&timeArray);
    }
    for (auto& a : pointData)
    {
        blocks.push_back(&a);
    }
    blocks.push_back(&points);
    blocks.push_back(&cells.connectivity);
    blocks.push_back(&cells.offsets);
    std::uint64_t offset = 0;
    for (auto* b : blocks)
    {
        b->offset = offset;
        offset += sizeof(std::uint64_t) + b->nBytes;
    }

    const std::string section = cells.name;
    auto count = [&](const char* name)
    {
        return std::to_string(section == name ? cells.nCells : 0);
    };
    std::ostringstream header;
    header
        << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"PolyData\" version=\"1.0\""
           " byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
        << "  <PolyData>\n";
    if (!timeValue.empty())
    {
        header
            << "    <FieldData>\n"
            << "      <DataArray type=\"Float64\" Name=\"TimeValue\""
               " NumberOfTuples=\"1\" format=\"appended\" offset=\""
            << timeArray.offset << "\"/>\n"
            << "    </FieldData>\n";
    }
    header
        << "    <Piece NumberOfPoints=\"" << nPoints
        << "\" NumberOfVerts=\"" << count("Verts")
        << "\" NumberOfLines=\"" << count("Lines")
        << "\" NumberOfStrips=\"0\" NumberOfPolys=\"" << count("Polys")
        << "\">\n"
        << "      <PointData"
        << (normals.empty() ? "" : " Normals=\"" + xmlEscape(normals) + "\"")
        << ">\n";
    for (const auto& a : pointData)
    {
        writeDataArrayTag(header, a, "        ");
    }
    header
        << "      </PointData>\n"
        << "      <Points>\n";
    writeDataArrayTag(header, points, "        ");
    header
        << "      </Points>\n"
        << "      <" << section << ">\n";
    writeDataArrayTag(header, cells.connectivity, "        ");
    writeDataArrayTag(header, cells.offsets, "        ");
    header
        << "      </" << section << ">\n"
        << "    </Piece>\n"
        << "  </PolyData>\n"
        << "  <AppendedData encoding=\"raw\">\n"
        << "   _";

    writeAtomic(file, [&](std::ostream& os)
    {
        os << header.str();
        for (const auto* b : blocks)
        {
            writeRaw(os, &b->nBytes, sizeof(std::uint64_t));
            b->writeValues(os);
        }
        os << "\n  </AppendedData>\n</VTKFile>\n";
    });
}

} // End anonymous namespace


std::string exactNumber(double x)
{
    char buf[64];
    const auto result = std::to_chars(buf, buf + sizeof(buf), x);
    return std::string(buf, result.ptr);
}


void writeVtp(const std::filesystem::path& file, const particleBody& body,
              const std::vector<std::string>& fields, double time)
{
    const std::uint64_t n = std::uint64_t(body.size());
    const bool planar = body.nDimensions() == 2;

    std::vector<std::string> names = fields;
    if (names.empty())
    {
        names = body.fieldNames();
    }

    std::vector<dataArray> pointData;
    for (const auto& name : names)
    {
        if (name == "position" || !body.hasField(name))
        {
            continue;
        }
        bool duplicate = false;
        for (const auto& a : pointData)
        {
            duplicate = duplicate || a.name == name;
        }
        if (duplicate)
        {
            continue;
        }
        switch (body.kindOf(name))
        {
            case fieldKind::scalarField:
                pointData.push_back(directArray(name, scalarType, 1,
                    body.scalarField(name)));
                break;
            case fieldKind::vectorField:
                pointData.push_back(directArray(name, scalarType, 3,
                    body.vectorField(name)));
                break;
            case fieldKind::labelField:
                pointData.push_back(directArray(name, "Int32", 1,
                    body.labelField(name)));
                break;
        }
    }

    // A solid's stress components also as one symmetric tensor, in VTK's
    // order XX YY ZZ XY YZ XZ, for ParaView's tensor filters (principal
    // stresses, glyphs); the components a 2D body has no field for are 0.
    const bool wantStress = fields.empty()
        || std::find(fields.begin(), fields.end(), "stress") != fields.end();
    if (wantStress && body.hasField("stressXX")
     && body.kindOf("stressXX") == fieldKind::scalarField)
    {
        std::array<const std::vector<scalar>*, 6> parts{};
        const char* order[6] = {"stressXX", "stressYY", "stressZZ",
                                "stressXY", "stressYZ", "stressXZ"};
        for (int c = 0; c < 6; ++c)
        {
            if (body.hasField(order[c])
             && body.kindOf(order[c]) == fieldKind::scalarField)
            {
                parts[c] = &body.scalarField(order[c]);
            }
        }
        pointData.push_back({"stress", scalarType, 6, n*6*sizeof(scalar),
            [parts, n](std::ostream& os)
            {
                std::vector<scalar> buf;
                for (std::uint64_t start = 0; start < n; start += chunkSize)
                {
                    const std::uint64_t end = std::min<std::uint64_t>(n,
                        start + chunkSize);
                    buf.clear();
                    for (std::uint64_t i = start; i < end; ++i)
                    {
                        for (const auto* p : parts)
                        {
                            buf.push_back(p ? (*p)[i] : scalar(0));
                        }
                    }
                    writeRaw(os, buf.data(), buf.size()*sizeof(scalar));
                }
            }});
    }

    // Positions are points, double in both builds.
    const std::vector<point>& position = body.position();
    dataArray points = directArray("Points", "Float64", 3, position);
    if (planar)
    {
        // A 2D body lies in the x-y plane whatever z holds in memory.
        points.writeValues = [&position](std::ostream& os)
        {
            std::vector<point> buf;
            buf.reserve(std::min(position.size(), chunkSize));
            for (std::size_t start = 0; start < position.size();
                 start += chunkSize)
            {
                const std::size_t end =
                    std::min(position.size(), start + chunkSize);
                buf.clear();
                for (std::size_t i = start; i < end; ++i)
                {
                    buf.push_back({position[i].x, position[i].y, 0});
                }
                writeRaw(os, buf.data(), buf.size()*sizeof(point));
            }
        };
    }

    // One vertex cell per particle: connectivity i, offsets i + 1 (the end
    // of each cell in connectivity).
    dataArray connectivity{"connectivity", "Int64", 1,
        n*sizeof(std::int64_t), sequence(n, 0, 1)};
    dataArray offsets{"offsets", "Int64", 1, n*sizeof(std::int64_t),
        sequence(n, 1, 1)};
    writePolyData(file, n, pointData, points, {"Verts", n, connectivity,
        offsets}, time);
}


void writeVtpMesh(const std::filesystem::path& file, const vtpMesh& mesh,
                  const double time)
{
    if (mesh.nodesPerCell < 1 || mesh.nodesPerCell > 3
     || mesh.connectivity.size() % mesh.nodesPerCell != 0)
    {
        fatalError("writeVtpMesh: " + std::to_string(
            mesh.connectivity.size()) + " connectivity entries for cells of "
            + std::to_string(mesh.nodesPerCell) + " points (" + file.string()
            + ")");
    }
    const std::uint64_t n = mesh.points.size();
    std::vector<dataArray> pointData;
    for (const auto& [name, values] : mesh.scalarFields)
    {
        pointData.push_back(directArray(name, scalarType, 1, values));
    }
    for (const auto& [name, values] : mesh.vectorFields)
    {
        pointData.push_back(directArray(name, scalarType, 3, values));
    }
    const dataArray points = directArray("Points", "Float64", 3, mesh.points);
    const std::uint64_t nCells = mesh.nCells();
    const dataArray connectivity = directArray("connectivity", "Int64", 1,
        mesh.connectivity);
    const dataArray offsets{"offsets", "Int64", 1,
        nCells*sizeof(std::int64_t),
        sequence(nCells, mesh.nodesPerCell, mesh.nodesPerCell)};
    const char* section = mesh.nodesPerCell == 1 ? "Verts"
        : mesh.nodesPerCell == 2 ? "Lines" : "Polys";
    writePolyData(file, n, pointData, points, {section, nCells,
        connectivity, offsets}, time, mesh.normals);
}


void writeVtpSeries(const std::filesystem::path& file,
                    const std::vector<vtpSeriesEntry>& entries)
{
    std::ostringstream json;
    json << "{\n  \"file-series-version\" : \"1.0\",\n  \"files\" : [\n";
    for (std::size_t i = 0; i < entries.size(); ++i)
    {
        const auto& e = entries[i];
        if (!std::isfinite(e.time))
        {
            fatalError("Time " + exactNumber(e.time) + " of " + e.name
                + " in " + file.string() + " is not a finite number");
        }
        std::string name;
        for (char c : e.name)
        {
            if (c == '"' || c == '\\')
            {
                name += '\\';
            }
            name += c;
        }
        json << "    { \"name\" : \"" << name << "\", \"time\" : "
             << exactNumber(e.time) << " }"
             << (i + 1 < entries.size() ? ",\n" : "\n");
    }
    json << "  ]\n}\n";

    writeAtomic(file, [&](std::ostream& os) { os << json.str(); });
}

} // End namespace sphvcpm
