#include "DrawnMaps.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <random>

namespace toposlam::rooms::test {

namespace {

// Pixel rectangle of the world box [x0, x1] x [y0, y1] (m) in an image `rows` high.
cv::Rect box(const cv::Mat& img, double x0, double y0, double x1, double y1) {
    const int c0 = static_cast<int>(std::lround(x0 / kResolution));
    const int c1 = static_cast<int>(std::lround(x1 / kResolution));
    const int r0 = img.rows - static_cast<int>(std::lround(y1 / kResolution));
    const int r1 = img.rows - static_cast<int>(std::lround(y0 / kResolution));
    return {c0, r0, c1 - c0, r1 - r0};
}

void fill(cv::Mat& img, double x0, double y0, double x1, double y1, int value) {
    img(box(img, x0, y0, x1, y1)) = value;
}

cv::Point pixel(const cv::Mat& img, double x, double y) {
    return {static_cast<int>(std::lround(x / kResolution)),
            img.rows - static_cast<int>(std::lround(y / kResolution))};
}

}  // namespace

double labelIoU(const cv::Mat& a, int labelA, const cv::Mat& b, int labelB) {
    const cv::Mat inA = a == labelA, inB = b == labelB;
    const double both = cv::countNonZero(inA & inB), either = cv::countNonZero(inA | inB);
    return either > 0 ? both / either : 0;
}

double distanceToNearestDoor(const TopologicalMap& map, const mrpt::math::TPoint2D& p) {
    double best = 1e9;
    for (const auto& d : map.doors)
        best = std::min(best, std::hypot(d.middle().x - p.x, d.middle().y - p.y));
    return best;
}

GridImageFrame frameOf(const cv::Mat& image) {
    GridImageFrame f;
    f.resolution = kResolution;
    f.cols = image.cols;
    f.rows = image.rows;
    return f;
}

mrpt::maps::COccupancyGridMap2D gridOf(const cv::Mat& image) {
    mrpt::maps::COccupancyGridMap2D grid;
    grid.setSize(0, static_cast<float>(image.cols * kResolution), 0,
                 static_cast<float>(image.rows * kResolution), static_cast<float>(kResolution),
                 0.5f);
    for (int r = 0; r < image.rows; ++r) {
        for (int c = 0; c < image.cols; ++c) {
            const int v = image.at<std::uint8_t>(r, c);
            if (v == 255)
                grid.setCell(c, image.rows - 1 - r, 1.0f);
            if (v == 0)
                grid.setCell(c, image.rows - 1 - r, 0.0f);
        }
    }
    return grid;
}

DrawnMap office() {
    // 22 x 14 m image, the building from (1, 1) to (21, 13).
    DrawnMap m;
    m.image = cv::Mat(280, 440, CV_8U, cv::Scalar(128));
    cv::Mat& img = m.image;
    fill(img, 1, 1, 21, 13, 0);            // building block
    fill(img, 1.2, 1.2, 20.8, 12.8, 255);  // inside
    // Corridor walls at y = 6 and y = 8 (0.2 m thick): corridor y in [6.2, 7.8].
    fill(img, 1, 6, 21, 6.2, 0);
    fill(img, 1, 7.8, 21, 8, 0);
    // Upper rooms: x in [1.2, 7.8], [8, 14.4], [14.6, 20.8] (walls at x = 7.8 and 14.4).
    fill(img, 7.8, 8, 8, 13, 0);
    fill(img, 14.4, 8, 14.6, 13, 0);
    // Lower rooms: x in [1.2, 10.9], [11.1, 20.8].
    fill(img, 10.9, 1, 11.1, 6, 0);
    // Doors (clear openings cut into the walls).
    auto door = [&](double x0, double y0, double x1, double y1) {
        fill(img, x0, y0, x1, y1, 255);
        m.doors.push_back({{0.5 * (x0 + x1), 0.5 * (y0 + y1)}, std::max(x1 - x0, y1 - y0)});
    };
    door(3.0, 7.8, 3.9, 8.0);    // corridor - upper left
    door(10.5, 7.8, 11.4, 8.0);  // corridor - upper middle
    door(17.0, 7.8, 18.0, 8.0);  // corridor - upper right
    door(5.0, 6.0, 5.9, 6.2);    // corridor - lower left
    door(15.0, 6.0, 16.0, 6.2);  // corridor - lower right
    door(7.8, 11.0, 8.0, 11.9);  // upper left - upper middle
    m.rooms = {{10, 7}, {4, 10.5}, {11, 10.5}, {17.5, 10.5}, {5, 3.5}, {16, 3.5}};
    m.tour = {{2, 7},      {3.45, 7},  {3.45, 10}, {7, 11.45}, {9, 11.45},
              {10.95, 10}, {10.95, 7}, {17.5, 7},  {17.5, 10}, {17.5, 7},
              {15.5, 7},   {15.5, 3},  {15.5, 7},  {5.45, 7},  {5.45, 3}};
    return m;
}

DrawnMap furnishedOffice() {
    DrawnMap m = office();
    cv::Mat& img = m.image;
    auto chair = [&](double x, double y) {
        cv::circle(img, pixel(img, x, y), 4, cv::Scalar(0), cv::FILLED);
    };
    auto table = [&](double x0, double y0, double x1, double y1) { fill(img, x0, y0, x1, y1, 0); };
    // Upper left room: a meeting table with chairs around it, a cabinet against the wall.
    table(3, 9.8, 6, 11.2);
    for (double x = 3.3; x < 6; x += 0.9) {
        chair(x, 9.4);
        chair(x, 11.6);
    }
    table(1.2, 12.2, 3.2, 12.8);  // cabinet in the corner
    // Upper middle: two desks, 1 m from the back wall and from each other.
    table(9, 11.0, 10.6, 11.8);
    table(11.6, 11.0, 13.2, 11.8);
    chair(9.8, 10.6);
    chair(12.4, 10.6);
    // Upper right: a bin 1 m from a wall, a plant, a sofa along the wall.
    cv::circle(img, pixel(img, 20.0, 9.0), 5, cv::Scalar(0), cv::FILLED);
    cv::circle(img, pixel(img, 15.6, 12.0), 6, cv::Scalar(0), cv::FILLED);
    table(16.5, 12.2, 19.5, 12.8);
    // Lower left: a row of desks with a 1 m aisle to the wall.
    for (double x = 2; x < 10; x += 2.2)
        table(x, 2.2, x + 1.6, 3.0);
    for (double x = 2.8; x < 10; x += 2.2)
        chair(x, 3.4);
    // Lower right: a big table in the middle, shelves along the bottom wall.
    table(13, 2.5, 18, 4.0);
    table(11.5, 1.2, 20.5, 1.6);
    // Room points clear of the furniture.
    m.rooms = {{10, 7}, {2, 9}, {11, 9.5}, {17.5, 10.5}, {5, 4.5}, {16, 5}};
    return m;
}

DrawnMap noisyOffice(unsigned seed) {
    DrawnMap m = office();
    cv::Mat& img = m.image;
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> col(0, img.cols - 1), row(0, img.rows - 1);
    std::uniform_real_distribution<double> u(0, 1);
    const cv::Mat clean = img.clone();
    for (int k = 0; k < 1500; ++k) {  // specks: occupied in free space, free in the unknown
        const int c = col(rng), r = row(rng);
        if (clean.at<std::uint8_t>(r, c) == 255)
            img.at<std::uint8_t>(r, c) = 0;
        if (clean.at<std::uint8_t>(r, c) == 128)
            img.at<std::uint8_t>(r, c) = 255;
    }
    for (int r = 1; r + 1 < img.rows;
         ++r) {  // ragged walls: free cells next to walls turn occupied
        for (int c = 1; c + 1 < img.cols; ++c) {
            if (clean.at<std::uint8_t>(r, c) != 255)
                continue;
            const bool byWall =
                clean.at<std::uint8_t>(r - 1, c) == 0 || clean.at<std::uint8_t>(r + 1, c) == 0 ||
                clean.at<std::uint8_t>(r, c - 1) == 0 || clean.at<std::uint8_t>(r, c + 1) == 0;
            if (byWall && u(rng) < 0.3)
                img.at<std::uint8_t>(r, c) = 0;
        }
    }
    return m;
}

DrawnMap rotated(const DrawnMap& map, double degrees) {
    DrawnMap m = map;
    const cv::Point2f centre(0.5f * (map.image.cols - 1), 0.5f * (map.image.rows - 1));
    cv::Mat rot = cv::getRotationMatrix2D(centre, degrees, 1.0);
    const cv::Rect2f bounds =
        cv::RotatedRect(centre, map.image.size(), static_cast<float>(degrees)).boundingRect2f();
    rot.at<double>(0, 2) += 0.5 * bounds.width - centre.x;
    rot.at<double>(1, 2) += 0.5 * bounds.height - centre.y;
    cv::warpAffine(map.image, m.image, rot, bounds.size(), cv::INTER_NEAREST, cv::BORDER_CONSTANT,
                   cv::Scalar(128));
    auto move = [&](const mrpt::math::TPoint2D& p) {
        const double c = p.x / kResolution, r = map.image.rows - p.y / kResolution;
        const double c2 =
            rot.at<double>(0, 0) * c + rot.at<double>(0, 1) * r + rot.at<double>(0, 2);
        const double r2 =
            rot.at<double>(1, 0) * c + rot.at<double>(1, 1) * r + rot.at<double>(1, 2);
        return mrpt::math::TPoint2D(c2 * kResolution, (m.image.rows - r2) * kResolution);
    };
    for (auto& p : m.rooms)
        p = move(p);
    for (auto& d : m.doors)
        d.middle = move(d.middle);
    for (auto& p : m.tour)
        p = move(p);
    return m;
}

DrawnMap singleRoom() {
    DrawnMap m;
    m.image = cv::Mat(120, 160, CV_8U, cv::Scalar(128));
    fill(m.image, 1, 1, 7.2, 5.2, 0);
    fill(m.image, 1.2, 1.2, 7, 5, 255);
    m.rooms = {{4, 3}};
    return m;
}

DrawnMap doorAtAWallsEndBesideAnOuterWall() {
    DrawnMap m;
    m.image = cv::Mat(140, 160, CV_8U, cv::Scalar(128));
    cv::Mat& img = m.image;
    fill(img, 1, 1, 7.4, 6, 0);
    fill(img, 1.15, 1.15, 7.25, 5.85, 255);
    fill(img, 1, 3.4, 6.35, 3.55, 0);     // the wall, from the left outer wall
    fill(img, 7.05, 3.4, 7.25, 3.55, 0);  // the stub on the right outer wall
    m.rooms = {{3.5, 2.2}, {3.5, 4.7}};
    m.doors = {{{6.7, 3.475}, 0.7}};
    m.tour = {{3.5, 2.2}, {6.7, 2.2}, {6.7, 4.7}, {3.5, 4.7}};
    return m;
}

DrawnMap thickWall() {
    DrawnMap m;
    m.image = cv::Mat(140, 240, CV_8U, cv::Scalar(128));
    cv::Mat& img = m.image;
    fill(img, 1, 1, 10.8, 5.4, 0);
    fill(img, 1.2, 1.2, 5.6, 5.2, 255);
    fill(img, 6.15, 1.2, 10.6, 5.2, 255);
    fill(img, 5.6, 2.7, 6.15, 3.7, 255);  // the door through the 0.55 m wall
    m.rooms = {{3.4, 3.2}, {8.4, 3.2}};
    m.doors = {{{5.875, 3.2}, 1.0}};
    m.tour = {{3.4, 3.2}, {8.4, 3.2}};
    return m;
}

DrawnMap hollowWall(double length) {
    DrawnMap m;
    const double right = 1.2 + length;
    m.image = cv::Mat(168, static_cast<int>(std::lround((right + 1.2) / kResolution)), CV_8U,
                      cv::Scalar(128));
    cv::Mat& img = m.image;
    fill(img, 1, 1, right + 0.2, 7.6, 0);
    fill(img, 1.2, 5.6, right, 7.4, 255);  // the corridor
    fill(img, 1.2, 1.2, right, 4.6, 255);  // the office
    fill(img, 1.2, 4.7, right, 5.5, 128);  // the wall's unseen inside, between its faces
    fill(img, 1.9, 4.6, 3.1, 5.6, 0);      // the doorway's sides ...
    fill(img, 2.0, 4.6, 3.0, 5.6, 255);    // ... and the doorway
    const double middle = 0.5 * (1.2 + right);
    m.rooms = {{middle, 6.5}, {middle, 3}};
    m.doors = {{{2.5, 5.1}, 1.0}};
    m.tour = {{middle, 6.5}, {2.5, 6.5}, {2.5, 3}, {middle, 3}};
    return m;
}

DrawnMap thinWalls() {
    DrawnMap m;
    m.image = cv::Mat(160, 360, CV_8U, cv::Scalar(128));
    cv::Mat& img = m.image;
    fill(img, 1, 1, 17.4, 7.4, 0);
    fill(img, 1.2, 1.2, 17.2, 7.2, 255);
    const double doorBottom[] = {3.7, 5.7, 1.7};  // m: middle, near the top, near the bottom
    for (int i = 0; i < 3; ++i) {
        const double x = 5.1 + 4.0 * i;
        fill(img, x, 1.2, x + 0.1, doorBottom[i], 0);
        fill(img, x, doorBottom[i] + 1.0, x + 0.1, 7.2, 0);
        m.doors.push_back({{x + 0.05, doorBottom[i] + 0.5}, 1.0});
    }
    m.rooms = {{3.1, 4.2}, {7.1, 4.2}, {11.1, 4.2}, {15.1, 4.2}};
    m.tour = {{3.1, 4.2},  {5.15, 4.2}, {7.1, 4.2},   {7.1, 6.2}, {9.15, 6.2},
              {11.1, 6.2}, {11.1, 2.2}, {13.15, 2.2}, {15.1, 2.2}};
    return m;
}

DrawnMap wallAtAnAngle() {
    DrawnMap m;
    m.image = cv::Mat(200, 360, CV_8U, cv::Scalar(128));
    cv::Mat& img = m.image;
    fill(img, 1, 1, 17.4, 9.4, 0);
    fill(img, 1.2, 1.2, 17.2, 9.2, 255);
    // From (6.5, 1.2) to (11.5, 9.2): direction (5, 8) / 9.43; the door's middle at 4.2 m along.
    const mrpt::math::TPoint2D from{6.5, 1.2}, to{11.5, 9.2};
    const double length = std::hypot(to.x - from.x, to.y - from.y);
    auto at = [&](double s) {
        return mrpt::math::TPoint2D{from.x + (to.x - from.x) * s / length,
                                    from.y + (to.y - from.y) * s / length};
    };
    const auto gapStart = at(3.7), gapEnd = at(4.7);
    cv::line(img, pixel(img, from.x, from.y), pixel(img, gapStart.x, gapStart.y), 0, 3);
    cv::line(img, pixel(img, gapEnd.x, gapEnd.y), pixel(img, to.x, to.y), 0, 3);
    m.doors.push_back({at(4.2), 0.85});  // the line's round caps (0.075 m) narrow the gap
    m.rooms = {{4, 5}, {14, 5}};
    m.tour = {{4, 5}, at(4.2), {14, 5}};
    return m;
}

DrawnMap deskRow() {
    DrawnMap m;
    m.image = cv::Mat(200, 320, CV_8U, cv::Scalar(128));
    cv::Mat& img = m.image;
    fill(img, 1, 1, 15.2, 9.2, 0);
    fill(img, 1.2, 1.2, 15, 9, 255);
    for (double x = 2.2; x < 14; x += 2.6)
        fill(img, x, 4.75, x + 1.6, 5.45, 0);  // desks 1.6 x 0.7 m, 1 m apart
    m.rooms = {{8, 2.5}};
    return m;
}

DrawnMap openPlan() {
    DrawnMap m;
    m.image = cv::Mat(240, 360, CV_8U, cv::Scalar(128));
    cv::Mat& img = m.image;
    fill(img, 1, 1, 17.2, 11.2, 0);
    fill(img, 1.2, 1.2, 17, 11, 255);
    for (double x : {6.0, 12.0}) {  // pillars 0.4 m, 1 m apart from desks
        for (double y : {4.0, 8.0})
            fill(img, x - 0.2, y - 0.2, x + 0.2, y + 0.2, 0);
    }
    for (double x = 2.0; x < 16; x += 3.0)
        fill(img, x, 5.6, x + 1.6, 6.4, 0);  // desks, 1.4 m apart
    m.rooms = {{9, 2}};
    return m;
}

DrawnMap tableShadow() {
    DrawnMap m;
    m.image = cv::Mat(168, 208, CV_8U, cv::Scalar(128));
    cv::Mat& img = m.image;
    fill(img, 1, 1, 9.4, 7.4, 0);
    fill(img, 1.2, 1.2, 9.2, 7.2, 255);
    fill(img, 1.2, 2.8, 2.0, 3.0, 0);    // wall stub, ending at x = 2
    fill(img, 3.0, 4.6, 4.2, 5.0, 0);    // the table's face, seen by the laser
    fill(img, 3.0, 1.2, 4.2, 4.6, 128);  // its shadow, down to the bottom wall
    m.rooms = {{6, 5}};
    m.tour = {{6, 5}, {2.5, 3.9}, {2.2, 2.0}, {2.5, 3.9}, {6, 5}};
    return m;
}

DrawnMap cabinetPocket() {
    DrawnMap m;
    m.image = cv::Mat(168, 208, CV_8U, cv::Scalar(128));
    cv::Mat& img = m.image;
    fill(img, 1, 1, 9.4, 7.4, 0);
    fill(img, 1.2, 1.2, 9.2, 7.2, 255);
    // The closet, bottom right: walls 0.1 m, door y in [1.8, 2.7]; the unseen shadow of a
    // table fills its lower-right corner, enclosed by the walls the laser saw.
    fill(img, 6.6, 1.2, 6.7, 3.7, 0);
    fill(img, 6.6, 3.6, 9.2, 3.7, 0);
    fill(img, 6.6, 1.8, 6.7, 2.7, 255);
    m.doors.push_back({{6.65, 2.25}, 0.9});
    fill(img, 7.6, 1.2, 9.2, 2.8, 128);
    // The two cabinets along the top wall, x in [1.2, 4.2] and [5.4, 9.2], y in [5.0, 7.2]:
    // fronts seen, bodies and the wall behind them unknown.
    fill(img, 1.0, 5.0, 4.2, 7.4, 128);
    fill(img, 5.4, 5.0, 9.4, 7.4, 128);
    fill(img, 1.0, 5.0, 4.2, 5.1, 0);
    fill(img, 5.4, 5.0, 9.4, 5.1, 0);
    fill(img, 5.4, 5.1, 5.5, 5.4, 0);  // the right cabinet's flank, seen near its front
    // The pocket behind the mouth: the right flank's diagonal shadow, the back wall seen.
    const std::vector<cv::Point> seen = {pixel(img, 5.4, 5.4), pixel(img, 6.6, 7.2),
                                         pixel(img, 5.4, 7.2)};
    cv::fillConvexPoly(img, seen, cv::Scalar(255));
    fill(img, 4.2, 7.2, 6.6, 7.4, 0);
    m.rooms = {{3, 3}, {7.9, 3.0}};
    m.tour = {{3, 3}, {4.8, 4.5}, {4.8, 6.0}, {4.8, 4.5}, {5.5, 2.25}, {7.9, 3.0}};
    return m;
}

// A 13.2 x 8 m hall with three 3.2 x 2.4 m cubicles along its top wall (x in [1.2, 4.4],
// [4.5, 7.7], [7.8, 11.0], y in [6.6, 9]; partitions 0.1 m), each cubicle's front a stub of
// `stub` m on both sides of its opening (y in [6.5, 6.6]). `post(x0, x1, front)` may add
// obstacles around each front.
template <typename Post>
DrawnMap cubicleRow(double stub, Post post) {
    DrawnMap m;
    m.image = cv::Mat(200, 300, CV_8U, cv::Scalar(128));
    cv::Mat& img = m.image;
    fill(img, 1, 1, 14.4, 9.2, 0);
    fill(img, 1.2, 1.2, 14.2, 9, 255);
    const double front = 6.5;
    for (double x : {4.4, 7.7, 11.0})
        fill(img, x, front, x + 0.1, 9, 0);
    for (double x0 : {1.2, 4.5, 7.8}) {
        const double x1 = x0 + 3.2;
        fill(img, x0, front, x0 + stub, front + 0.1, 0);
        fill(img, x1 - stub, front, x1, front + 0.1, 0);
        post(img, x0 + stub, x1 - stub, front);
        m.doors.push_back({{0.5 * (x0 + x1), front + 0.05}, 3.2 - 2 * stub});
        m.rooms.push_back({0.5 * (x0 + x1), 8});
    }
    m.rooms.push_back({7, 3});
    return m;
}

DrawnMap cubicles() {
    return cubicleRow(0.6, [](cv::Mat&, double, double, double) {});
}

DrawnMap raggedCubicles() {
    // Two posts 0.2 m back from the stubs' ends (a, b), on either side of the front: the
    // nearest obstacles to the opening's middle, off every straight cut through the opening.
    return cubicleRow(0.75, [](cv::Mat& img, double a, double b, double front) {
        fill(img, a + 0.1, front + 0.3, a + 0.25, front + 0.45, 0);
        fill(img, b - 0.25, front - 0.35, b - 0.1, front - 0.2, 0);
    });
}

namespace {

// A 14 x 6 m building: a 2 m corridor along the bottom (y in [1.2, 3.2]) below the rooms, its
// upper wall 0.1 m; no room, door or partition drawn yet.
DrawnMap corridorBelowRooms() {
    DrawnMap m;
    m.image = cv::Mat(170, 330, CV_8U, cv::Scalar(128));
    fill(m.image, 1, 1, 15.4, 7.4, 0);
    fill(m.image, 1.2, 1.2, 15.2, 7.2, 255);
    fill(m.image, 1.2, 3.2, 15.2, 3.3, 0);  // the corridor's upper wall, 0.1 m
    return m;
}

}  // namespace

DrawnMap doubleDoors() {
    DrawnMap m = corridorBelowRooms();
    cv::Mat& img = m.image;
    const double roomX0[] = {1.2, 4.8, 8.3, 11.8}, clear[] = {1.45, 1.5, 1.55, 1.6};
    for (int i = 0; i < 4; ++i) {
        if (i > 0)
            fill(img, roomX0[i] - 0.1, 3.3, roomX0[i], 7.2, 0);  // partitions, 0.1 m
        const double x0 = roomX0[i] + 1.0, x1 = x0 + clear[i];
        fill(img, x0, 3.2, x1, 3.3, 255);
        const double middle = 0.5 * (x0 + x1);
        m.doors.push_back({{middle, 3.25}, clear[i]});
        m.rooms.push_back({middle, 5.2});
        m.tour.insert(m.tour.end(), {{middle, 2.2}, {middle, 5.2}, {middle, 2.2}});
    }
    m.rooms.push_back({8.2, 2.2});
    return m;
}

DrawnMap pierBetweenDoorways() {
    DrawnMap m = corridorBelowRooms();
    cv::Mat& img = m.image;
    fill(img, 8.2, 3.3, 8.3, 7.2, 0);  // the partition between the two rooms
    // The left room: a 1.8 m opening and a 1.1 m door, the 0.45 m pier between them.
    auto opening = [&](double x0, double x1) {
        fill(img, x0, 3.2, x1, 3.3, 255);
        m.doors.push_back({{0.5 * (x0 + x1), 3.25}, x1 - x0});
        m.tour.insert(m.tour.end(), {{0.5 * (x0 + x1), 2.2}, {0.5 * (x0 + x1), 5.2}});
    };
    opening(2.5, 4.3);
    opening(4.75, 5.85);
    opening(10.0, 11.0);  // the right room's door
    m.rooms = {{4.5, 5.2}, {11.7, 5.2}, {8.2, 2.2}};
    return m;
}

DrawnMap corridorWithOppositeDoors() {
    DrawnMap m;
    m.image = cv::Mat(220, 380, CV_8U, cv::Scalar(128));
    cv::Mat& img = m.image;
    fill(img, 1, 1, 17.8, 10, 0);
    fill(img, 1.2, 1.2, 17.6, 9.8, 255);
    // Corridor y in [4.4, 6.6], walls 0.2 m; partitions x in [6.6, 6.8] and [12.0, 12.2].
    fill(img, 1, 4.2, 17.8, 4.4, 0);
    fill(img, 1, 6.6, 17.8, 6.8, 0);
    for (double x : {6.6, 12.0}) {
        fill(img, x, 1, x + 0.2, 4.4, 0);
        fill(img, x, 6.6, x + 0.2, 10, 0);
    }
    auto door = [&](double x0, double y0) {
        fill(img, x0, y0, x0 + 1.0, y0 + 0.2, 255);
        m.doors.push_back({{x0 + 0.5, y0 + 0.1}, 1.0});
    };
    for (double x : {6.8, 12.2}) {  // beside the partitions, above and below the corridor
        door(x, 6.6);
        door(x, 4.2);
    }
    door(3.0, 6.6);
    door(3.0, 4.2);
    m.rooms = {{9, 5.5}, {4, 8}, {9.4, 8}, {15, 8}, {4, 2.5}, {9.4, 2.5}, {15, 2.5}};
    return m;
}

DrawnMap corridorBend() {
    DrawnMap m;
    m.image = cv::Mat(280, 320, CV_8U, cv::Scalar(128));
    cv::Mat& img = m.image;
    fill(img, 1, 1, 15, 13, 0);
    fill(img, 1.2, 10.6, 14.8, 12.8, 255);  // the top arm
    fill(img, 1.2, 1.2, 3.0, 10.6, 255);    // the left arm
    fill(img, 3.2, 1.2, 8.9, 10.4, 255);    // room A
    fill(img, 9.1, 1.2, 14.8, 10.4, 255);   // room B
    for (const double x : {5.0, 11.0}) {
        fill(img, x, 10.4, x + 1.0, 10.6, 255);
        m.doors.push_back({{x + 0.5, 10.5}, 1.0});
    }
    m.rooms = {{2.1, 11.5}, {6, 6}, {12, 6}};
    m.tour = {{2.1, 5}, {2.1, 11.5}, {5.5, 11.5}, {5.5, 8}, {5.5, 11.5}, {11.5, 11.5}, {11.5, 8}};
    return m;
}

DrawnMap corridorOffAHall() {
    DrawnMap m;
    m.image = cv::Mat(210, 340, CV_8U, cv::Scalar(128));
    cv::Mat& img = m.image;
    fill(img, 1, 1, 16.2, 10.2, 0);
    fill(img, 1.2, 1.2, 16, 10, 255);
    fill(img, 6.0, 2.6, 6.2, 10, 0);     // the hall's wall, from the corridor up
    fill(img, 6.0, 2.6, 16, 2.8, 0);     // the corridor's upper wall...
    fill(img, 7.0, 2.6, 8.0, 2.8, 255);  // ... with the door 1 m from the hall's wall
    m.doors.push_back({{7.5, 2.7}, 1.0});
    m.rooms = {{3.5, 5}, {11, 6}};
    m.tour = {{3.5, 5}, {7.5, 1.9}, {7.5, 4}, {11, 6}};
    return m;
}

DrawnMap cabinetAcrossFromAColumnEnd() {
    DrawnMap m;
    m.image = cv::Mat(200, 180, CV_8U, cv::Scalar(128));
    cv::Mat& img = m.image;
    fill(img, 1, 1, 7.8, 9, 0);
    fill(img, 1.2, 1.2, 7.6, 8.8, 255);
    fill(img, 5.0, 1.2, 5.1, 8.8, 0);    // the partition...
    fill(img, 5.0, 1.8, 5.1, 2.8, 255);  // ... with its door
    fill(img, 4.5, 5.0, 5.1, 8.8, 0);    // the column against its upper half
    fill(img, 6.4, 4.6, 7.6, 5.4, 0);    // a cabinet against the right room's far wall
    m.doors.push_back({{5.05, 2.3}, 1.0});
    m.rooms = {{3, 3}, {6.3, 7}};
    return m;
}

DrawnMap officesSeenThroughTheirDoors() {
    DrawnMap m;
    m.image = cv::Mat(160, 320, CV_8U, cv::Scalar(128));
    cv::Mat& img = m.image;
    fill(img, 1.0, 1.0, 14.6, 7.8, 0);
    fill(img, 1.2, 1.2, 14.4, 3.4, 255);  // the corridor
    m.rooms.push_back({7.8, 2.3});
    for (int k = 0; k < 3; ++k) {
        const double x0 = 1.2 + 4.4 * k, x1 = x0 + 4.2;  // the office, above the wall y 3.4-3.6
        const double door = 0.5 * (x0 + x1);
        fill(img, x0, 3.6, x1, 7.6, 255);
        fill(img, door - 0.5, 3.4, door + 0.5, 3.6, 255);
        m.doors.push_back({{door, 3.5}, 1.0});
        m.rooms.push_back({door, 6.0});
        // The shadows beside the door: from each jamb's inner corner up to the side wall
        // (slope 0.5), the wall's inner face below them included.
        for (const double side : {-1.0, 1.0}) {
            // The wall cell beside the opening (the opening's cells stay free).
            const double jamb = side < 0 ? door - 0.5 - kResolution : door + 0.5;
            const double wall = side < 0 ? x0 : x1;
            const cv::Point wedge[3] = {pixel(img, jamb, 3.5), pixel(img, wall, 3.5),
                                        pixel(img, wall, 3.6 + 0.5 * std::abs(jamb - wall))};
            cv::fillConvexPoly(img, wedge, 3, cv::Scalar(128));
        }
        // Seen through the door by few beams each, the cells between two beams stayed unknown:
        // broken one-cell streaks fanning out from the door.
        for (double x = x0 + 0.1; x < x1; x += 0.2) {
            const double length = std::hypot(x - door, 4.0);
            for (double t = 0.1; t + 0.4 < 1.0; t += 0.5 / length) {
                const double t1 = t + 0.4 / length;
                cv::line(img, pixel(img, door + t * (x - door), 3.6 + t * 4.0),
                         pixel(img, door + t1 * (x - door), 3.6 + t1 * 4.0), cv::Scalar(128));
            }
        }
    }
    m.tour = {{1.8, 2.3}, {13.8, 2.3}};
    return m;
}

DrawnMap corridorRing() {
    DrawnMap m;
    m.image = cv::Mat(480, 880, CV_8U, cv::Scalar(0));
    cv::Mat& img = m.image;
    const double x0 = 2, y0 = 2, x1 = 42, y1 = 22, width = 2.2;
    fill(img, x0, y0, x1, y0 + width, 255);
    fill(img, x0, y1 - width, x1, y1, 255);
    fill(img, x0, y0, x0 + width, y1, 255);
    fill(img, x1 - width, y0, x1, y1, 255);
    m.rooms.push_back({x0 + width / 2, 12});
    for (double x = x0 + width + 3; x + 4 < x1 - width - 2; x += 8) {
        for (const bool top : {false, true}) {
            // 0.2 m wall between the corridor and the office, door in its middle.
            const double wall = top ? y1 - width - 0.2 : y0 + width;
            const double office0 = top ? wall - 5 : wall + 0.2;
            fill(img, x, office0, x + 4, office0 + 5, 255);
            fill(img, x + 1.5, wall, x + 2.5, wall + 0.2, 255);
            m.rooms.push_back({x + 2, office0 + 2.5});
            m.doors.push_back({{x + 2, wall + 0.1}, 1.0});
        }
    }
    const double cx0 = x0 + width / 2, cy0 = y0 + width / 2;
    const double cx1 = x1 - width / 2, cy1 = y1 - width / 2;
    m.tour = {{9, cy0}, {cx1, cy0}, {cx1, cy1}, {cx0, cy1}, {cx0, cy0}, {9, cy0}};
    return m;
}

}  // namespace toposlam::rooms::test
