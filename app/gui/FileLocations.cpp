#include "FileLocations.h"

#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>
#include <QSettings>
#include <QStandardPaths>

namespace vsim::gui {

QString startFolder(const QString& purpose)
{
    const QString remembered = QSettings().value("folders/" + purpose).toString();
    if (!remembered.isEmpty() && QFileInfo(remembered).isDir())
        return remembered;
    const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    if (!documents.isEmpty() && QFileInfo(documents).isDir())
        return documents;
    return QDir::homePath();
}

void rememberFolder(const QString& purpose, const QString& chosenPath)
{
    if (chosenPath.isEmpty())
        return;
    const QFileInfo info(chosenPath);
    const QString folder = info.isDir() ? info.absoluteFilePath() : info.absolutePath();
    QSettings().setValue("folders/" + purpose, folder);
}

QString portableFileName(const QString& name)
{
    QString cleaned = name;
    cleaned.replace(QRegularExpression(R"([\\/:*?"<>|\x00-\x1f]+)"), "-");
    cleaned = cleaned.trimmed();
    while (cleaned.startsWith('.') || cleaned.endsWith('.') || cleaned.endsWith(' '))
        cleaned = (cleaned.startsWith('.') ? cleaned.mid(1) : cleaned.chopped(1)).trimmed();
    return cleaned.isEmpty() ? QStringLiteral("untitled") : cleaned;
}

} // namespace vsim::gui
