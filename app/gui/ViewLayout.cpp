#include "ViewLayout.h"

#include "VesselViewPanel.h"

#include "vsim/viz/SliceView.h"
#include "vsim/viz/VolumeView3D.h"

#include <QEvent>
#include <QGridLayout>

#include <algorithm>
#include <vector>

namespace vsim::gui {

ViewLayout::ViewLayout(QWidget* parent) : QWidget(parent)
{
    using viz::SliceOrientation;
    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->setSpacing(2);
    const SliceOrientation orientations[3] = {SliceOrientation::Axial, SliceOrientation::Coronal,
                                              SliceOrientation::Sagittal};
    for (int v = 0; v < 3; ++v)
    {
        m_sliceViews[v] = new viz::SliceView(orientations[v], this);
        m_sliceViews[v]->setObjectName(v == 0 ? "axialView" : v == 1 ? "coronalView" : "sagittalView");
    }
    m_volumeView = new viz::VolumeView3D(this);
    m_volumeView->setObjectName("volumeView");
    m_vesselPanel = new VesselViewPanel(this);
    m_mainView = m_sliceViews[0];
    for (QWidget* view : {static_cast<QWidget*>(m_sliceViews[0]), static_cast<QWidget*>(m_sliceViews[1]),
                          static_cast<QWidget*>(m_sliceViews[2]), static_cast<QWidget*>(m_volumeView)})
        view->installEventFilter(this); // which view the user works in
    setLayoutMode(LayoutMode::TwoByTwo);

    for (viz::SliceView* source : m_sliceViews)
    {
        connect(source, &viz::SliceView::cursorChanged, this, [this](const Eigen::Vector3d& cursor) {
            if (!m_linked)
                return;
            for (viz::SliceView* target : m_sliceViews)
                target->setCursor(cursor); // a view whose cursor is already there does not emit again
        });
        connect(source, &viz::SliceView::windowLevelChanged, this, [this](double window, double level) {
            if (!m_linked)
                return;
            for (viz::SliceView* target : m_sliceViews)
                if (target->windowLevel().window != window || target->windowLevel().level != level)
                    target->setWindowLevel({window, level});
        });
    }
}

void ViewLayout::setLayoutMode(LayoutMode mode)
{
    m_mode = mode;
    auto* grid = static_cast<QGridLayout*>(layout());
    QWidget* const views[5] = {m_sliceViews[0], m_sliceViews[1], m_sliceViews[2], m_volumeView, m_vesselPanel};
    for (QWidget* view : views)
        grid->removeWidget(view);
    for (int i = 0; i < 4; ++i)
    {
        grid->setRowStretch(i, 0);
        grid->setColumnStretch(i, 0);
    }
    std::vector<QWidget*> shown;
    switch (mode)
    {
    case LayoutMode::TwoByTwo:
        grid->addWidget(m_sliceViews[0], 0, 0);
        grid->addWidget(m_volumeView, 0, 1);
        grid->addWidget(m_sliceViews[1], 1, 0);
        grid->addWidget(m_sliceViews[2], 1, 1);
        shown = {views, views + 4};
        break;
    case LayoutMode::OneByOne:
        grid->addWidget(m_mainView, 0, 0);
        shown = {m_mainView};
        break;
    case LayoutMode::OneByThree:
        for (int v = 0; v < 3; ++v)
            grid->addWidget(m_sliceViews[std::size_t(v)], 0, v);
        shown = {views, views + 3};
        break;
    case LayoutMode::VolumePlusSlices:
        grid->addWidget(m_volumeView, 0, 0, 3, 1);
        for (int v = 0; v < 3; ++v)
            grid->addWidget(m_sliceViews[std::size_t(v)], v, 1);
        grid->setColumnStretch(0, 2);
        grid->setColumnStretch(1, 1);
        shown = {views, views + 4};
        break;
    case LayoutMode::VolumePlusCpr:
        grid->addWidget(m_volumeView, 0, 0);
        grid->addWidget(m_vesselPanel, 0, 1);
        grid->setColumnStretch(0, 1);
        grid->setColumnStretch(1, 1);
        shown = {m_volumeView, m_vesselPanel};
        break;
    }
    for (QWidget* view : views)
        view->setVisible(std::find(shown.begin(), shown.end(), view) != shown.end());
}

void ViewLayout::setMainView(QWidget* view)
{
    m_mainView = view ? view : m_sliceViews[0];
    if (m_mode == LayoutMode::OneByOne)
        setLayoutMode(m_mode);
}

QWidget* ViewLayout::activeView() const
{
    return m_activeView && m_activeView->isVisible() ? m_activeView : m_mainView;
}

bool ViewLayout::eventFilter(QObject* watched, QEvent* event)
{
    if (event->type() == QEvent::MouseButtonPress || event->type() == QEvent::FocusIn)
        m_activeView = static_cast<QWidget*>(watched);
    return QWidget::eventFilter(watched, event);
}

viz::SliceView* ViewLayout::sliceView(viz::SliceOrientation orientation) const
{
    return m_sliceViews[static_cast<int>(orientation)];
}

void ViewLayout::showImage(const CtVolume& image)
{
    for (viz::SliceView* view : m_sliceViews)
        image.isEmpty() ? view->clearImage() : view->setImage(image);
    image.isEmpty() ? m_volumeView->clearImage() : m_volumeView->setImage(image);
}

void ViewLayout::applyWindowLevel(const viz::WindowLevel& windowLevel)
{
    for (viz::SliceView* view : m_sliceViews)
        view->setWindowLevel(windowLevel);
}

void ViewLayout::jumpTo(const Eigen::Vector3d& pointMm)
{
    for (viz::SliceView* view : m_sliceViews)
    {
        view->setCursor(pointMm);
        view->ensureVisible(pointMm);
    }
}

void ViewLayout::resetViews()
{
    for (viz::SliceView* view : m_sliceViews)
        view->resetView();
}

void ViewLayout::setSlabThickness(double thicknessMm)
{
    for (viz::SliceView* view : m_sliceViews)
        view->setSlabThickness(thicknessMm);
}

void ViewLayout::setCrosshairShown(bool shown)
{
    for (viz::SliceView* view : m_sliceViews)
        view->setCrosshairShown(shown);
}

void ViewLayout::setPatientText(const QString& text)
{
    for (viz::SliceView* view : m_sliceViews)
        view->setPatientText(text);
}

} // namespace vsim::gui
