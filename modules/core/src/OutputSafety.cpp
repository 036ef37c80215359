#include "vsim/core/OutputSafety.h"

#include "vsim/core/Error.h"

#include <fstream>
#include <set>
#include <sstream>

namespace vsim {
namespace fs = std::filesystem;

namespace {

std::string markerText(const std::string& purpose) { return "vascusim " + purpose; }

void writeMarker(const fs::path& folder, const std::string& purpose)
{
    std::ofstream marker(folder / kOwnedFolderMarker, std::ios::trunc);
    marker << markerText(purpose) << "\n";
    if (!marker.flush())
        throw Error("cannot write into the output folder", {{"folder", folder.string()}});
}

/// True when `path` is `root` or lies below it (lexically).
bool isInside(const fs::path& path, const fs::path& root)
{
    const fs::path relative = path.lexically_normal().lexically_relative(root.lexically_normal());
    return !relative.empty() && *relative.begin() != "..";
}

} // namespace

bool isOwnedFolder(const fs::path& folder, const std::string& purpose)
{
    std::ifstream marker(folder / kOwnedFolderMarker);
    std::string line;
    return marker && std::getline(marker, line) && line == markerText(purpose);
}

void checkOutputFolder(const fs::path& folder, const std::string& purpose)
{
    std::error_code error;
    const fs::file_status status = fs::status(folder, error);
    if (!fs::exists(status))
    {
        // It can be created when its nearest existing ancestor is a folder.
        fs::path ancestor = fs::absolute(folder, error).parent_path();
        while (!ancestor.empty() && !fs::exists(ancestor, error) && ancestor != ancestor.parent_path())
            ancestor = ancestor.parent_path();
        if (!ancestor.empty() && fs::exists(ancestor, error) && !fs::is_directory(ancestor, error))
            throw Error(Pattern{"cannot create the output folder: %1 is a file",
                                {ancestor.string()}}, {{"folder", folder.string()}});
        return;
    }
    if (!fs::is_directory(status))
        throw Error("the output path is a file, not a folder; VascuSim does not replace it",
                    {{"path", folder.string()}});
    if (isOwnedFolder(folder, purpose))
        return;
    std::ifstream marker(folder / kOwnedFolderMarker);
    std::string other;
    if (marker && std::getline(marker, other) && other.rfind("vascusim ", 0) == 0)
        throw Error(Pattern{"the output folder is VascuSim's %1 folder, not a %2 folder; choose a new or empty folder",
                            {other.substr(9), purpose}},
                    {{"folder", folder.string()}});
    if (!fs::is_empty(folder, error))
        throw Error("the output folder holds files VascuSim did not write; choose a new or empty folder",
                    {{"folder", folder.string()}});
}

void claimOutputFolder(const fs::path& folder, const std::string& purpose)
{
    checkOutputFolder(folder, purpose);
    std::error_code error;
    if (!fs::exists(folder, error))
    {
        fs::create_directories(folder, error);
        if (error)
            throw Error(Pattern{"cannot create the output folder: %1",
                                {error.message()}}, {{"folder", folder.string()}});
    }
    if (!isOwnedFolder(folder, purpose))
        writeMarker(folder, purpose);
}

void checkOutputFile(const fs::path& file, bool overwrite)
{
    std::error_code error;
    const fs::file_status status = fs::symlink_status(file, error);
    if (!fs::exists(status))
        return;
    if (fs::is_directory(status))
        throw Error("the output path is a folder; VascuSim writes a file there only where nothing is",
                    {{"path", file.string()}});
    if (!overwrite)
        throw Error("the output file exists; give --overwrite to replace it", {{"file", file.string()}});
    if (!fs::is_regular_file(status))
        throw Error("the output path is not a regular file; VascuSim does not replace it", {{"path", file.string()}});
}

std::size_t removeWrittenFiles(const std::vector<fs::path>& files, const fs::path& root)
{
    std::size_t removed = 0;
    std::set<fs::path, std::greater<>> folders; // deepest first
    std::error_code error;
    for (const fs::path& file : files)
    {
        if (fs::remove(file, error))
            ++removed;
        for (fs::path folder = file.parent_path(); isInside(folder, root); folder = folder.parent_path())
            folders.insert(folder);
    }
    folders.insert(root);
    for (const fs::path& folder : folders)
        if (fs::is_directory(folder, error) && fs::is_empty(folder, error))
            fs::remove(folder, error);
    return removed;
}

} // namespace vsim
