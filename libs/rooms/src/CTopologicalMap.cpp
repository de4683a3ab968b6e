#include <toposlam/rooms/CTopologicalMap.h>

#include <mrpt/rtti/CObject.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/serialization/stl_serialization.h>
#include <toposlam/io/ClassRegistration.h>

#include <cstdint>
#include <sstream>

namespace toposlam::rooms {

IMPLEMENTS_SERIALIZABLE(CTopologicalMap, CSerializable, toposlam::rooms)
TOPOSLAM_REGISTER_CLASS(CTopologicalMap)

uint8_t CTopologicalMap::serializeGetVersion() const {
    return 0;
}

void CTopologicalMap::serializeTo(mrpt::serialization::CArchive& out) const {
    const GridImageFrame& f = map.frame;
    out << f.resolution << f.xMin << f.yMin << static_cast<int32_t>(f.cols)
        << static_cast<int32_t>(f.rows);
    out << static_cast<uint32_t>(map.rooms.size());
    for (const Room& r : map.rooms) {
        out << static_cast<int32_t>(r.id) << r.name << r.area << r.centroid.x << r.centroid.y
            << r.anchor.x << r.anchor.y;
        std::vector<double> outline;
        outline.reserve(2 * r.outline.size());
        for (const auto& p : r.outline) {
            outline.push_back(p.x);
            outline.push_back(p.y);
        }
        out << outline;
    }
    out << static_cast<uint32_t>(map.doors.size());
    for (const Door& d : map.doors) {
        out << static_cast<int32_t>(d.id) << d.jambA.x << d.jambA.y << d.jambB.x << d.jambB.y
            << d.width << static_cast<int32_t>(d.roomA) << static_cast<int32_t>(d.roomB);
    }
    // Labels as runs (value, count) in row-major order: rooms are large, so this is small.
    std::vector<int32_t> runs;
    if (!map.labels.empty()) {
        int32_t current = map.labels.at<int>(0, 0), count = 0;
        for (int r = 0; r < map.labels.rows; ++r) {
            const int* row = map.labels.ptr<int>(r);
            for (int c = 0; c < map.labels.cols; ++c) {
                if (row[c] == current) {
                    ++count;
                } else {
                    runs.push_back(current);
                    runs.push_back(count);
                    current = row[c];
                    count = 1;
                }
            }
        }
        runs.push_back(current);
        runs.push_back(count);
    }
    out << runs;
}

void CTopologicalMap::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version) {
    switch (version) {
        case 0: {
            map = TopologicalMap{};
            GridImageFrame& f = map.frame;
            int32_t cols = 0, rows = 0;
            in >> f.resolution >> f.xMin >> f.yMin >> cols >> rows;
            f.cols = cols;
            f.rows = rows;
            uint32_t n = 0;
            in >> n;
            for (uint32_t i = 0; i < n; ++i) {
                Room r;
                int32_t id = 0;
                std::vector<double> outline;
                in >> id >> r.name >> r.area >> r.centroid.x >> r.centroid.y >> r.anchor.x >>
                    r.anchor.y >> outline;
                r.id = id;
                for (std::size_t k = 0; k + 1 < outline.size(); k += 2)
                    r.outline.push_back({outline[k], outline[k + 1]});
                map.rooms.push_back(std::move(r));
            }
            in >> n;
            for (uint32_t i = 0; i < n; ++i) {
                Door d;
                int32_t id = 0, a = 0, b = 0;
                in >> id >> d.jambA.x >> d.jambA.y >> d.jambB.x >> d.jambB.y >> d.width >> a >> b;
                d.id = id;
                d.roomA = a;
                d.roomB = b;
                map.doors.push_back(d);
            }
            std::vector<int32_t> runs;
            in >> runs;
            const long long cells = static_cast<long long>(rows) * cols;
            if (!runs.empty()) {
                map.labels = cv::Mat(rows, cols, CV_32S);
                long long at = 0;
                for (std::size_t k = 0; k + 1 < runs.size(); k += 2) {
                    if (runs[k + 1] < 0 || at + runs[k + 1] > cells) {
                        THROW_EXCEPTION("CTopologicalMap: corrupt label runs");
                    }
                    std::fill_n(map.labels.ptr<int>() + at, runs[k + 1], runs[k]);
                    at += runs[k + 1];
                }
                if (at != cells)
                    THROW_EXCEPTION("CTopologicalMap: label runs do not cover the grid");
            }
            break;
        }
        default:
            MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
    }
}

std::string CTopologicalMap::asString() const {
    std::ostringstream o;
    o << "toposlam::rooms::CTopologicalMap: " << map.rooms.size() << " rooms, " << map.doors.size()
      << " doors, grid " << map.frame.cols << " x " << map.frame.rows << " cells of "
      << map.frame.resolution << " m\n";
    for (const Room& r : map.rooms) {
        o << "  room " << r.id << (r.name.empty() ? "" : " '" + r.name + "'") << ": " << r.area
          << " m^2, centroid (" << r.centroid.x << ", " << r.centroid.y << ")\n";
    }
    for (const Door& d : map.doors) {
        o << "  door " << d.id << ": rooms " << d.roomA << " - " << d.roomB << ", " << d.width
          << " m wide at (" << d.middle().x << ", " << d.middle().y << ")\n";
    }
    return o.str();
}

}  // namespace toposlam::rooms
