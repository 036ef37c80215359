// The one list of VascuSim's parameter tables (ParameterCatalogue.h).
#include "vsim/app/ParameterCatalogue.h"

#include "vsim/app/BloodFlowPipeline.h"
#include "vsim/app/InjectionPipeline.h"
#include "vsim/app/WallPipeline.h"
#include "vsim/imaging/Centerlines.h"
#include "vsim/imaging/GuidedSegmentation.h"
#include "vsim/imaging/LesionGrowing.h"
#include "vsim/imaging/OrganGrowing.h"
#include "vsim/imaging/Skeletonization.h"
#include "vsim/imaging/VesselMeasurements.h"
#include "vsim/imaging/VesselSegmentation.h"
#include "vsim/mesh/VesselSurface.h"
#include "vsim/sim/common/RunDriver.h"
#include "vsim/sim/fem/FemProtocols.h"
#include "vsim/sim/heat/HeatDiffusion.h"
#include "vsim/sim/network/NetworkRun.h"
#include "vsim/sim/network/Territories.h"
#include "vsim/sim/smoke/SmokeSolver.h"
#include "vsim/sim/sph/SphSolver.h"

#include <nlohmann/json.hpp>

namespace vsim::app {

std::vector<ParameterTable> parameterCatalogue()
{
    return {
        {"segmentation", imaging::segmentationParameters()},
        {"guided-segmentation", imaging::guidedSegmentationParameters()},
        {"organ", imaging::organGrowingParameters()},
        {"lesion", imaging::lesionGrowingParameters()},
        {"surface", mesh::surfaceParameters()},
        {"skeleton", imaging::skeletonParameters()},
        {"centerline", imaging::centerlineParameters()},
        {"measurement", imaging::measurementParameters()},
        {"wall-mesh", wallMeshParameters()},
        {"fem", sim::fem::femParameters()},
        {"network", sim::network::networkParameters()},
        {"territories", sim::network::territoryParameters()},
        {"blood-flow", bloodFlowSetupParameters()},
        {"sph", sim::sph::sphParameters()},
        {"injection", injectionSetupParameters()},
        {"smoke", sim::smoke::smokeParameters()},
        {"heat", sim::heat::heatParameters()},
        {"run-control", sim::runControlParameters()},
    };
}

std::string parameterCatalogueJson(const std::vector<ParameterTable>& tables)
{
    nlohmann::json listed = nlohmann::json::array();
    for (const ParameterTable& table : tables)
    {
        nlohmann::json parameters = nlohmann::json::array();
        for (const ParameterSpec& spec : table.specs)
            parameters.push_back({{"key", spec.key},
                                  {"label", spec.label},
                                  {"unit", spec.unit},
                                  {"default", spec.defaultValue},
                                  {"minimum", spec.minimum},
                                  {"maximum", spec.maximum},
                                  {"group", spec.group},
                                  {"description", spec.description},
                                  {"kind", spec.kind == ParameterSpec::Kind::Integer ? "integer" : "real"}});
        listed.push_back({{"table", table.name}, {"parameters", parameters}});
    }
    return listed.dump(2);
}

} // namespace vsim::app
