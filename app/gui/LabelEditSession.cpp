#include "LabelEditSession.h"

#include <QPointer>

namespace vsim::gui {
namespace {

/// One brush stroke; the first redo() is skipped because the stroke was applied while it was drawn.
class BrushStrokeCommand : public QUndoCommand
{
public:
    BrushStrokeCommand(LabelEditSession* session, imaging::LabelEdit edit)
        : QUndoCommand(edit.after ? QObject::tr("Paint label") : QObject::tr("Erase label")), m_session(session),
          m_edit(std::move(edit))
    {
    }
    void redo() override
    {
        if (m_firstRedo)
            m_firstRedo = false;
        else if (m_session)
            m_session->reapply(m_edit);
    }
    void undo() override
    {
        if (m_session)
            m_session->revert(m_edit);
    }

private:
    QPointer<LabelEditSession> m_session; // a finished session leaves its strokes in the stack harmless
    imaging::LabelEdit m_edit;
    bool m_firstRedo = true;
};

} // namespace

LabelEditSession::LabelEditSession(std::string sourceId, const LabelVolume& source, QObject* parent)
    : QObject(parent), m_sourceId(std::move(sourceId)), m_label(source.clone())
{
}

void LabelEditSession::dab(const Eigen::Vector3d& centreMm, const Eigen::Vector3d& planeNormal, double radiusMm,
                           std::uint8_t value, bool sphere)
{
    // A stroke writes one value (the brush mode cannot change during a drag; merge() checks it).
    m_stroke.merge(sphere ? imaging::paintBall(m_label, centreMm, radiusMm, value)
                          : imaging::paintDisc(m_label, centreMm, planeNormal, radiusMm, value));
    emit labelChanged();
}

QUndoCommand* LabelEditSession::finishStroke()
{
    if (m_stroke.empty())
        return nullptr;
    imaging::LabelEdit stroke = std::move(m_stroke);
    m_stroke = {};
    count(stroke, +1);
    return new BrushStrokeCommand(this, std::move(stroke));
}

QUndoCommand* LabelEditSession::removeIsland(const Eigen::Vector3d& pointMm)
{
    imaging::LabelEdit island = imaging::removeIsland(m_label, pointMm);
    if (island.empty())
        return nullptr;
    count(island, +1);
    emit labelChanged();
    auto* command = new BrushStrokeCommand(this, std::move(island));
    command->setText(QObject::tr("Remove island"));
    return command;
}

void LabelEditSession::reapply(const imaging::LabelEdit& edit)
{
    imaging::reapply(m_label, edit);
    count(edit, +1);
    emit labelChanged();
}

void LabelEditSession::revert(const imaging::LabelEdit& edit)
{
    imaging::revert(m_label, edit);
    count(edit, -1);
    emit labelChanged();
}

void LabelEditSession::count(const imaging::LabelEdit& edit, int sign)
{
    std::size_t& counter = edit.after ? m_painted : m_erased;
    counter = sign > 0 ? counter + edit.voxels.size() : counter - std::min(counter, edit.voxels.size());
}

} // namespace vsim::gui
