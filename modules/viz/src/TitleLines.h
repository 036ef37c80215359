#pragma once

// A legend's title broken into lines that fit the room the view gives it: VTK's scalar bar draws its title as one
// text centred over the bar and clips it at the view's edge ("...ed over 2.0-4.0 ms; grey: no value" lost its start
// in a 570-pixel view). The lines break where Unicode's line-breaking rules allow (QTextBoundaryFinder: after
// spaces and punctuation, between CJK characters), so German and Chinese titles wrap as English ones do, and each
// line is measured in pixels by VTK's own text renderer with the title's font, not estimated.
#include <QString>

#include <vector>

class vtkTextProperty;

namespace vsim::viz::detail {

/// `title` with line breaks so that no line is wider than `roomPixels` when drawn with `font` at `dpi`; its own
/// line breaks are kept. A piece between two break opportunities wider than the room keeps a line to itself. No
/// character is dropped but the spaces at the breaks.
QString titleLines(const QString& title, vtkTextProperty* font, double roomPixels, int dpi);

/// The width in pixels of each line of `text` drawn with `font` at `dpi` (VTK's text renderer; 0 for an empty line).
std::vector<int> lineWidthsPixels(const QString& text, vtkTextProperty* font, int dpi);

} // namespace vsim::viz::detail
