#include "ViewState.h"

#include <nlohmann/json.hpp>

namespace vsim::gui {
namespace {

using Json = nlohmann::json;

Json cameraJson(const viz::CameraState& c)
{
    return {{"position", c.position}, {"focal_point", c.focalPoint}, {"view_up", c.viewUp},
            {"parallel_scale", c.parallelScale}, {"view_angle", c.viewAngle}, {"parallel", c.parallel}};
}

viz::CameraState cameraFrom(const Json& j)
{
    viz::CameraState c;
    c.position = j.at("position").get<std::array<double, 3>>();
    c.focalPoint = j.at("focal_point").get<std::array<double, 3>>();
    c.viewUp = j.at("view_up").get<std::array<double, 3>>();
    c.parallelScale = j.at("parallel_scale").get<double>();
    c.viewAngle = j.at("view_angle").get<double>();
    c.parallel = j.at("parallel").get<bool>();
    return c;
}

} // namespace

std::string ViewState::toJson() const
{
    Json j{{"version", 1}, {"hidden_artifacts", hiddenArtifacts}};
    if (cursorMm)
        j["cursor_mm"] = {cursorMm->x(), cursorMm->y(), cursorMm->z()};
    if (windowLevel)
        j["window_level"] = {windowLevel->window, windowLevel->level};
    if (sliceFieldsOfViewMm)
        j["slice_fields_of_view_mm"] = *sliceFieldsOfViewMm;
    if (sliceViewCentresMm)
        for (const Eigen::Vector3d& centre : *sliceViewCentresMm)
            j["slice_view_centres_mm"].push_back({centre.x(), centre.y(), centre.z()});
    if (camera3d)
        j["camera_3d"] = cameraJson(*camera3d);
    return j.dump();
}

ViewState ViewState::fromJson(const std::string& text)
{
    ViewState state;
    try
    {
        const Json j = Json::parse(text);
        state.hiddenArtifacts = j.value("hidden_artifacts", std::set<std::string>{});
        if (j.contains("cursor_mm"))
        {
            const auto xyz = j.at("cursor_mm").get<std::array<double, 3>>();
            state.cursorMm = Eigen::Vector3d(xyz[0], xyz[1], xyz[2]);
        }
        if (j.contains("window_level"))
        {
            const auto wl = j.at("window_level").get<std::array<double, 2>>();
            state.windowLevel = viz::WindowLevel{wl[0], wl[1]};
        }
        if (j.contains("slice_fields_of_view_mm"))
            state.sliceFieldsOfViewMm = j.at("slice_fields_of_view_mm").get<std::array<double, 3>>();
        if (j.contains("slice_view_centres_mm"))
        {
            const auto centres = j.at("slice_view_centres_mm").get<std::array<std::array<double, 3>, 3>>();
            std::array<Eigen::Vector3d, 3> read;
            for (std::size_t v = 0; v < 3; ++v)
                read[v] = Eigen::Vector3d(centres[v][0], centres[v][1], centres[v][2]);
            state.sliceViewCentresMm = read;
        }
        if (j.contains("camera_3d"))
            state.camera3d = cameraFrom(j.at("camera_3d"));
    }
    catch (const nlohmann::json::exception&)
    {
        return {}; // an older or damaged record: the views start as for a new study
    }
    return state;
}

} // namespace vsim::gui
