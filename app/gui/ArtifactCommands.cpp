#include "ArtifactCommands.h"

#include "StudyDocument.h"

namespace vsim::gui {

RenameArtifactCommand::RenameArtifactCommand(StudyDocument& document, std::string id, std::string newName)
    : m_document(document), m_id(std::move(id)), m_oldName(document.study().artifact(m_id).name),
      m_newName(std::move(newName))
{
    setText(QObject::tr("Rename \"%1\"").arg(QString::fromStdString(m_oldName)));
}

void RenameArtifactCommand::redo()
{
    m_document.study().renameArtifact(m_id, m_newName);
    m_document.notifyChanged();
}

void RenameArtifactCommand::undo()
{
    m_document.study().renameArtifact(m_id, m_oldName);
    m_document.notifyChanged();
}

RemoveArtifactCommand::RemoveArtifactCommand(StudyDocument& document, std::string id)
    : m_document(document), m_id(std::move(id))
{
    setText(QObject::tr("Delete \"%1\"").arg(QString::fromStdString(document.study().artifact(m_id).name)));
}

void RemoveArtifactCommand::redo()
{
    m_document.study().removeArtifact(m_id);
    m_document.notifyChanged();
}

void RemoveArtifactCommand::undo()
{
    m_document.study().restoreArtifact(m_id);
    m_document.notifyChanged();
}

AddedArtifactCommand::AddedArtifactCommand(StudyDocument& document, std::string id, const QString& description)
    : m_document(document), m_id(std::move(id))
{
    setText(description);
}

void AddedArtifactCommand::redo()
{
    if (m_firstRedo) // the task already added it
    {
        m_firstRedo = false;
        m_document.notifyChanged();
        return;
    }
    m_document.study().restoreArtifact(m_id);
    m_document.notifyChanged();
}

void AddedArtifactCommand::undo()
{
    m_document.study().removeArtifact(m_id);
    m_document.notifyChanged();
}

} // namespace vsim::gui
