#include <mrpt/core/initializer.h>
#include <mrpt/rtti/CObject.h>
#include <toposlam/classes/TopoSlamClasses.h>
#include <toposlam/features/CObservationLaserFeatures.h>
#include <toposlam/matching/CScanFeaturesMap.h>
#include <toposlam/rooms/CTopologicalMap.h>

#include <array>

namespace toposlam::classes {

namespace {

std::array<const mrpt::rtti::TRuntimeClassId*, 3> classIds() {
    return {CLASS_ID(features::CObservationLaserFeatures), CLASS_ID(matching::CScanFeaturesMap),
            CLASS_ID(rooms::CTopologicalMap)};
}

}  // namespace

void registerTopoSlamClasses() {
    for (const mrpt::rtti::TRuntimeClassId* id : classIds())
        mrpt::rtti::registerClass(id);
}

std::vector<std::string> topoSlamClassNames() {
    std::vector<std::string> names;
    for (const mrpt::rtti::TRuntimeClassId* id : classIds())
        names.emplace_back(id->className);
    return names;
}

}  // namespace toposlam::classes

// Linking this library is enough: it registers the classes when the program starts.
MRPT_INITIALIZER(toposlam_register_all_classes) {
    toposlam::classes::registerTopoSlamClasses();
}
