#include "TaskRunner.h"

#include "vsim/core/Error.h"

#include <QtConcurrent/QtConcurrentRun>

namespace vsim::gui {

TaskRunner::TaskRunner(QObject* parent) : QObject(parent)
{
    connect(&m_watcher, &QFutureWatcher<void>::finished, this, [this] {
        m_busy = false;
        const QString title = m_title;
        // The success step may start the next task (e.g. opening a study, then preparing its views): it runs from
        // a local copy, and idle is told only when no task follows.
        const std::function<void()> onSuccess = std::move(m_onSuccess);
        m_onSuccess = nullptr;
        if (m_wasCancelled)
            emit cancelled(title);
        else if (!m_error.isEmpty())
            emit failed(title, m_error);
        else
        {
            if (onSuccess)
            {
                try
                {
                    onSuccess();
                }
                catch (const std::exception& error)
                {
                    emit failed(title, QString::fromStdString(textForPeople(error)));
                    if (!m_busy)
                        emit idle();
                    return;
                }
            }
            emit succeeded(title);
        }
        if (!m_busy)
            emit idle();
    });
}

TaskRunner::~TaskRunner()
{
    cancel();
    waitForFinished();
}

bool TaskRunner::run(const QString& title, Work work, std::function<void()> onSuccess)
{
    if (m_busy)
        return false;
    m_busy = true;
    m_title = title;
    m_error.clear();
    m_wasCancelled = false;
    m_onSuccess = std::move(onSuccess);
    m_token = CancellationToken();
    m_lastPercent = -1;
    const Progress progress(
        [this](double fraction, const std::string& stage) {
            const int percent = static_cast<int>(fraction * 100.0);
            if (percent == m_lastPercent)
                return;
            m_lastPercent = percent;
            QMetaObject::invokeMethod(
                this, [this, fraction, text = QString::fromStdString(stage)] { emit progressChanged(fraction, text); },
                Qt::QueuedConnection);
        },
        m_token);
    emit started(title);
    m_watcher.setFuture(QtConcurrent::run([this, work = std::move(work), progress] {
        try
        {
            work(progress);
        }
        catch (const Cancelled&)
        {
            m_wasCancelled = true;
        }
        catch (const std::exception& error)
        {
            m_error = QString::fromStdString(textForPeople(error));
        }
    }));
    return true;
}

void TaskRunner::cancel()
{
    m_token.cancel();
}

void TaskRunner::waitForFinished()
{
    m_watcher.waitForFinished();
}

} // namespace vsim::gui
