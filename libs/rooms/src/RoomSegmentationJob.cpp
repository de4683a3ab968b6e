#include <toposlam/io/AtomicFile.h>
#include <toposlam/io/InputError.h>
#include <toposlam/io/Trajectory.h>
#include <toposlam/rooms/CTopologicalMap.h>
#include <toposlam/rooms/RoomSegmentationJob.h>
#include <toposlam/rooms/TopologicalMapIO.h>
#include <toposlam/rooms/TopologicalMapRendering.h>

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <opencv2/imgcodecs.hpp>

#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace toposlam::rooms {

RoomSegmenter::Result runRoomSegmentationJob(const RoomSegmentationJob& job) {
    const auto grid = io::loadGridMap(job.mapPath, job.geometry);
    std::vector<mrpt::math::TPose2D> poses;
    if (!job.trajectoryPath.empty()) {
        for (const auto& p : io::loadTrajectory(job.trajectoryPath))
            poses.push_back(p.pose);
        if (poses.empty())
            throw io::InputError(job.trajectoryPath, "the trajectory has no poses");
    }
    const RoomSegmenter segmenter(job.options);
    RoomSegmenter::Result result = segmenter.segment(grid, poses, job.mapPath);
    if (result.fromTrajectory && result.trajectoryCells == 0) {
        throw io::InputError(job.trajectoryPath,
                             "no pose of the trajectory lies in the map's free space (wrong "
                             "frame or wrong file?)");
    }
    return result;
}

std::vector<std::string> roomSegmentationFileNames() {
    return {"rooms.json", "rooms.graphml", "rooms.png", "rooms-steps.png", "rooms.topomap.gz"};
}

std::vector<std::string> writeRoomSegmentationFiles(const RoomSegmenter::Result& result,
                                                    const std::string& dir, int scale) {
    if (scale < 1 || scale > 8)
        throw std::invalid_argument("scale must be 1-8 pixels per cell, not " +
                                    std::to_string(scale));
    const std::filesystem::path folder(dir);
    std::filesystem::create_directories(folder);
    std::vector<std::string> files;
    for (const std::string& name : roomSegmentationFileNames())
        files.push_back((folder / name).string());
    io::OutputGroup outputs;  // all five files, or none (a folder never mixes two runs)
    saveTopologicalMapJson(result.map, files[0]);
    saveTopologicalMapGraphML(result.map, files[1]);
    RenderOptions render;
    render.scale = scale;
    render.doorIds = true;
    saveTopologicalMapPng(result.map, files[2], render);
    // What each step saw, over the binarised map.
    cv::Mat free(result.map.labels.size(), CV_8U, cv::Scalar(0));
    free.setTo(255, result.map.labels > 0);
    const cv::Mat steps = renderDiagnostics(result, free);
    io::writeFileAtomically(files[3], [&](const std::string& tmp) {
        if (!cv::imwrite(tmp, steps))
            throw std::runtime_error(files[3] + ": cannot write the PNG");
    });
    io::writeFileAtomically(files[4], [&](const std::string& tmp) {
        mrpt::io::CFileGZOutputStream out(tmp);
        mrpt::serialization::archiveFrom(out) << CTopologicalMap(result.map);
    });
    outputs.commit();
    return files;
}

std::string describeRoomSegmentation(const RoomSegmenter::Result& result,
                                     const std::string& mapName) {
    const TopologicalMap& m = result.map;
    std::string text;
    char line[256];
    std::snprintf(line, sizeof line,
                  "%s: %zu rooms, %zu doors (%s search, %zu candidate doors, %.1f ms)\n",
                  mapName.c_str(), m.rooms.size(), m.doors.size(),
                  result.fromTrajectory ? "trajectory" : "medial-axis", result.candidates.size(),
                  result.milliseconds);
    text += line;
    if (result.specksRemoved > 0 || result.unseenHolesFreed > 0) {
        std::snprintf(line, sizeof line,
                      "  cleaned up: specks in the free space made free %zu, unseen holes in "
                      "the floor counted as floor %zu (%.2f m^2)\n",
                      result.specksRemoved, result.unseenHolesFreed, result.unseenHoleArea);
        text += line;
    }
    for (const Room& r : m.rooms) {
        std::snprintf(line, sizeof line,
                      "  room %3d  %8.2f m^2  centroid (%.2f, %.2f)  neighbours:", r.id, r.area,
                      r.centroid.x, r.centroid.y);
        text += line;
        for (int n : m.neighbours(r.id))
            text += " " + std::to_string(n);
        text += "\n";
    }
    for (const Door& d : m.doors) {
        std::snprintf(line, sizeof line, "  door %3d  rooms %d-%d  %.2f m wide at (%.2f, %.2f)\n",
                      d.id, d.roomA, d.roomB, d.width, d.middle().x, d.middle().y);
        text += line;
    }
    return text;
}

}  // namespace toposlam::rooms
