#pragma once

#include "vsim/core/ImageVolume.h"
#include "vsim/imaging/LabelEditing.h"

#include <QObject>
#include <QUndoCommand>

#include <memory>
#include <string>

namespace vsim::gui {

/// Manual correction of one vessel label: a working copy of the study's label that brush strokes paint or
/// erase (each stroke one undo step); apply() turns the edited copy into a new label artifact (the original
/// stays, provenance names it and counts the edits).
class LabelEditSession : public QObject
{
    Q_OBJECT
public:
    LabelEditSession(std::string sourceId, const LabelVolume& source, QObject* parent = nullptr);

    const std::string& sourceId() const { return m_sourceId; }
    /// The working copy the views overlay (edited in place).
    const LabelVolume& label() const { return m_label; }
    /// One dab of the current stroke: writes `value` (1 lumen, 4 thrombus, 5 wall; 0 erases) in a disc of
    /// `radiusMm` in the view's plane, or in a ball of that radius through the slices (`sphere`).
    void dab(const Eigen::Vector3d& centreMm, const Eigen::Vector3d& planeNormal, double radiusMm, std::uint8_t value,
             bool sphere);
    /// Ends the stroke; returns the undo command that holds it (already applied), or nullptr if nothing changed.
    QUndoCommand* finishStroke();
    /// Removes the connected piece of the label at `pointMm` (imaging::removeIsland); returns its undo command
    /// (already applied), or nullptr when no labelled voxel is within 3 mm.
    QUndoCommand* removeIsland(const Eigen::Vector3d& pointMm);
    /// Voxels set to 1 and to 0 by the strokes in effect now.
    std::size_t paintedVoxels() const { return m_painted; }
    std::size_t erasedVoxels() const { return m_erased; }
    bool hasEdits() const { return m_painted + m_erased > 0; }

    /// Used by the stroke command: redo / undo of a stroke.
    void reapply(const imaging::LabelEdit& edit);
    void revert(const imaging::LabelEdit& edit);

signals:
    /// The working label's voxels changed: redraw the overlays.
    void labelChanged();

private:
    void count(const imaging::LabelEdit& edit, int sign);

    std::string m_sourceId;
    LabelVolume m_label;
    imaging::LabelEdit m_stroke;
    std::size_t m_painted = 0;
    std::size_t m_erased = 0;
};

} // namespace vsim::gui
