#include "vsim/report/PdfReport.h"

#include "PlotPainter.h"
#include "vsim/core/Error.h"
#include "vsim/core/Localized.h"

#include <QBuffer>
#include <QFile>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>

#include <algorithm>
#include <cctype>

namespace vsim::report {
namespace {

constexpr int kDotsPerInch = 300;
constexpr double kMarginMm = 18.0;
const char* const kFontFamily = "DejaVu Sans";
/// Chinese (a patient's name, a segment named by the user): Debian's fonts-noto-cjk, the simplified Chinese face.
const char* const kCjkFontFamily = "Noto Sans CJK SC";

/// Lays the blocks out top to bottom on the writer's pages, starting a new page where a block does not fit.
class PageLayout
{
public:
    PageLayout(QPdfWriter& writer, const Report& report)
        : m_writer(writer), m_painter(&writer), m_report(report)
    {
        const QRect page = m_painter.viewport();
        m_mm = double(kDotsPerInch) / 25.4;
        m_area = QRectF(page).adjusted(kMarginMm * m_mm, kMarginMm * m_mm, -kMarginMm * m_mm, -(kMarginMm + 6) * m_mm);
        m_y = m_area.top();
        m_painter.setRenderHint(QPainter::Antialiasing);
    }

    ~PageLayout()
    {
        footer();
        m_painter.end();
    }

    void header(const ReportHeader& h)
    {
        text(h.title, 16, true);
        space(2);
        std::vector<std::pair<std::string, std::string>> rows;
        const std::string notRecorded = localized("Report", "(not recorded)");
        const auto given = [&](const std::string& value) { return value.empty() ? notRecorded : value; };
        if (h.anonymized)
            rows.push_back({localized("Report", "Patient"), localized("Report", "anonymized")});
        else
        {
            rows.push_back({localized("Report", "Patient"), given(h.patientName)});
            rows.push_back({localized("Report", "Patient ID"), given(h.patientId)});
            if (!h.patientBirthDate.empty())
                rows.push_back({localized("Report", "Birth date"), h.patientBirthDate});
            rows.push_back({localized("Report", "Institution"), given(h.institution)});
        }
        rows.push_back({localized("Report", "Study date"), given(h.studyDate)});
        if (!h.studyDescription.empty())
            rows.push_back({localized("Report", "Study"), h.studyDescription});
        if (!h.seriesDescription.empty())
            rows.push_back({localized("Report", "Series"), h.seriesDescription});
        rows.push_back({localized("Report", "Software"), h.softwareVersion});
        rows.push_back({localized("Report", "Report date"), h.reportDate});
        Table table;
        for (auto& [key, value] : rows)
            table.rows.push_back({key, value});
        drawTable(table, {0.25, 0.75}, false);
        space(2);
        boxed(planningStatement());
        space(4);
    }

    void section(const Section& s)
    {
        const QFont font = fontOf(13, true);
        ensure(QFontMetricsF(font, &m_writer).height() * 4);
        space(3);
        text(s.title, 13, true);
        m_painter.setPen(QPen(Qt::black, 0.3 * m_mm));
        m_painter.drawLine(QPointF(m_area.left(), m_y), QPointF(m_area.right(), m_y));
        space(2);
        for (const Block& block : s.blocks)
            std::visit([this](const auto& b) { draw(b); }, block);
    }

    void notRun(const std::vector<std::string>& analyses)
    {
        if (analyses.empty())
            return;
        space(3);
        text(localized("Report", "Analyses not run"), 13, true);
        space(1);
        for (const std::string& analysis : analyses)
            text("- " + analysis, 9.5, false);
    }

private:
    QFont fontOf(double points, bool bold) const
    {
        QFont font;
        font.setFamilies({kFontFamily, kCjkFontFamily});
        font.setPointSizeF(points);
        font.setBold(bold);
        font.setStyleStrategy(QFont::PreferNoShaping); // no ligatures: "fi" stays two letters for text search
        return font;
    }

    void space(double mm) { m_y += mm * m_mm; }

    void newPage()
    {
        footer();
        m_writer.newPage();
        ++m_page;
        m_y = m_area.top();
    }

    void ensure(double height)
    {
        if (m_y + height > m_area.bottom() && m_y > m_area.top())
            newPage();
    }

    void footer()
    {
        m_painter.setFont(fontOf(7.5, false));
        m_painter.setPen(Qt::darkGray);
        const QString left =
            QString::fromStdString(m_report.header.softwareVersion + " - " + m_report.header.title + " - " +
                                   localized("Report", "planning support, needs clinical judgement"));
        const QRectF band(m_area.left(), m_area.bottom() + 3 * m_mm, m_area.width(), 5 * m_mm);
        m_painter.drawText(band, Qt::AlignLeft | Qt::AlignVCenter, left);
        m_painter.drawText(
            band, Qt::AlignRight | Qt::AlignVCenter,
            QString::fromStdString(withArguments(localized("Report", "page %1"), {std::to_string(m_page)})));
        m_painter.setPen(Qt::black);
    }

    /// Wrapped text across the text width.
    void text(const std::string& content, double points, bool bold, double indentMm = 0.0)
    {
        const QFont font = fontOf(points, bold);
        m_painter.setFont(font);
        const QRectF width(m_area.left() + indentMm * m_mm, 0, m_area.width() - indentMm * m_mm, 1e6);
        const QString string = QString::fromStdString(content);
        const QRectF bounds = m_painter.boundingRect(width, Qt::TextWordWrap, string);
        ensure(bounds.height());
        m_painter.setPen(Qt::black);
        m_painter.drawText(QRectF(width.left(), m_y, width.width(), bounds.height()), Qt::TextWordWrap, string);
        m_y += bounds.height();
    }

    void boxed(const std::string& content)
    {
        const QFont font = fontOf(9.5, true);
        m_painter.setFont(font);
        const double pad = 2.5 * m_mm;
        const QRectF width(m_area.left() + pad, 0, m_area.width() - 2 * pad, 1e6);
        const QString string = QString::fromStdString(content);
        const QRectF bounds = m_painter.boundingRect(width, Qt::TextWordWrap, string);
        ensure(bounds.height() + 2 * pad);
        const QRectF box(m_area.left(), m_y, m_area.width(), bounds.height() + 2 * pad);
        m_painter.setPen(QPen(QColor(180, 60, 40), 0.4 * m_mm));
        m_painter.setBrush(QColor(252, 244, 240));
        m_painter.drawRect(box);
        m_painter.setBrush(Qt::NoBrush);
        m_painter.setPen(Qt::black);
        m_painter.drawText(QRectF(box.left() + pad, box.top() + pad, width.width(), bounds.height()), Qt::TextWordWrap,
                           string);
        m_y = box.bottom();
    }

    /// The caption's height (device units) as caption() draws it.
    double captionHeight(const std::string& content)
    {
        if (content.empty())
            return 0.0;
        m_painter.setFont(fontOf(9, true));
        return m_painter.boundingRect(QRectF(0, 0, m_area.width(), 1e6), Qt::TextWordWrap, QString::fromStdString(content))
                   .height() +
               1.5 * m_mm;
    }

    void caption(const std::string& content)
    {
        if (!content.empty())
        {
            space(1);
            text(content, 9, true);
            space(0.5);
        }
    }

    void draw(const Paragraph& paragraph)
    {
        text(paragraph.text, 9.5, false);
        space(1.5);
    }

    void draw(const MetricTable& metrics)
    {
        ensure(captionHeight(metrics.caption) + 15 * m_mm); // a caption does not end a page alone
        caption(metrics.caption);
        Table table;
        table.columns = {localized("Report", "Metric"), localized("Report", "Value")};
        for (const Metric& m : metrics.rows)
            table.rows.push_back({m.label, m.unit.empty() ? m.text : m.text + " " + m.unit});
        drawTable(table, {0.68, 0.32}, true);
        space(2);
    }

    void draw(const Table& table)
    {
        ensure(captionHeight(table.caption) + 15 * m_mm);
        caption(table.caption);
        // Column widths in proportion to the longest text in each, within limits.
        const std::size_t columns = table.columns.empty() ? (table.rows.empty() ? 0 : table.rows.front().size())
                                                          : table.columns.size();
        std::vector<double> weights(columns, 1.0);
        for (std::size_t c = 0; c < columns; ++c)
        {
            std::size_t longest = c < table.columns.size() ? table.columns[c].size() : 1;
            for (const auto& row : table.rows)
                if (c < row.size())
                    longest = std::max(longest, row[c].size());
            weights[c] = std::clamp(double(longest) + 2.0, 6.0, 40.0); // + 2: the bold header and the padding
        }
        double sum = 0.0;
        for (double w : weights)
            sum += w;
        for (double& w : weights)
            w /= sum;
        drawTable(table, weights, !table.columns.empty());
        space(2);
    }

    void draw(const Plot& plot)
    {
        const double height = 72 * m_mm;
        ensure(captionHeight(plot.caption) + height); // the caption stays with its plot
        caption(plot.caption);
        m_painter.setFont(fontOf(8, false));
        detail::paintPlot(m_painter, QRectF(m_area.left(), m_y, m_area.width(), height), plot);
        m_y += height;
        space(2);
    }

    void draw(const Figure& figure)
    {
        if (figure.image.isNull())
        {
            caption(figure.caption);
            return;
        }
        const double maxWidth = m_area.width(), maxHeight = 110 * m_mm;
        const double scale = std::min(maxWidth / figure.image.width(), maxHeight / figure.image.height());
        const QSizeF size(figure.image.width() * scale, figure.image.height() * scale);
        ensure(captionHeight(figure.caption) + size.height());
        caption(figure.caption);
        m_painter.drawImage(QRectF(QPointF(m_area.left() + (maxWidth - size.width()) / 2, m_y), size), figure.image);
        m_y += size.height();
        space(2);
    }

    /// Rows of wrapped cells; `widths` are fractions of the text width; a header row is repeated on a new page.
    void drawTable(const Table& table, const std::vector<double>& widths, bool headerRow)
    {
        const QFont body = fontOf(8.5, false), bold = fontOf(8.5, true);
        const double pad = 1.0 * m_mm;
        auto rowHeight = [&](const std::vector<std::string>& cells, const QFont& font) {
            m_painter.setFont(font);
            double height = 0.0;
            for (std::size_t c = 0; c < cells.size() && c < widths.size(); ++c)
            {
                const QRectF cell(0, 0, widths[c] * m_area.width() - 2 * pad, 1e6);
                height = std::max(height, m_painter.boundingRect(cell, Qt::TextWordWrap, QString::fromStdString(cells[c])).height());
            }
            return height + 2 * pad;
        };
        auto drawRow = [&](const std::vector<std::string>& cells, const QFont& font, bool shaded) {
            const double height = rowHeight(cells, font);
            m_painter.setFont(font);
            if (shaded)
                m_painter.fillRect(QRectF(m_area.left(), m_y, m_area.width(), height), QColor(235, 238, 242));
            double x = m_area.left();
            for (std::size_t c = 0; c < cells.size() && c < widths.size(); ++c)
            {
                const double w = widths[c] * m_area.width();
                m_painter.setPen(Qt::black);
                m_painter.drawText(QRectF(x + pad, m_y + pad, w - 2 * pad, height - 2 * pad), Qt::TextWordWrap,
                                   QString::fromStdString(cells[c]));
                x += w;
            }
            m_painter.setPen(QPen(QColor(200, 200, 200), 0.15 * m_mm));
            m_painter.drawLine(QPointF(m_area.left(), m_y + height), QPointF(m_area.right(), m_y + height));
            m_y += height;
        };
        if (headerRow)
        {
            ensure(rowHeight(table.columns, bold) + (table.rows.empty() ? 0.0 : rowHeight(table.rows.front(), body)));
            drawRow(table.columns, bold, true);
        }
        for (const auto& row : table.rows)
        {
            if (m_y + rowHeight(row, body) > m_area.bottom())
            {
                newPage();
                if (headerRow)
                    drawRow(table.columns, bold, true);
            }
            drawRow(row, body, false);
        }
    }

    QPdfWriter& m_writer;
    QPainter m_painter;
    const Report& m_report;
    QRectF m_area;
    double m_mm = 1.0;
    double m_y = 0.0;
    int m_page = 1;
};

} // namespace

PageSize pageSizeFromName(const std::string& name)
{
    std::string lower = name;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (lower == "a4")
        return PageSize::A4;
    if (lower == "letter")
        return PageSize::Letter;
    throw Error(Pattern{"unknown page size '%1'; use a4 or letter", {name}});
}

QByteArray renderPdf(const Report& report, PageSize size)
{
    QByteArray bytes;
    {
        QBuffer buffer(&bytes);
        buffer.open(QIODevice::WriteOnly);
        QPdfWriter writer(&buffer);
        writer.setResolution(kDotsPerInch);
        writer.setPageSize(QPageSize(size == PageSize::A4 ? QPageSize::A4 : QPageSize::Letter));
        writer.setPageMargins(QMarginsF(0, 0, 0, 0));
        writer.setTitle(QString::fromStdString(report.header.title));
        writer.setCreator(QString::fromStdString(report.header.softwareVersion));
        PageLayout layout(writer, report);
        layout.header(report.header);
        for (const Section& section : report.sections)
            layout.section(section);
        layout.notRun(report.notRun);
    }
    if (bytes.isEmpty())
        throw Error("the PDF could not be rendered (no fonts or no QGuiApplication)");
    return bytes;
}

void writePdf(const Report& report, const std::filesystem::path& file, PageSize size)
{
    const QByteArray bytes = renderPdf(report, size);
    QFile out(QString::fromStdString(file.string()));
    if (!out.open(QIODevice::WriteOnly | QIODevice::Truncate) || out.write(bytes) != bytes.size())
        throw Error("cannot write the report", {{"file", file.string()}});
}

} // namespace vsim::report
