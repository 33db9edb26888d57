/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Conversion of a case's time directories to VTK (see vtkCaseConverter.H).

#include "vtkCaseConverter.H"
#include "error.H"
#include "vtpWriter.H"

#include <algorithm>
#include <set>

namespace sphvcpm
{

vtkCaseConverter::vtkCaseConverter(std::filesystem::path caseDir)
:
    caseDir_(std::move(caseDir)),
    times_(findTimes(caseDir_))
{
    std::map<label, std::string> byIndex;
    for (const auto& t : times_)
    {
        const timeState state = readTimeState(caseDir_, t.name);
        auto [it, fresh] = byIndex.emplace(state.index, t.name);
        if (!fresh)
        {
            sharedIndex_[t.name] = it->second;
            sharedIndex_.emplace(it->second, t.name);
            warning("Times " + it->second + " and " + t.name + " of case "
                + caseDir_.string() + " have the same time index "
                + std::to_string(state.index) + " (from <time>/uniform/time,"
                  " 0 without one): neither can be converted, and the VTK"
                  " series leave both out. Remove or rename one of the two"
                  " time directories.");
        }
        states_[t.name] = state;
    }
}


void vtkCaseConverter::checkOwnIndex(const std::string& time) const
{
    const auto other = sharedIndex_.find(time);
    if (other == sharedIndex_.end()) return;
    const auto [a, b] = std::minmax(time, other->second);
    fatalError("Times " + a + " and " + b + " of case " + caseDir_.string()
        + " have the same time index "
        + std::to_string(states_.at(time).index) + " (from"
          " <time>/uniform/time, 0 without one), so their VTK files would"
          " have the same name.\nRemove or rename one of the two time"
          " directories (other times convert: choose them with -time).");
}


void vtkCaseConverter::restrictFields(const std::vector<std::string>& fields,
                                      const std::vector<timeInstant>& times)
{
    // Field files on disk are enough to tell names apart: nothing is read.
    std::set<std::string> present;
    for (const auto& t : times)
    {
        std::error_code ec;
        for (const auto& bodyDir :
             std::filesystem::directory_iterator(caseDir_/t.name, ec))
        {
            if (!std::filesystem::is_regular_file(
                    bodyDir.path()/"bodyProperties"))
            {
                continue;
            }
            for (const auto& f :
                 std::filesystem::directory_iterator(bodyDir.path(), ec))
            {
                const std::string name = f.path().filename().string();
                if (f.is_regular_file() && name != "bodyProperties"
                 && name[0] != '.')
                {
                    present.insert(name);
                }
            }
        }
    }

    for (const auto& name : fields)
    {
        // stress: the solids' tensor, read from its component fields.
        if (!present.count(name) && !(name == "stress"
                                      && present.count("stressXX")))
        {
            std::string timeList, fieldList;
            for (const auto& t : times)
            {
                timeList += " " + t.name;
            }
            for (const auto& f : present)
            {
                fieldList += " " + f;
            }
            fatalError("Field '" + name + "' given by -fields is in no body"
                " of the selected times (" + timeList.substr(1) + ").\n"
                "Fields there:" + fieldList);
        }
    }

    restricted_ = true;
    fields_ = fields;
    if (std::find(fields_.begin(), fields_.end(), "stress") != fields_.end())
    {
        for (const char* c : {"stressXX", "stressYY", "stressZZ", "stressXY",
                              "stressYZ", "stressXZ"})
        {
            if (present.count(c)
             && std::find(fields_.begin(), fields_.end(), c) == fields_.end())
            {
                fields_.push_back(c);
            }
        }
    }
    if (std::find(fields_.begin(), fields_.end(), "id") == fields_.end())
    {
        fields_.push_back("id");
    }
}


std::filesystem::path vtkCaseConverter::vtpName(const std::string& body,
                                                label index)
{
    return std::filesystem::path(body)
        /(body + "_" + std::to_string(index) + ".vtp");
}


std::vector<vtkCaseConverter::bodyOutput> vtkCaseConverter::convert(
    const timeInstant& time, std::vector<particleBody>* bodies)
{
    const auto state = states_.find(time.name);
    if (state == states_.end())
    {
        fatalError("Time " + time.name + " is not a time directory of case "
            + caseDir_.string());
    }

    checkOwnIndex(time.name);
    std::vector<bodyOutput> outputs;
    std::vector<particleBody> read = readTimeDirectory(caseDir_, time.name);
    for (const particleBody& body : read)
    {
        const std::filesystem::path name =
            vtpName(body.name(), state->second.index);
        std::filesystem::create_directories(vtkDir()/body.name());
        writeVtp(vtkDir()/name, body,
                 restricted_ ? fields_ : std::vector<std::string>(),
                 state->second.value);

        outputs.push_back({body.name(), body.size(), "VTK"/name});
        addToSeries(body.name());
    }
    if (bodies)
    {
        *bodies = std::move(read);
    }
    return outputs;
}


std::filesystem::path vtkCaseConverter::writeMesh(const std::string& name,
    const timeInstant& time, const vtpMesh& mesh)
{
    const std::vector<std::string> names = bodyNames(caseDir_, time.name);
    if (std::find(names.begin(), names.end(), name) != names.end())
    {
        fatalError("Time " + time.name + " of case " + caseDir_.string()
            + " has a body named '" + name + "': its VTK files and those of"
              " the " + name + " would be the same.\nRename the body in"
              " system/generateParticlesDict.");
    }
    checkOwnIndex(time.name);
    const std::filesystem::path file =
        vtpName(name, states_.at(time.name).index);
    std::filesystem::create_directories(vtkDir()/name);
    writeVtpMesh(vtkDir()/file, mesh, states_.at(time.name).value);
    addToSeries(name);
    return "VTK"/file;
}


void vtkCaseConverter::addToSeries(const std::string& name)
{
    if (!std::binary_search(bodies_.begin(), bodies_.end(), name))
    {
        bodies_.insert(std::upper_bound(bodies_.begin(), bodies_.end(),
            name), name);
    }
}


void vtkCaseConverter::writeSeries() const
{
    for (const auto& body : bodies_)
    {
        std::vector<vtpSeriesEntry> entries;
        for (const auto& t : times_)
        {
            // A shared index: which time its file is cannot be told.
            if (sharedIndex_.count(t.name)) continue;
            const timeState& state = states_.at(t.name);
            const std::filesystem::path name = vtpName(body, state.index);
            if (std::filesystem::exists(vtkDir()/name))
            {
                entries.push_back({name.generic_string(), state.value});
            }
        }
        writeVtpSeries(vtkDir()/(body + ".vtp.series"), entries);
    }
}

} // End namespace sphvcpm
