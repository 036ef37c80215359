#include "HelpWindow.h"

#include <QFile>
#include <QLocale>
#include <QTextBrowser>
#include <QUrl>
#include <QVBoxLayout>

namespace vsim::gui {

QString guidePage(const QLocale& locale)
{
    // "de_DE" -> guide_de.html, "zh_CN" -> guide_zh_CN.html; English (and any language without a guide): guide.html.
    for (const QString& code : {locale.name(), locale.name().section('_', 0, 0)})
        if (QFile::exists(":/help/guide_" + code + ".html"))
            return "qrc:/help/guide_" + code + ".html";
    return "qrc:/help/guide.html";
}

HelpWindow::HelpWindow(QWidget* parent) : QDialog(parent)
{
    setObjectName("helpWindow");
    setWindowTitle(tr("VascuSim User Guide"));
    resize(900, 800);
    m_browser = new QTextBrowser(this);
    m_browser->setObjectName("helpBrowser");
    m_browser->setOpenExternalLinks(false);
    m_browser->setSearchPaths({":/help"});
    m_browser->setSource(QUrl(guidePage(QLocale())));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_browser);
}

void HelpWindow::showSection(const QString& anchor)
{
    m_browser->scrollToAnchor(anchor);
}

} // namespace vsim::gui
