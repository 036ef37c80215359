#include "TitleLines.h"

#include <vtkSmartPointer.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>

#include <QStringList>
#include <QTextBoundaryFinder>

namespace vsim::viz::detail {
namespace {

int widthPixels(const QString& line, vtkTextProperty* font, int dpi)
{
    if (line.isEmpty())
        return 0;
    vtkTextRenderer* renderer = vtkTextRenderer::GetInstance();
    int box[4] = {0, -1, 0, -1}; // x min, x max, y min, y max (pixels)
    if (!renderer || !renderer->GetBoundingBox(font, line.toStdString(), box, dpi))
        return 0;
    return box[1] - box[0] + 1;
}

/// The pieces of one line between its break opportunities, each with the spaces that follow it.
QStringList breakablePieces(const QString& line)
{
    QStringList pieces;
    QTextBoundaryFinder finder(QTextBoundaryFinder::Line, line);
    qsizetype start = 0;
    for (qsizetype at = finder.toNextBoundary(); at > 0; at = finder.toNextBoundary())
    {
        pieces << line.mid(start, at - start);
        start = at;
    }
    if (start < line.size())
        pieces << line.mid(start);
    return pieces;
}

} // namespace

QString titleLines(const QString& title, vtkTextProperty* font, double roomPixels, int dpi)
{
    QStringList lines;
    for (const QString& paragraph : title.split('\n'))
    {
        QString line;
        for (const QString& piece : breakablePieces(paragraph))
        {
            const QString longer = line + piece;
            if (line.isEmpty() || widthPixels(longer.trimmed(), font, dpi) <= roomPixels)
                line = longer;
            else
                lines << line.trimmed(), line = piece;
        }
        lines << line.trimmed();
    }
    return lines.join('\n');
}

std::vector<int> lineWidthsPixels(const QString& text, vtkTextProperty* font, int dpi)
{
    std::vector<int> widths;
    for (const QString& line : text.split('\n'))
        widths.push_back(widthPixels(line, font, dpi));
    return widths;
}

} // namespace vsim::viz::detail
