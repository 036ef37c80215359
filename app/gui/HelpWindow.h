#pragma once

#include <QDialog>

class QLocale;
class QTextBrowser;

namespace vsim::gui {

/// The guide's page for a language: resources/help/guide_<code>.html ("de", "zh_CN"), else the English guide.html.
QString guidePage(const QLocale& locale);

/// Help > User Guide (F1): the guide of resources/help in the workstation's language (both cases walked through with pictures made by the GUI
/// tests, the mouse and keyboard table, the definitions and units) in a browser with working links.
class HelpWindow : public QDialog
{
    Q_OBJECT
public:
    explicit HelpWindow(QWidget* parent = nullptr);
    /// Shows the part of the guide under an anchor ("keys", "aaa", "tace", ...).
    void showSection(const QString& anchor);
    QTextBrowser* browser() const { return m_browser; }

private:
    QTextBrowser* m_browser = nullptr;
};

} // namespace vsim::gui
