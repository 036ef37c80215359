#pragma once

// Where file dialogs start and what default file names look like. A dialog starts in the folder last used for the
// same purpose ("study", "volume", "dicom", "report", "capture"; kept in the settings), else in the user's
// documents folder, else the home folder: never the program's working folder. Default names keep to letters,
// digits, '-', '_', '.' and spaces so that they survive Windows shares, macOS and PACS exports.

#include <QString>

namespace vsim::gui {

/// The folder a dialog for `purpose` starts in.
QString startFolder(const QString& purpose);
/// Remembers the folder of `chosenPath` (a file or a folder) for `purpose`; an empty path is ignored.
void rememberFolder(const QString& purpose, const QString& chosenPath);
/// `name` with the characters that break on other systems (\ / : * ? " < > | and control characters) replaced by
/// '-', runs of them collapsed, and leading/trailing dots and spaces removed; "untitled" if nothing is left.
QString portableFileName(const QString& name);

} // namespace vsim::gui
