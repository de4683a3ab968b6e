#include "MrptObjectCheck.h"

#include <mrpt/maps/OccupancyGridCellType.h>
#include <mrpt/rtti/CObject.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <vector>

namespace toposlam::io {

namespace {

constexpr unsigned char kEndFlag = 0x88;    // MRPT's SERIALIZATION_END_FLAG after every object
constexpr std::size_t kMaxClassName = 120;  // MRPT refuses longer names too
constexpr std::size_t kMinObjectBytes = 4;  // length byte, 1-character name, version, end flag
// CActionRobotMovement2D with Thrun's motion model draws this many particles on reading
// (MRPT's default is 300).
constexpr int32_t kMaxThrunParticles = 100000;

// Thrown where the layout is not known (another class): the rest of the top-level object is
// left to MRPT.
struct StopChecking {};

class Checker {
  public:
    explicit Checker(LookaheadStream& in) : in_(in) {}

    std::size_t position() const { return pos_; }
    const std::string& topClass() const { return topClass_; }
    /// A polymorphic object: any class derived from `base` ("" = any class, or null).
    void object(const char* base);

  private:
    using Body = void (Checker::*)(int version);
    struct Header {
        std::string name;
        int version = -1;
        bool oldFormat = false;  // pre-2007: no end flag
    };

    [[noreturn]] void fail(const std::string& problem) const;
    const unsigned char* take(std::size_t n, const char* what);
    template <typename T>
    T read(const char* what) {
        T v;
        std::memcpy(&v, take(sizeof v, what), sizeof v);  // MRPT files are little-endian
        return v;
    }
    void skip(std::size_t n, const char* what) { take(n, what); }
    /// Checks that `count` elements of at least `minBytes` each fit in the rest of the file,
    /// without consuming them: MRPT allocates the elements before reading them.
    void expectElements(uint64_t count, std::size_t minBytes, const char* what);
    bool boolean(const char* what) { return read<uint8_t>(what) != 0; }
    void string(const char* what) { skip(read<uint32_t>(what), what); }
    void array(uint64_t count, std::size_t elementSize, const char* what);
    Header header();
    void endFlag(const Header& h);
    void body(const Header& h, const std::string& name);
    /// A member object of exactly class `name` (MRPT's ReadObject(existing)).
    void member(const std::string& name);
    /// A CMatrixF / CMatrixD member; rows = 0: any shape.
    void matrix(const std::string& name, std::size_t elementSize, uint32_t rows, uint32_t cols);
    [[noreturn]] void badVersion(int version) const;

    void pose2D(int version);
    void pose3D(int version);
    void posePdfGaussian(int version);
    void odometryModel(int version);
    void actionRobotMovement2D(int version);
    void actionCollection(int version);
    void sensoryFrame(int version);
    void rangeScan(int version);
    void odometry(int version);
    void bearingRange(int version);
    void gridMap(int version);
    void gridMapOptions(int version);
    void mapGenericParams(int version);
    void laserFeatures(int version);

    static const std::map<std::string, Body>& bodies();

    LookaheadStream& in_;
    std::size_t pos_ = 0;
    std::string topClass_;
    std::vector<std::string> nesting_;  // classes being checked, outermost first
};

void Checker::fail(const std::string& problem) const {
    std::string where;
    for (auto it = nesting_.rbegin(); it != nesting_.rend(); ++it)
        where += (where.empty() ? "a " : " in a ") + *it;
    throw MalformedObject(topClass_, (where.empty() ? std::string() : where + ": ") + problem);
}

void Checker::badVersion(int version) const {
    fail("unsupported serialization version " + std::to_string(version));
}

const unsigned char* Checker::take(std::size_t n, const char* what) {
    if (n > std::numeric_limits<std::size_t>::max() - pos_ || !in_.ensure(pos_ + n)) {
        const std::size_t left = in_.buffered() - pos_;
        fail(std::string(what) + " needs " + std::to_string(n) + " bytes, the file has only " +
             std::to_string(left) + " left");
    }
    const unsigned char* p = in_.ahead() + pos_;
    pos_ += n;
    return p;
}

void Checker::array(uint64_t count, std::size_t elementSize, const char* what) {
    if (count > std::numeric_limits<std::size_t>::max() / elementSize) {
        fail(std::string(what) + ": " + std::to_string(count) + " elements cannot fit in memory");
    }
    skip(static_cast<std::size_t>(count) * elementSize, what);
}

Checker::Header Checker::header() {
    // MRPT's CArchive::internal_ReadObjectHeader(): 0x80 | name length, name, version; or, in
    // the pre-2007 format, name length, 3 zero bytes, name, int32 version (no end flag).
    const auto length = read<uint8_t>("an object header");
    Header h;
    h.oldFormat = !(length & 0x80);
    if (h.oldFormat) {
        const unsigned char* zeros = take(3, "an object header");
        if (zeros[0] || zeros[1] || zeros[2])
            fail("an object header that is neither MRPT's current nor its old format");
    }
    const std::size_t n = length & 0x7f;
    if (n > kMaxClassName)
        fail("a class name of " + std::to_string(n) + " characters");
    h.name.assign(reinterpret_cast<const char*>(take(n, "a class name")), n);
    if (h.oldFormat) {
        const auto version = read<int32_t>("an object version");
        if (version < 0 || version >= 255)
            fail("object version " + std::to_string(version));
        h.version = version;
    } else if (h.name != "nullptr") {
        h.version = read<uint8_t>("an object version");
    }
    return h;
}

void Checker::expectElements(uint64_t count, std::size_t minBytes, const char* what) {
    const uint64_t bytes = count * minBytes;  // count < 2^32, minBytes small
    if (bytes > std::numeric_limits<std::size_t>::max() - pos_ || !in_.ensure(pos_ + bytes)) {
        fail(std::string(what) + ": " + std::to_string(count) + " of them need at least " +
             std::to_string(bytes) + " bytes, only " + std::to_string(in_.buffered() - pos_) +
             " left in the file");
    }
}

void Checker::endFlag(const Header& h) {
    if (h.oldFormat)
        return;
    if (read<uint8_t>("the end of the object") != kEndFlag)
        fail("the " + h.name + " does not end where its content ends (corrupt data)");
}

void Checker::body(const Header& h, const std::string& name) {
    const auto it = bodies().find(name);
    if (it == bodies().end())
        throw StopChecking{};
    nesting_.push_back(name);
    (this->*(it->second))(h.version);
    endFlag(h);
    nesting_.pop_back();
}

void Checker::object(const char* base) {
    const Header h = header();
    const bool topLevel = topClass_.empty();
    if (topLevel)
        topClass_ = h.name;
    if (h.name == "nullptr") {
        if (*base)
            fail(std::string("a null object where a ") + base + " is needed");
        return;
    }
    const mrpt::rtti::TRuntimeClassId* cls = mrpt::rtti::findRegisteredClass(h.name);
    if (!cls)
        throw StopChecking{};  // MRPT reports the unregistered class
    if (*base && !cls->derivedFrom(base))
        fail(std::string("a ") + cls->className + " where a " + base + " is needed");
    if (topLevel)
        topClass_ = cls->className;
    body(h, cls->className);
}

void Checker::member(const std::string& name) {
    const Header h = header();
    const mrpt::rtti::TRuntimeClassId* cls =
        h.name == "nullptr" ? nullptr : mrpt::rtti::findRegisteredClass(h.name);
    if (!cls || name != cls->className)
        fail("a " + h.name + " where a " + name + " is needed");
    body(h, name);
}

void Checker::matrix(const std::string& name, std::size_t elementSize, uint32_t rows,
                     uint32_t cols) {
    const Header h = header();
    const mrpt::rtti::TRuntimeClassId* cls =
        h.name == "nullptr" ? nullptr : mrpt::rtti::findRegisteredClass(h.name);
    if (!cls || name != cls->className)
        fail("a " + h.name + " where a " + name + " is needed");
    nesting_.push_back(name);
    if (h.version != 0)
        badVersion(h.version);
    const auto r = read<uint32_t>("the number of rows");
    const auto c = read<uint32_t>("the number of columns");
    if (rows != 0 && (r != rows || c != cols)) {
        fail("a " + std::to_string(r) + " x " + std::to_string(c) + " matrix where a " +
             std::to_string(rows) + " x " + std::to_string(cols) + " one is needed");
    }
    array(uint64_t{r} * c, elementSize, "the matrix elements");
    endFlag(h);
    nesting_.pop_back();
}

void Checker::pose2D(int version) {
    if (version > 1)
        badVersion(version);
    skip(version == 0 ? 3 * 4 : 3 * 8, "the pose");
}

void Checker::pose3D(int version) {
    switch (version) {
        case 0:
            return matrix("mrpt::math::CMatrixF", 4, 4, 4);
        case 1:
            return matrix("mrpt::math::CMatrixD", 8, 4, 4);
        case 2:
            return skip(7 * 8, "the pose");
        case 3:
            return skip(12 * 8, "the pose");
        default:
            badVersion(version);
    }
}

void Checker::posePdfGaussian(int version) {
    if (version > 2)
        badVersion(version);
    member("mrpt::poses::CPose2D");
    if (version == 0) {
        matrix("mrpt::math::CMatrixF", 4, 3, 3);
    } else {
        skip(version == 1 ? 6 * 4 : 6 * 8, "the covariance");
    }
}

// Versions 3-7 of CActionRobotMovement2D with estimationMethod emOdometry: the odometry
// increment and the motion model, from which MRPT rebuilds the pose PDF (Thrun's model by
// drawing particles).
void Checker::odometryModel(int version) {
    member("mrpt::poses::CPose2D");
    const auto model = read<int32_t>("the motion model");
    if (model != 0 && model != 1)
        fail("unknown motion model " + std::to_string(model));
    // Version 3: 3 unused floats, then minStdXY and minStdPHI as doubles; later: 6 floats.
    skip(version == 3 ? 3 * 4 + 2 * 8 : 6 * 4, "the Gaussian motion model");
    const auto particles = read<int32_t>("the particle count");
    if (model == 1 && (particles < 1 || particles > kMaxThrunParticles)) {
        fail("Thrun's motion model with " + std::to_string(particles) + " particles (at most " +
             std::to_string(kMaxThrunParticles) + ")");
    }
    skip(4 * 4, "Thrun's motion model");
    if (version >= 5)
        skip(2 * 4, "Thrun's motion model");
}

void Checker::actionRobotMovement2D(int version) {
    if (version > 7)
        badVersion(version);
    const auto method = [&] {
        const auto m = read<int32_t>("the estimation method");
        if (m != 0 && m != 1)  // emOdometry, emScan2DMatching
            fail("unknown estimation method " + std::to_string(m));
        return m;
    };
    if (version <= 1) {
        object("mrpt::poses::CPosePDF");
        method();
        if (version == 1)
            skip(1 + 2 * 4 + 1 + 2 * 4, "velocities and encoders");
        return;
    }
    if (method() == 0) {
        if (version == 2) {
            member("mrpt::poses::CPose2D");
            skip(44, "the motion model");
        } else {
            odometryModel(version);
        }
    } else {
        object("mrpt::poses::CPosePDF");
    }
    const bool hasVelocities = boolean("hasVelocities");
    if (version >= 7) {
        skip(hasVelocities ? 3 * 8 : 0, "the velocities");
    } else {
        skip(2 * 4, "the velocities");
    }
    const bool hasEncoders = boolean("hasEncodersInfo");
    if (version < 7 || hasEncoders)
        skip(2 * 4, "the encoder ticks");
    if (version >= 6)
        skip(8, "the timestamp");
}

void Checker::actionCollection(int version) {
    if (version != 0)
        badVersion(version);
    const auto n = read<uint32_t>("the number of actions");
    expectElements(n, kMinObjectBytes, "the actions");
    for (uint32_t i = 0; i < n; ++i)
        object("mrpt::obs::CAction");
}

void Checker::sensoryFrame(int version) {
    if (version > 2)
        badVersion(version);
    if (version < 2)
        skip(4, "the frame ID");
    if (version == 0)
        skip(8, "the timestamp");
    const auto n = read<uint32_t>("the number of observations");
    expectElements(n, kMinObjectBytes, "the observations");
    for (uint32_t i = 0; i < n; ++i)
        object("mrpt::obs::CObservation");
}

void Checker::rangeScan(int version) {
    if (version > 7)
        badVersion(version);
    skip(4 + 1 + 4, "aperture, rightToLeft, maxRange");
    member("mrpt::poses::CPose3D");
    if (version < 6)
        matrix("mrpt::math::CMatrixF", 4, 0, 0);  // the sensor pose covariance, unused
    const auto n = read<uint32_t>("the number of readings");
    array(n, 4, "the ranges");
    if (version >= 1)
        array(n, 1, "the validity flags");
    if (version <= 3) {
        skip((version >= 2 ? 4 : 0) + (version >= 3 ? 8 : 0), "stdError, timestamp");
        return;
    }
    skip(4 + 8 + 4, "stdError, timestamp, beamAperture");
    if (version >= 5) {
        string("the sensor label");
        skip(8, "deltaPitch");
    }
    if (version >= 7 && boolean("hasIntensity"))
        array(n, 4, "the intensities");
}

void Checker::odometry(int version) {
    if (version > 2)
        badVersion(version);
    member("mrpt::poses::CPose2D");
    string("the sensor label");
    skip(8, "the timestamp");
    if (version == 0)
        return;
    const bool hasEncoders = boolean("hasEncodersInfo");
    if (hasEncoders || version < 2)
        skip(2 * 4, "the encoder ticks");
    const bool hasVelocities = boolean("hasVelocities");
    if (version < 2) {
        skip(2 * 4, "the velocities");
    } else if (hasVelocities) {
        skip(3 * 8, "the velocities");
    }
}

void Checker::bearingRange(int version) {
    if (version > 3)
        badVersion(version);
    skip(version >= 3 ? 4 * 4 : 3 * 4, "distances and field of view");
    member("mrpt::poses::CPose3D");
    if (version >= 2)
        skip(8, "the timestamp");
    const bool validCovariances = version >= 3 && boolean("validCovariances");
    if (version >= 3 && !validCovariances)
        skip(3 * 4, "the sensor noise");
    const auto n = read<uint32_t>("the number of landmarks");
    expectElements(n, 4 * 4, "the landmarks");
    for (uint32_t i = 0; i < n; ++i) {
        skip(4 * 4, "a landmark");
        if (validCovariances)
            matrix("mrpt::math::CMatrixD", 8, 3, 3);
    }
    if (version >= 1)
        string("the sensor label");
}

// COccupancyGridMap2D: MRPT sizes the grid from the stored limits and resolution (setSize()
// with its rounding), then reads the cells; both must be plausible and present.
void Checker::gridMap(int version) {
    if (version > 6)
        badVersion(version);
    constexpr unsigned kOwnBits = 8 * sizeof(mrpt::maps::OccGridCellTraits::cellType);
    const unsigned bits = version >= 2 ? read<uint8_t>("the bits per cell") : kOwnBits;
    if (bits != 8 && bits != 16)
        fail(std::to_string(bits) + " bits per cell (8 or 16)");
    skip(8, "the stored size");  // unused by MRPT's reader
    float xMin = read<float>("x_min"), xMax = read<float>("x_max");
    float yMin = read<float>("y_min"), yMax = read<float>("y_max");
    const float res = read<float>("the resolution");
    if (!(std::isfinite(xMin) && std::isfinite(xMax) && std::isfinite(yMin) &&
          std::isfinite(yMax) && std::isfinite(res) && res > 0 && xMax > xMin && yMax > yMin)) {
        fail("implausible limits or resolution");
    }
    // COccupancyGridMap2D::setSize(), in float as MRPT computes it.
    xMin = res * std::round(xMin / res), xMax = res * std::round(xMax / res);
    yMin = res * std::round(yMin / res), yMax = res * std::round(yMax / res);
    const double cellsX = std::round((xMax - xMin) / res);
    const double cellsY = std::round((yMax - yMin) / res);
    if (!(cellsX * cellsY <= static_cast<double>(kMaxGridMapCells))) {
        fail("a grid of " + std::to_string(cellsX) + " x " + std::to_string(cellsY) +
             " cells (at most " + std::to_string(kMaxGridMapCells) + ")");
    }
    array(static_cast<uint64_t>(cellsX * cellsY), bits / 8, "the cells");
    gridMapOptions(version);
}

void Checker::gridMapOptions(int version) {
    if (version >= 1) {
        // insertionOptions (20 bytes), likelihoodMethod, likelihoodOptions (54 bytes) up to
        // OWA_weights, as COccupancyGridMap2D::serializeFrom reads them.
        skip(20 + 4 + 54, "the map options");
        array(read<uint32_t>("the OWA weights"), 4, "the OWA weights");
        skip(1, "enableLikelihoodCache");
        if (version >= 6) {
            member("mrpt::maps::TMapGenericParams");
        } else {
            skip(1, "disableSaveAs3DObject");
        }
    }
    if (version >= 4)
        skip(2 * 4, "the CFD feature sizes");
    if (version >= 5)
        skip(1, "wideningBeamsWithDistance");
}

void Checker::mapGenericParams(int version) {
    if (version != 0)
        badVersion(version);
    skip(3, "the flags");
}

// toposlam::features::CObservationLaserFeatures (libs/features, which builds on this library:
// keep this in step with its serializeFrom). Later versions are left unchecked.
void Checker::laserFeatures(int version) {
    if (version != 0)
        throw StopChecking{};
    skip(8, "the timestamp");
    string("the sensor label");
    member("mrpt::poses::CPose3D");
    string("the extractor name");
    string("the scan label");
    // Segment: 2 points, line (theta, rho), 2 beams, 2 end types, RMS; corner: point, 3
    // indices, angle, covariance (3 doubles), type; endpoint: point, type, beam.
    const std::size_t segment = 4 * 8 + 2 * 8 + 2 * 4 + 2 + 8;
    const std::size_t corner = 2 * 8 + 3 * 4 + 8 + 3 * 8 + 1;
    const std::size_t endpoint = 2 * 8 + 1 + 4;
    array(read<uint32_t>("the number of segments"), segment, "the segments");
    array(read<uint32_t>("the number of corners"), corner, "the corners");
    array(read<uint32_t>("the number of endpoints"), endpoint, "the endpoints");
}

const std::map<std::string, Checker::Body>& Checker::bodies() {
    static const std::map<std::string, Body> kBodies{
        {"mrpt::poses::CPose2D", &Checker::pose2D},
        {"mrpt::poses::CPose3D", &Checker::pose3D},
        {"mrpt::poses::CPosePDFGaussian", &Checker::posePdfGaussian},
        {"mrpt::obs::CActionRobotMovement2D", &Checker::actionRobotMovement2D},
        {"mrpt::obs::CActionCollection", &Checker::actionCollection},
        {"mrpt::obs::CSensoryFrame", &Checker::sensoryFrame},
        {"mrpt::obs::CObservation2DRangeScan", &Checker::rangeScan},
        {"mrpt::obs::CObservationOdometry", &Checker::odometry},
        {"mrpt::obs::CObservationBearingRange", &Checker::bearingRange},
        {"mrpt::maps::COccupancyGridMap2D", &Checker::gridMap},
        {"mrpt::maps::TMapGenericParams", &Checker::mapGenericParams},
        {"toposlam::features::CObservationLaserFeatures", &Checker::laserFeatures},
    };
    return kBodies;
}

}  // namespace

ObjectCheck checkNextObject(LookaheadStream& in) {
    if (!in.ensure(1))
        return {};
    Checker checker(in);
    try {
        checker.object("");
        return {checker.topClass(), true, checker.position()};
    } catch (const StopChecking&) {
        return {checker.topClass(), false, 0};
    }
}

}  // namespace toposlam::io
