#pragma once

// Column headers that are never cut: each column as wide as its header or contents (the last one stretches), and
// each header with a tooltip that says what the column holds, its definition and unit.

#include <QHeaderView>
#include <QString>
#include <QTableWidget>

#include <utility>
#include <vector>

namespace vsim::gui {

/// Sets `table`'s columns to `headers` (label, tooltip).
inline void setColumnHeaders(QTableWidget* table, const std::vector<std::pair<QString, QString>>& headers)
{
    table->setColumnCount(int(headers.size()));
    for (std::size_t c = 0; c < headers.size(); ++c)
    {
        auto* item = new QTableWidgetItem(headers[c].first);
        item->setToolTip(headers[c].second);
        table->setHorizontalHeaderItem(int(c), item);
    }
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table->horizontalHeader()->setStretchLastSection(true);
}

} // namespace vsim::gui
