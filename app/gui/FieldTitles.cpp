#include "FieldTitles.h"

#include <QCoreApplication>

#include <map>

namespace vsim::gui {

QString fieldTitle(const QString& key)
{
    // The frames' fields of every solver (wall FEM, drug network and filling, SPH, smoke, heat) and the wall loads.
    static const std::map<QString, const char*> titles = {
        {"von_mises_kpa", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "von Mises stress (kPa)")},
        {"max_principal_kpa", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "maximum principal stress (kPa)")},
        {"wall_strength_kpa", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "wall strength (kPa)")},
        {"rupture_index", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "rupture potential index")},
        {"material", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "material")},
        {"displacement_mm", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "displacement (mm)")},
        {"displacement_x_mm", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "displacement x (mm)")},
        {"displacement_y_mm", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "displacement y (mm)")},
        {"displacement_z_mm", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "displacement z (mm)")},
        {"drug_flow_ml_min", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "drug flow (ml/min)")},
        {"liquid_flow_ml_min", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "drug flow, liquid only (ml/min)")},
        {"flow_ml_min", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "flow (ml/min)")},
        {"velocity_mm_s", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "mean velocity (mm/s)")},
        {"pressure_from_mmhg", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "pressure at the segment's start (mmHg)")},
        {"pressure_to_mmhg", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "pressure at the segment's end (mmHg)")},
        {"reynolds", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "Reynolds number")},
        {"injected_percent", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "injected share of the flow (%)")},
        {"downstream", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "downstream of the catheter's tip")},
        {"fill_enter_s", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "drug front enters the segment (s)")},
        {"fill_leave_s", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "drug front leaves the segment (s)")},
        {"filled_length_mm", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "filled length (mm)")},
        {"filled_fraction", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "filled fraction")},
        {"speed_m_s", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "speed (m/s)")},
        {"velocity_x_m_s", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "velocity x (m/s)")},
        {"velocity_y_m_s", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "velocity y (m/s)")},
        {"velocity_z_m_s", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "velocity z (m/s)")},
        {"pressure_pa", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "pressure (Pa)")},
        {"density_kg_m3", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "density (kg/m\u00b3)")},
        {"void_fraction", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "void fraction")},
        {"wall", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "wall particle")},
        {"open_boundary", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "open boundary")},
        {"tracer", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "tracer")},
        {"tawss_pa", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "time-averaged wall shear stress (Pa)")},
        {"osi", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "oscillatory shear index")},
        {"wall_pressure_pa", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "wall pressure (Pa)")},
        {"smoke_density_mg_m3", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "smoke density (mg/m\u00b3)")},
        {"temperature_rise_k", QT_TRANSLATE_NOOP("vsim::gui::FieldTitles", "temperature rise (K)")},
    };
    const auto found = titles.find(key);
    return found == titles.end() ? key : QCoreApplication::translate("vsim::gui::FieldTitles", found->second);
}

} // namespace vsim::gui
