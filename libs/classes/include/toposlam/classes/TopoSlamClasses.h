#pragma once
// TopoSLAM's serializable classes, known to every program that reads logs.
//
// TopoSLAM writes its own MRPT objects into rawlogs and other archives: scan features
// (toposlam::features::CObservationLaserFeatures, from toposlam-annotate-features), feature
// maps (toposlam::matching::CScanFeaturesMap) and topological maps
// (toposlam::rooms::CTopologicalMap). MRPT can only read an object whose class is registered
// in the running program; otherwise it stops at it ("class ... is not registered"). Each
// library registers its classes when it is loaded, but libs/io, which reads the logs, sits
// below those libraries and cannot load them: programs that read logs link this library
// (toposlam::classes), which registers them all when the program starts; calling
// registerTopoSlamClasses() says so in the code. (MRPT's own tools load libtoposlam-plugin.so
// for the same purpose.)
#include <string>
#include <vector>

namespace toposlam::classes {

/// Registers every class listed by topoSlamClassNames() with mrpt-rtti. Idempotent.
void registerTopoSlamClasses();

/// The registered names, e.g. "toposlam::features::CObservationLaserFeatures".
std::vector<std::string> topoSlamClassNames();

}  // namespace toposlam::classes
