#pragma once

// What a SliceView draws, shared by its files (SliceView.cpp: the slice and its state; SliceViewInput.cpp: the
// mouse, the wheel, the keys and the measurement drawing).

#include "SliceFieldLayer.h"
#include "SliceMarkerLayer.h"
#include "SliceMeasurementLayer.h"
#include "SliceOverlayLayer.h"

#include "vsim/viz/SliceView.h"

#include <vtkImageActor.h>
#include <vtkImageData.h>
#include <vtkImageMapToColors.h>
#include <vtkImageReslice.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>

#include <array>
#include <memory>

namespace vsim::viz {

struct SliceView::Pipeline
{
    vtkSmartPointer<vtkImageData> scaledIndexImage; // the CT in "index * spacing" space, sharing its voxels
    vtkSmartPointer<vtkImageReslice> reslice = vtkSmartPointer<vtkImageReslice>::New();
    vtkSmartPointer<vtkImageActor> actor = vtkSmartPointer<vtkImageActor>::New();
    // The label overlay: same reslice axes, nearest neighbour, translucent colours per value (see the table).
    vtkSmartPointer<vtkImageData> scaledIndexLabel;
    vtkSmartPointer<vtkImageReslice> labelReslice = vtkSmartPointer<vtkImageReslice>::New();
    vtkSmartPointer<vtkImageMapToColors> labelColours = vtkSmartPointer<vtkImageMapToColors>::New();
    vtkSmartPointer<vtkImageActor> labelActor = vtkSmartPointer<vtkImageActor>::New();
    std::array<vtkSmartPointer<vtkTextActor>, 4> edgeLabels; // left, right, top, bottom
    std::unique_ptr<SliceMarkerLayer> markers;
    std::unique_ptr<SliceFieldLayer> field;
    std::unique_ptr<SliceOverlayLayer> overlay;
    std::unique_ptr<SliceMeasurementLayer> measurements;
};

} // namespace vsim::viz
