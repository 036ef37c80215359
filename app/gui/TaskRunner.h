#pragma once

#include "vsim/core/Progress.h"

#include <QFutureWatcher>
#include <QObject>
#include <QString>

#include <functional>

namespace vsim::gui {

/// Runs one long task at a time off the GUI thread with progress and Cancel. The work function runs on a pool
/// thread and must not touch widgets; `onSuccess` runs afterwards on the GUI thread. vsim::Error and other
/// exceptions become failed(); vsim::Cancelled becomes cancelled(). `onSuccess` may start the next task; idle() is
/// emitted once no task runs.
class TaskRunner : public QObject
{
    Q_OBJECT
public:
    using Work = std::function<void(const Progress&)>;

    explicit TaskRunner(QObject* parent = nullptr);
    ~TaskRunner() override;

    bool isBusy() const { return m_busy; }
    /// Starts `work`; returns false (and does nothing) while another task runs.
    bool run(const QString& title, Work work, std::function<void()> onSuccess = {});
    /// Asks the running task to stop at its next progress report.
    void cancel();
    /// Blocks until the running task has finished (used on close and in tests).
    void waitForFinished();

signals:
    void started(const QString& title);
    void progressChanged(double fraction, const QString& stage);
    void succeeded(const QString& title);
    void failed(const QString& title, const QString& message);
    void cancelled(const QString& title);
    void idle();

private:
    QFutureWatcher<void> m_watcher;
    CancellationToken m_token;
    QString m_title;
    QString m_error;
    bool m_wasCancelled = false;
    bool m_busy = false;
    std::function<void()> m_onSuccess;
    int m_lastPercent = -1;
};

} // namespace vsim::gui
