#pragma once
// What toposlam-slam writes of a SLAM run, and its summary.
//   trajectory.txt       every scan's robot pose, 'timestamp x y yaw' (stamps as in the log)
//   map.gridmap.gz       the occupancy grid (MRPT serialization)
//   map.png + map.yaml   the grid as an image and its ROS map_server description
//   keyframes.graph      the keyframe pose graph, MRPT's .graph text format (graph engine)
//   keyframes.simplemap  the keyframes: pose + sensory frame with the scan and its
//                        CObservationLaserFeatures, gzip (graph engine; observations2map and
//                        RawLogViewer read it with TopoSLAM's plugin loaded)
//   summary.txt          the summary below
//   summary.json         the same as JSON (keys: see share/doc/apps.md, toposlam-slam)
// Every file is written atomically (temporary file, then rename).
#include <toposlam/mapping/LogMapper.h>
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace toposlam::mapping {

/// Log duration / wall time, or none where the log's stamps do not tell its time (less than
/// 1 ms a scan on average: a log whose stamps were lost).
std::optional<double> realTimeFactor(const MappingResult& result);

/// The run in a few lines: scans, keyframes, how scans were registered, loops, optimisation
/// and wall time, real-time factor; a loud WARNING line when most scans could not be
/// registered (the trajectory is then mostly odometry and must not be taken for a map), and
/// one when ICP registered less than 90 % of them (weakFrontEnd).
std::string formatSummary(const MappingResult& result);

/// The summary as JSON: engine, scans, log_duration_s, wall_s, cpu_s, real_time_factor (null
/// without one), wall_alignment_deg; graph engine also keyframes, submaps, registration {icp,
/// icp_unsettled, icp_second_start, icp_unsettled_refused, icp_refuted_beyond_jump,
/// icp_without_foreground, icp_short_of_turn, icp_short_of_turn_replaced,
/// icp_wide_turn_starts, icp_outfitted_matcher, graph_matcher, failed, odometry_jumps,
/// odometry_catch_ups, odometry_catch_ups_kept, registered_share}, loops {candidates, accepted,
/// guess_free_accepted, contested_accepted, lever_arm_accepted, unmatched, rejected, withdrawn,
/// unconfirmed, open_at_end, largest_open_at_end {from_stamp, to_stamp, distance_m, angle_deg}
/// (only with one), guess_free_search, contested_rule, lever_arm_gate}, cpu_by_stage_s
/// {front_end, loop_search, loop_search_on_workers, optimization}, optimizations,
/// mostly_unregistered, weak_front_end, open_loop_at_end.
nlohmann::json summaryJson(const MappingResult& result);

/// True when fewer than half of the scans were registered (graph engine).
bool mostlyUnregistered(const MappingResult& result);

/// True when loops found in the log's last keyframes still awaited a second, agreeing match
/// at its end and would have moved the map by more than optimize_global_distance or
/// optimize_global_angle (graph engine; SlamStatistics::loopsOpenAtEnd): either the map is
/// open there or the scans fit a look-alike place. summary.txt warns (with the stamps of the
/// largest), summary.json says open_loop_at_end.
bool openLoopAtEnd(const MappingResult& result);

/// True when, though most scans were registered, fewer than 90 % were registered by ICP
/// against the local map (graph engine): the front end struggled (a narrow field of view,
/// bare walls, crowds), and the map may be distorted. intel, fr079 and mit-csail stay above
/// 99 %; a simulated 58 deg laser (a depth camera's scan) falls to 69-85 % and maps worse
/// than its odometry (benchmarks.md, B3).
bool weakFrontEnd(const MappingResult& result);

/// The names of every file above, those only the graph engine writes too (an app checks
/// them against its inputs before the run).
std::vector<std::string> mappingOutputFileNames();

/// Writes the files above into `directory` (created); returns their paths in that order.
std::vector<std::string> saveMappingOutputs(const MappingResult& result,
                                            const std::string& directory);

}  // namespace toposlam::mapping
