#include <toposlam/io/AtomicFile.h>
#include <toposlam/planning/RoomPath.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <stdexcept>

namespace toposlam::planning {

double polylineLength(const std::vector<mrpt::math::TPoint2D>& points) {
    double length = 0;
    for (std::size_t i = 1; i < points.size(); ++i) {
        length += std::hypot(points[i].x - points[i - 1].x, points[i].y - points[i - 1].y);
    }
    return length;
}

void savePath(const RoomPath& path, const std::string& file) {
    if (!path.solved)
        throw std::invalid_argument("savePath: the path was not solved");
    io::writeFileAtomically(file, [&](const std::string& tmp) {
        std::ofstream out(tmp);
        out << "# TopoSLAM room-to-room path: x y (m, map frame), one point per line\n";
        out << "# rooms:";
        for (const int r : path.route.rooms)
            out << ' ' << r;
        out << "\n# doors:";
        for (const int d : path.route.doors)
            out << ' ' << d;
        out << "\n# length_m: " << std::setprecision(6) << path.length << "\n";
        out << std::setprecision(10);
        for (const auto& p : path.points)
            out << p.x << ' ' << p.y << '\n';
        if (!out)
            throw std::runtime_error(file + ": cannot write the path");
    });
}

}  // namespace toposlam::planning
