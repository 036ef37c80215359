#pragma once

namespace vsim::dicom {

/// Registers DCMTK's JPEG, JPEG-LS and RLE decoders and encoders once per process and quiets DCMTK's and GDCM's
/// own loggers (errors reach the user as vsim::Error messages instead). Thread-safe.
void ensureDcmtkCodecs();

} // namespace vsim::dicom
