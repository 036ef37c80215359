#include "StudyDocument.h"

namespace vsim::gui {

StudyDocument::StudyDocument(QObject* parent) : QObject(parent) {}

void StudyDocument::setStudy(study::Study study)
{
    m_undoStack.clear();
    m_study.emplace(std::move(study));
    emit studyReplaced();
    emit artifactsChanged();
}

void StudyDocument::notifyChanged()
{
    emit artifactsChanged();
}

void StudyDocument::markSaved()
{
    m_undoStack.setClean();
    emit artifactsChanged();
}

} // namespace vsim::gui
