// Runs LLVMFuzzerTestOneInput on every file given (or every file of the folders given): the seed corpus as a
// regression test where no libFuzzer is at hand. Exit 0 when every input was handled without a crash, 1 when a
// seed that must parse did not.

#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
bool vsimFuzzImportFile(const std::string& path);

int main(int argc, char** argv)
{
    std::size_t inputs = 0, images = 0;
    for (int a = 1; a < argc; ++a)
    {
        std::vector<std::filesystem::path> files;
        if (std::filesystem::is_directory(argv[a]))
            for (const auto& entry : std::filesystem::directory_iterator(argv[a]))
                files.push_back(entry.path());
        else
            files.push_back(argv[a]);
        for (const auto& file : files)
        {
            std::ifstream stream(file, std::ios::binary);
            const std::vector<char> bytes((std::istreambuf_iterator<char>(stream)), std::istreambuf_iterator<char>());
            const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
            LLVMFuzzerTestOneInput(data, bytes.size());
            ++inputs;
            if (vsimFuzzImportFile(file.string()))
                ++images;
            else if (file.filename().string().rfind("seed-", 0) == 0) // seeds are valid images
            {
                std::cerr << file.filename().string() << " must decode\n";
                return 1;
            }
        }
    }
    std::cout << inputs << " inputs, " << images << " decoded images, no crash\n";
    return inputs > 0 ? 0 : 1;
}
