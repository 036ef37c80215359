#include "HelpWindow.h"

#include <QTextBrowser>
#include <QUrl>
#include <QVBoxLayout>

namespace vsim::gui {

HelpWindow::HelpWindow(QWidget* parent) : QDialog(parent)
{
    setObjectName("helpWindow");
    setWindowTitle(tr("VascuSim User Guide"));
    resize(900, 800);
    m_browser = new QTextBrowser(this);
    m_browser->setObjectName("helpBrowser");
    m_browser->setOpenExternalLinks(false);
    m_browser->setSearchPaths({":/help"});
    m_browser->setSource(QUrl("qrc:/help/guide.html"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_browser);
}

void HelpWindow::showSection(const QString& anchor)
{
    m_browser->scrollToAnchor(anchor);
}

} // namespace vsim::gui
