#include "ViewLayout.h"

#include "vsim/viz/SliceView.h"
#include "vsim/viz/VolumeView3D.h"

#include <QGridLayout>

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
    grid->addWidget(m_sliceViews[0], 0, 0);
    grid->addWidget(m_volumeView, 0, 1);
    grid->addWidget(m_sliceViews[1], 1, 0);
    grid->addWidget(m_sliceViews[2], 1, 1);

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
