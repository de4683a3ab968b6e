#pragma once
// share/office, made from scratch: the office floor plan (OfficeFloorPlan) as a grid map, its
// ground truth (room labels, doors), and a simulated robot log of a tour through every room
// with its ground-truth trajectory. `toposlam-sim --make-office <dir>` calls this, so the bundled
// data can always be regenerated bit for bit from the code and config_ini/sim-office.ini.
#include <toposlam/io/ProgressCallback.h>
#include <toposlam/simulation/SimulatorConfig.h>

#include <string>
#include <vector>

namespace toposlam::simulation {

struct OfficeDataset {
    static constexpr double kResolution = 0.05;  ///< m per cell
    static constexpr double kMargin = 0.5;       ///< m of unknown space around the building

    std::vector<std::string> files;  ///< every file written, in order
    std::size_t scans = 0;
    double tourLength = 0;         ///< m
    double duration = 0;           ///< s, from the first to the last scan
    std::size_t roomsVisited = 0;  ///< rooms (incl. the corridor) with a tour pose inside
    std::size_t rooms = 0;
};

/// The names of the files writeOfficeDataset writes, in the order listed below.
std::vector<std::string> officeDatasetFileNames();

/// Writes into `dir` (created if needed), all of the files or none:
///   office.gridmap.gz        the map (MRPT serialization)
///   office.png               the same map as a picture (grey p(free))
///   office.yaml, office.pgm  the same map as a ROS map_server pair (trinary)
///   office_rooms.png         ground-truth room labels: 8-bit, pixel = room id, 0 = none
///   office_rooms.json        rooms (id, name, kind, floor box) and doors (jambs, width, rooms)
///   office.rawlog            the simulated log (config.format; 'config' gives every parameter)
///   office_gt.txt            its ground-truth trajectory (timestamp x y yaw)
///   office_tour.png          a picture of the tour over the map
/// `progress`: of the log's simulation (scans written).
OfficeDataset writeOfficeDataset(const std::string& dir, const SimulatorConfig& config,
                                 const io::ProgressCallback& progress = {});

}  // namespace toposlam::simulation
