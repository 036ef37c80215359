#pragma once

// The multi-frame functional-group rule (PS3.3 C.7.6.16), shared by the Enhanced CT reader and the DICOM SEG reader.

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcitem.h>

namespace vsim::dicom::detail {

/// A functional group macro of a frame: the frame's own item, else the shared one; nullptr when neither has it.
inline DcmItem* functionalGroup(DcmItem* perFrame, DcmItem* shared, const DcmTagKey& sequence)
{
    DcmItem* item = nullptr;
    if (perFrame && perFrame->findAndGetSequenceItem(sequence, item, 0).good() && item)
        return item;
    if (shared && shared->findAndGetSequenceItem(sequence, item, 0).good() && item)
        return item;
    return nullptr;
}

} // namespace vsim::dicom::detail
