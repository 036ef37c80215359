#include "TaskRunner.h"

#include "vsim/core/Error.h"

#include <QtConcurrent/QtConcurrentRun>

namespace vsim::gui {

TaskRunner::TaskRunner(QObject* parent) : QObject(parent)
{
    connect(&m_watcher, &QFutureWatcher<void>::finished, this, [this] {
        m_busy = false;
        if (m_wasCancelled)
            emit cancelled(m_title);
        else if (!m_error.isEmpty())
            emit failed(m_title, m_error);
        else
        {
            if (m_onSuccess)
            {
                try
                {
                    m_onSuccess();
                }
                catch (const std::exception& error)
                {
                    emit failed(m_title, QString::fromStdString(error.what()));
                    emit idle();
                    return;
                }
            }
            emit succeeded(m_title);
        }
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
            m_error = QString::fromStdString(error.what());
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
