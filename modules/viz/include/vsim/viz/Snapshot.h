#pragma once

// Offscreen pictures of coloured 3D results for reports: a surface carrying a field (the wall stress) or a vessel
// tree of tubes (the drug flow), seen from the patient's front with a colour legend, rendered by VTK into an
// offscreen window at print resolution. VTK needs an OpenGL context, which on Linux means a display (X, or
// xvfb-run on a server): canRenderSnapshots() says whether there is one, and the snapshots throw vsim::Error without.

#include "vsim/core/TriangleMesh.h"
#include "vsim/viz/Callout.h"

#include <Eigen/Core>

#include <QImage>
#include <QSize>

#include <array>
#include <string>
#include <vector>

namespace vsim::viz {

struct SnapshotColouring
{
    std::string legendTitle; ///< with the unit: "von Mises [kPa]"
    double low = 0.0, high = 1.0;
};

/// Whether this process can open an offscreen OpenGL context (a display is set).
bool canRenderSnapshots();

/// The surface coloured by its point field `field`, with `callouts`.
QImage snapshotSurface(const TriangleMesh& surface, const std::string& field, const SnapshotColouring& colouring,
                       QSize pixels, const std::vector<Callout>& callouts = {});

/// Polylines (mm) as tubes of their radii (mm, linear along each), each coloured by its value.
QImage snapshotTubes(const std::vector<std::vector<Eigen::Vector3d>>& lines, const std::vector<double>& values,
                     const std::vector<std::array<double, 2>>& radiiMm, const SnapshotColouring& colouring,
                     QSize pixels);

} // namespace vsim::viz
