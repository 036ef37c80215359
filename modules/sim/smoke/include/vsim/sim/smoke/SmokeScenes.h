#pragma once

// The smoke scenes of issue 21 (illustrative: the geometry is synthetic, placed around a study's anatomy where
// there is one). Each is a grid with its solids and vents, the direction of gravity, the cautery's smoke source,
// and where a camera looks from; SI, the grid's axes those of the patient frame (LPS) where a study is involved.
//  ball-drop       the thesis demo: a 1 m box, open at the top, smoke rising from the floor, a ball of 0.08 m
//                  radius dropped through it at 1 s; a camera at a side wall looking at the plume.
//  evh             endoscopic vessel harvesting: a CO2 tunnel of `tunnelRadius` around a vessel's centerline (a
//                  pre-operative CT shows no cavity: the tunnel is drawn around the vessel), the vessel itself
//                  solid, the cautery's contact on the vessel's anterior wall halfway along, smoke from 9 s after
//                  contact (thesis), the insufflation port a vent at the tunnel's entry, the endoscope 25 mm back
//                  along the tunnel looking at the contact.
//  liver-ablation  an insufflated abdomen over the liver: a dome of 0.24 x 0.20 x 0.12 m above a slab of liver
//                  (or the study's liver label under the dome), the probe's smoke at the liver's surface with a slow
//                  plume, the insufflator a vent in the dome's roof, a suction port beside the probe, the
//                  laparoscope through the roof looking down at the site.

#include "vsim/core/ImageVolume.h"
#include "vsim/sim/smoke/Obscuration.h"
#include "vsim/sim/smoke/SmokeSimulation.h"

#include <optional>
#include <string>
#include <vector>

namespace vsim::sim::smoke {

struct SmokeScene
{
    std::string name;
    std::string description; ///< for people: what is modelled and what is synthetic
    SmokeGrid grid;
    Eigen::Vector3d up = Eigen::Vector3d::UnitZ(); ///< against gravity, in the grid's axes
    SmokeSource source;                            ///< its rates and timing come from the parameters
    std::optional<MovingSphere> ball;
    double ballReleaseS = 0.0;
    std::optional<SmokeSuction> suction;           ///< its flow and timing come from the parameters
    SmokeCamera camera;
};

/// The thesis demo on a cubic grid of `cells` per edge.
SmokeScene ballDropScene(int cells);

/// The liver-ablation box phantom with `cells` along its longest edge.
SmokeScene liverBoxScene(int cells);

/// The liver-ablation scene over a liver label (its voxels > 0; mm, patient frame LPS, supine: anterior up): a dome
/// of 0.24 x 0.20 x 0.12 m whose floor is the liver's anterior surface around its most anterior point, `cells`
/// along the longest edge. Throws vsim::Error for an empty label.
SmokeScene liverDomeScene(const LabelVolume& liver, int cells);

/// The EVH tunnel around a centerline (points in mm, patient frame LPS, supine) with the vessel's radius (mm), the
/// tunnel's radius (mm) around the centerline, `cells` along the longest edge. Throws vsim::Error for a centerline
/// shorter than 20 mm.
SmokeScene evhTunnelScene(const std::vector<Eigen::Vector3d>& centerlineMm, double vesselRadiusMm,
                          double tunnelRadiusMm, int cells);

} // namespace vsim::sim::smoke
