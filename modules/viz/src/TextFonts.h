#pragma once

// Text in the views in any script: VTK draws with its built-in Arial, which has Latin-1 only, so a translated
// overlay ("窗宽 400") or a Chinese patient name would lose its characters. Text beyond Latin-1 is drawn with
// a system font that fontconfig finds covering all of it (Noto Sans CJK for Chinese, from Debian's
// fonts-noto-cjk).
#include <QString>

class vtkTextActor;
class vtkTextProperty;

namespace vsim::viz {

/// Makes `property` able to draw `text`: VTK's own font for Latin-1 text, else a covering system font file;
/// VTK's own font (with boxes) when the system has none.
void fitFontToText(vtkTextProperty* property, const QString& text);
/// Sets an actor's text (UTF-8) with a font fitted to it.
void setActorText(vtkTextActor* actor, const QString& text);
/// The system font file fontconfig matches to draw every character of `text` ("" when none covers it).
QString fontFileCovering(const QString& text);

} // namespace vsim::viz
