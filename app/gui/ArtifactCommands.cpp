#include "ArtifactCommands.h"

#include "StudyDocument.h"
#include "vsim/app/SegmentNames.h"
#include "vsim/core/StoredText.h"

namespace vsim::gui {

bool isUnusedArtifact(const study::Study& study, const std::string& id)
{
    for (const study::Artifact& artifact : study.artifacts())
        for (const std::string& input : artifact.provenance.inputs)
            if (input == id)
                return false;
    return true;
}

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

SetArtifactAttributeCommand::SetArtifactAttributeCommand(StudyDocument& document, std::string id, std::string key,
                                                         std::string value, const QString& description)
    : m_document(document), m_id(std::move(id)), m_key(std::move(key)), m_value(std::move(value)),
      m_oldAttributes(document.study().artifact(m_id).attributes)
{
    setText(description);
}

void SetArtifactAttributeCommand::redo()
{
    std::map<std::string, std::string> attributes = m_oldAttributes;
    attributes[m_key] = m_value;
    m_document.study().setArtifactAttributes(m_id, attributes);
    m_document.notifyChanged();
}

void SetArtifactAttributeCommand::undo()
{
    m_document.study().setArtifactAttributes(m_id, m_oldAttributes);
    m_document.notifyChanged();
}

RenameSegmentCommand::RenameSegmentCommand(StudyDocument& document, std::string centerlinesId, std::size_t segment,
                                           std::string name)
    : m_document(document), m_id(std::move(centerlinesId)), m_segment(segment), m_name(std::move(name)),
      m_oldAttributes(document.study().artifact(m_id).attributes)
{
    setText(QObject::tr("Name segment %1 \"%2\"").arg(segment).arg(QString::fromStdString(m_name)));
}

void RenameSegmentCommand::redo()
{
    app::renameSegment(m_document.study(), m_id, m_segment, m_name);
    m_document.notifyChanged();
}

void RenameSegmentCommand::undo()
{
    m_document.study().setArtifactAttributes(m_id, m_oldAttributes);
    m_document.notifyChanged();
}

RemoveArtifactCommand::RemoveArtifactCommand(StudyDocument& document, std::string id)
    : m_document(document), m_id(std::move(id))
{
    setText(QObject::tr("Delete \"%1\"").arg(QString::fromStdString(storedTextForPeople(document.study().artifact(m_id).name))));
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
    : AddedArtifactCommand(document, std::vector<std::string>{std::move(id)}, description)
{
}

AddedArtifactCommand::AddedArtifactCommand(StudyDocument& document, std::vector<std::string> ids,
                                           const QString& description)
    : m_document(document), m_ids(std::move(ids))
{
    setText(description);
}

void AddedArtifactCommand::redo()
{
    if (m_firstRedo) // the task already added them
    {
        m_firstRedo = false;
        m_document.notifyChanged();
        return;
    }
    for (const std::string& id : m_ids)
        m_document.study().restoreArtifact(id);
    m_document.notifyChanged();
}

void AddedArtifactCommand::undo()
{
    for (auto id = m_ids.rbegin(); id != m_ids.rend(); ++id)
        m_document.study().removeArtifact(*id);
    m_document.notifyChanged();
}

} // namespace vsim::gui
