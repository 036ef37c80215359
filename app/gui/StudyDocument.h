#pragma once

#include "vsim/study/Study.h"

#include <QObject>
#include <QUndoStack>

#include <optional>

namespace vsim::gui {

/// The study of one main window, with its undo stack. Widgets observe it through signals; edits that people
/// can undo go through the undo stack (ArtifactCommands.h).
class StudyDocument : public QObject
{
    Q_OBJECT
public:
    explicit StudyDocument(QObject* parent = nullptr);

    bool hasStudy() const { return m_study.has_value(); }
    /// The study; only valid when hasStudy().
    study::Study& study() { return *m_study; }
    const study::Study& study() const { return *m_study; }
    /// Takes ownership of a study (new or opened); clears the undo stack.
    void setStudy(study::Study study);
    QUndoStack* undoStack() { return &m_undoStack; }
    bool isModified() const { return m_study && m_study->isModified(); }
    /// Tells observers that artifacts or names changed (commands call it after editing the study).
    void notifyChanged();
    /// Marks the current undo state as saved.
    void markSaved();

signals:
    void studyReplaced();
    void artifactsChanged();

private:
    std::optional<study::Study> m_study;
    QUndoStack m_undoStack;
};

} // namespace vsim::gui
