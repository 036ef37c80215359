#pragma once

// Anatomical names of centerline segments from the tree's topology and the directions of its branches in the
// patient frame (LPS: +x the patient's left, +y posterior, +z superior), for the aortic and hepatic trees:
//   aorta: from the upstream end (the highest end of an aorta-wide segment, median radius >= 5 mm) along the
//     widest path (Dijkstra, cost length / r^2) to the lowest wide end (>= 3 mm, 40 mm below), at least 40 mm
//     long with its ends apart mostly along z (a pulmonary trunk is not taken for it);
//   left / right common iliac: where a second wide end's path leaves the aorta's, the two children of similar
//     calibre (radius ratio >= 0.6, >= 3 mm, each followed 10 mm or more) both running inferiorly to opposite
//     sides, the one heading to +x the left; the aorta ends there;
//   left / right renal: an aortic branch leaving the lumen laterally (over its first 15 mm outside the aortic
//     lumen |x| >= 0.5 and >= 0.8 |y|: the right renal runs behind the IVC), one per side; two candidates on a
//     side name the wider only when it is 1.3 x wider (an accessory renal stays unnamed);
//   celiac trunk, superior mesenteric artery: the two highest aortic branches leaving anteriorly (-y the largest
//     component, >= 0.5); a single one is the celiac when it divides into a right- and a left-going child, the SMA
//     when it runs inferiorly for 40 mm without dividing;
//   common hepatic / splenic: the celiac's division, the right-going (x <= -0.3) and the left-going (x >= 0.3) child;
//   gastroduodenal / proper hepatic: the common hepatic's junction with a child running inferiorly (z <= -0.4) and
//     another running above it (z larger by 0.4); right / left hepatic: the proper hepatic's division (radius ratio
//     >= 0.5) into a right- and a left-going child (x apart by 0.3); segmental hepatic: all beyond those.
// A vessel ends at a division (the second child reaching 15 mm or more and of radius ratio >= 0.7, 0.5 for the
// proper hepatic; under 2 mm, where radii are a voxel or two, reaching 0.3 x as far); a smaller child is a side
// branch. A junction split in two by a short edge (under max(3 mm, 0.75 x the parent's radius)) is read as one; a
// free end that stays within the parent's lumen or within 5 mm of the aortic lumen is a spur of the skeleton.
// Aortic branches must leave the aortic lumen by 2.5 mm (the skeleton's loops inside a sac do not). Whatever does
// not fit the pattern (a replaced or accessory artery, a lumbar artery, a pulmonary tree) is "unnamed" rather than
// guessed. References: the usual branching patterns in Gray's Anatomy
// (41st ed., ch. 61, 66) and the SVS reporting standards (Chaikof et al., J Vasc Surg 2018) for the aortic landmarks.

#include "vsim/core/SkeletonGraph.h"

#include <string>
#include <vector>

namespace vsim::imaging {

inline constexpr const char* kUnnamedSegment = "unnamed";

/// Which trees the names may be read from: the aortic and hepatic patterns, or none (a pulmonary or peripheral
/// tree from `segment --target all`: every segment unnamed).
enum class NamingScope
{
    AorticAndHepatic,
    None,
};

/// One name per edge of `centerlines` (same order); "unnamed" where the pattern does not fit.
std::vector<std::string> nameVesselSegments(const SkeletonGraph& centerlines,
                                            NamingScope scope = NamingScope::AorticAndHepatic);

} // namespace vsim::imaging
