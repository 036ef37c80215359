#pragma once

// New DICOM UIDs for the objects VascuSim makes: phantom series, reports (Encapsulated PDF), segmentations (SEG),
// a study stored anew. PS3.5 section 9 (at most 64 characters, digits and dots, no leading zero in a component).
// Under the organisation's registered root when one is set (the hospital's or distributor's, from the settings or
// `--uid-root`); otherwise in the 2.25 form from a random 128-bit UUID (PS3.5 B.2), which needs no registration.

#include <string>

namespace vsim {

/// A new, globally unique UID. Thread-safe.
std::string newDicomUid();

/// Sets the root of the UIDs made from now on in this process; "" returns to the 2.25 UUID form. Throws
/// vsim::Error unless `root` is a valid UID prefix of at most 32 characters (room for a 30-digit suffix).
void setDicomUidRoot(const std::string& root);

/// The root in use: "" for the 2.25 UUID form.
std::string dicomUidRoot();

} // namespace vsim
