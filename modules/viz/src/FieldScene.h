#pragma once

// The pieces of a coloured 3D scene that the workstation's 3D view and the report's offscreen snapshots share:
// a surface or a vessel tree carrying a field, its blue-to-red mapper, the colour legend, the anterior camera.

#include "vsim/core/TriangleMesh.h"
#include "vsim/viz/Callout.h"

#include <Eigen/Core>

#include <QString>

#include <vtkSmartPointer.h>

#include <array>
#include <functional>
#include <string>
#include <vector>

class vtkCamera;
class vtkLookupTable;
class vtkProp;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkScalarBarActor;

namespace vsim::viz::detail {

/// The blue (low) to red (high) colour table over [low, high] of every field view.
vtkSmartPointer<vtkLookupTable> fieldLookupTable(double low, double high);

/// A mapper colouring its scalars blue (low) to red (high) over [low, high].
vtkSmartPointer<vtkPolyDataMapper> fieldMapper(vtkPolyData* polyData, double low, double high);

/// The surface with its point field `field` as the point scalars. Throws vsim::Error when it has no such field.
vtkSmartPointer<vtkPolyData> fieldSurface(const TriangleMesh& surface, const std::string& field);

/// Polylines (mm) with one value each as cell scalars; with radii (mm, linear from the first point to the last, as
/// a conical segment), tubes of those radii, else lines. Throws vsim::Error for mismatched sizes.
vtkSmartPointer<vtkPolyData> fieldTubes(const std::vector<std::vector<Eigen::Vector3d>>& lines,
                                        const std::vector<double>& values,
                                        const std::vector<std::array<double, 2>>& radiiMm);

/// The props of `callouts` (Callout.h) for a view `widthPixels` x `heightPixels` with text of `fontSize`: per
/// callout a caption (2D, with its line) and a ball (3D).
std::vector<vtkSmartPointer<vtkProp>> calloutProps(const std::vector<Callout>& callouts, int fontSize, int widthPixels,
                                                   int heightPixels);

/// A vertical colour legend with five labels.
vtkSmartPointer<vtkScalarBarActor> newLegend();

/// Titles the legend with `title` (its font chosen for the script) in text of `fontSize` pixels, numbers and title
/// alike, upright: VTK otherwise shrinks the title to the bar's width, 6-8 pixels for "von Mises (kPa)". A long
/// title is broken before its unit, "Drug flow" over "(ml/min; grey: none)", so that it stays within the view; with
/// `roomPixels` (the width the title may take, centred over the bar) the text is smaller where its longest line
/// would not fit, down to three quarters of `fontSize`, and a line still wider than the room at that size, measured
/// at the view's `dpi`, breaks into more (TitleLines.h).
void titleLegend(vtkScalarBarActor* legend, const QString& title, int fontSize, double roomPixels = 0.0,
                 int dpi = 72);

/// Labels the legend with `count` numbers across its table's range, each written by `text`, so that they carry
/// the reader's decimal mark: VTK prints tick labels with printf, which keeps the '.', so the numbers become the
/// table's annotations (drawn at their values) and the tick labels are off. Call after SetLookupTable, and again
/// when the table's range changes.
void labelLegend(vtkScalarBarActor* legend, const std::function<std::string(double)>& text, int count = 5);

/// Looks at `centre` (mm) from the patient's front (anterior is -y in LPS), superior up, in parallel projection
/// showing `heightMm`.
void lookFromFront(vtkCamera* camera, const Eigen::Vector3d& centre, double heightMm);

} // namespace vsim::viz::detail
