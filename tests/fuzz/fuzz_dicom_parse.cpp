// libFuzzer target: one DICOM file goes through exactly what import does with a file on disk: the header read
// (lazy values, functional groups), then the pixel decode (every DCMTK codec, GDCM for JPEG 2000, HU rescale); a
// DICOM SEG goes through the label reader instead.
// The input is handed over as an in-memory file (memfd), so no disk is touched. Any outcome but a crash, a
// sanitizer report, an out-of-memory or a hang is fine: bad input must end in a vsim::Error.
//
// Fuzz (clang):  cmake --preset fuzz && cmake --build --preset fuzz
//                build/fuzz/tests/fuzz/fuzz_dicom_parse -max_total_time=600 -max_len=65536 <work-corpus> tests/fuzz/corpus
// Without clang the same entry point is built into `fuzz_dicom_parse_replay`, which runs every file of the
// seed corpus once (a CTest case), so the target always compiles and the seeds stay valid.

#include "vsim/dicom/DicomFile.h"
#include "vsim/dicom/DicomSegmentation.h"

#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace {

constexpr std::size_t kMaxVoxels = std::size_t(4) << 20; // larger images are refused by the harness, not decoded

/// Reads and decodes one file as the importer does (a DICOM SEG as `import --as-label` reads it); returns true when
/// it was a decodable image.
bool importOneFile(const std::string& path)
{
    try
    {
        if (vsim::dicom::isDicomSegmentation(path))
        {
            vsim::dicom::readDicomSegmentation(path, kMaxVoxels);
            return true;
        }
        const vsim::dicom::DicomImageHeader header = vsim::dicom::readDicomHeader(path);
        if (header.format.pixelsPerFrame() * header.frames.size() > kMaxVoxels)
            return false;
        std::vector<std::int16_t> hu(header.format.pixelsPerFrame() * header.frames.size());
        std::vector<int> frames;
        std::vector<std::int16_t*> out;
        for (std::size_t f = 0; f < header.frames.size(); ++f)
        {
            frames.push_back(int(f));
            out.push_back(hu.data() + f * header.format.pixelsPerFrame());
        }
        vsim::dicom::decodeFramesToHu(header, frames, out);
        return true;
    }
    catch (const vsim::Error&)
    {
        return false;
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const int fd = memfd_create("fuzz-dicom", 0);
    if (fd < 0)
        return 0;
    if (write(fd, data, size) == ssize_t(size))
        importOneFile("/proc/self/fd/" + std::to_string(fd));
    close(fd);
    return 0;
}

/// For the replay runner: the same path on a file of the corpus.
bool vsimFuzzImportFile(const std::string& path)
{
    return importOneFile(path);
}
