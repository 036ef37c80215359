#pragma once

// The virtual endoscope's picture (issue 20, item 8; thesis 5.5.2): a camera inside the vessel looking along
// it, the lumen wall lit by the probe's lamp, a flow run's particles drawn as blood cells (spheres flattened
// to a disc, as the thesis models them), seen through the lens of EndoscopeOptics.h. VTK renders the sharp
// picture and its depth offscreen; the lens is applied on the CPU and the result painted. The pose and lens
// come from the panel that flies the camera (app EndoscopePanel).

#include "vsim/core/TriangleMesh.h"
#include "vsim/viz/EndoscopeOptics.h"

#include <Eigen/Core>

#include <QImage>
#include <QWidget>

#include <memory>
#include <vector>

namespace vsim::viz {

class EndoscopeView : public QWidget
{
    Q_OBJECT

public:
    explicit EndoscopeView(QWidget* parent = nullptr);
    ~EndoscopeView() override;

    /// The lumen's surface (mm, outward normals: the camera sees its inside).
    void setLumen(const TriangleMesh& surface);
    bool hasLumen() const;
    /// A flow run's particles (mm) as blood cells of `radiusMm`; an empty list clears them.
    void setParticles(const std::vector<Eigen::Vector3d>& pointsMm, double radiusMm);
    std::size_t particleCount() const;
    /// The camera at `positionMm` looking along `forward`, `up` the picture's top (both unit, perpendicular).
    void setPose(const Eigen::Vector3d& positionMm, const Eigen::Vector3d& forward,
                 const Eigen::Vector3d& up);
    void setLens(const EndoscopeLens& lens);
    const EndoscopeLens& lens() const { return m_lens; }

    /// What the probe shows now (rendered if anything changed since), at the widget's size in device pixels
    /// (at most kMaxWidthPx across).
    QImage picture();
    /// The same before the lens (sharp, unlit by the lamp): for tests and comparisons.
    QImage sharpPicture();
    /// The depth (mm along the view axis) of each pixel of the last picture, row-major from the top; infinity
    /// where the wall was not hit.
    const std::vector<float>& depthMm() const { return m_depth; }
    /// The defocus of the last picture: the median blur (pixels) that sets its noise.
    double medianBlurPx() const { return m_medianBlurPx; }

    static constexpr int kMaxWidthPx = 640;

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    void renderIfNeeded();

    struct Pipeline;
    std::unique_ptr<Pipeline> m_pipeline;
    EndoscopeLens m_lens;
    bool m_dirty = true;
    unsigned m_frame = 0;
    QImage m_sharp, m_picture;
    std::vector<float> m_depth;
    double m_medianBlurPx = 0.0;
};

} // namespace vsim::viz
