#pragma once
// How far a scan's readings go into the submaps. Far readings are the noisy ones (a beam's
// footprint and its angular error grow with range, and grazing ones hit no wall at all), so
// indoors the maps keep what lies within map_max_range. In an open hall or with a long-range
// laser the far part is where the structure is: there a scan with more than map_far_share of
// its valid readings beyond map_max_range puts all of them in.
#include <toposlam/mapping/GraphSlamOptions.h>
#include <toposlam/matching/PolarScan.h>

namespace toposlam::mapping {

/// Range (m) up to which `scan`'s readings go into the maps (and count as mappable):
/// options.mapMaxRange, or the sensor's maximum range when more than options.mapFarShare of
/// the valid readings lie beyond mapMaxRange.
double mapRange(const matching::PolarScan& scan, const GraphSlamOptions& options);

}  // namespace toposlam::mapping
