#pragma once

#include "vsim/study/Study.h"

#include <QString>
#include <QUndoCommand>

#include <map>
#include <string>
#include <vector>

namespace vsim::gui {

class StudyDocument;

/// True when no artifact of the study takes `id` as an input (a re-run may then replace it).
bool isUnusedArtifact(const study::Study& study, const std::string& id);

/// Renames an artifact; undo restores the old name.
class RenameArtifactCommand : public QUndoCommand
{
public:
    RenameArtifactCommand(StudyDocument& document, std::string id, std::string newName);
    void redo() override;
    void undo() override;

private:
    StudyDocument& m_document;
    std::string m_id;
    std::string m_oldName;
    std::string m_newName;
};

/// Gives a centerline segment the user's name (app::renameSegment); undo restores the names before.
class RenameSegmentCommand : public QUndoCommand
{
public:
    RenameSegmentCommand(StudyDocument& document, std::string centerlinesId, std::size_t segment, std::string name);
    void redo() override;
    void undo() override;

private:
    StudyDocument& m_document;
    std::string m_id;
    std::size_t m_segment;
    std::string m_name;
    std::map<std::string, std::string> m_oldAttributes;
};

/// Sets one attribute of an artifact (e.g. a measurement's "in_report"); undo restores the attributes before.
class SetArtifactAttributeCommand : public QUndoCommand
{
public:
    SetArtifactAttributeCommand(StudyDocument& document, std::string id, std::string key, std::string value,
                                const QString& description);
    void redo() override;
    void undo() override;

private:
    StudyDocument& m_document;
    std::string m_id, m_key, m_value;
    std::map<std::string, std::string> m_oldAttributes;
};

/// Removes an artifact; undo puts it back (its data is kept in memory by the study).
class RemoveArtifactCommand : public QUndoCommand
{
public:
    RemoveArtifactCommand(StudyDocument& document, std::string id);
    void redo() override;
    void undo() override;

private:
    StudyDocument& m_document;
    std::string m_id;
};

/// Records the artifacts that a task has just added (a wall run: its stress mesh and its Run), so that undo removes
/// them and redo brings them back.
class AddedArtifactCommand : public QUndoCommand
{
public:
    AddedArtifactCommand(StudyDocument& document, std::string id, const QString& description);
    AddedArtifactCommand(StudyDocument& document, std::vector<std::string> ids, const QString& description);
    void redo() override;
    void undo() override;

private:
    StudyDocument& m_document;
    std::vector<std::string> m_ids;
    bool m_firstRedo = true;
};

} // namespace vsim::gui
