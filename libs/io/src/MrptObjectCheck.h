#pragma once
// A structural check of MRPT-serialized objects before MRPT deserializes them.
//
// MRPT 2.5.8's deserializers trust the file: they allocate what a length field says (strings,
// scans, the observations of a sensory frame, a grid's cells, the particles of a motion
// model) before reading the data, and some dereference a nested object of the wrong class.
// A few hundred corrupt bytes can so make a reader allocate gigabytes or crash. For the
// classes laser logs and grid maps are made of, this check walks the bytes the way MRPT 2.5.8
// reads them and verifies every length against the bytes the file really has (they are
// fetched, in bounded chunks, before MRPT sees them), the versions, the classes of nested
// objects and the few values MRPT allocates or dereferences by:
//   CSensoryFrame, CActionCollection, CActionRobotMovement2D (estimation method, motion model,
//   particle count), CObservation2DRangeScan, CObservationOdometry, CObservationBearingRange,
//   CPose2D, CPose3D, CPosePDFGaussian, CMatrixF, CMatrixD, COccupancyGridMap2D (cell count
//   at most kMaxGridMapCells), TMapGenericParams, and TopoSLAM's CObservationLaserFeatures
//   (its version 0).
// Both MRPT header formats (current and pre-2007) are understood. An object of any other class
// (camera images, IMU, topological maps, ...) ends the check there: the rest of that
// top-level object is read by its own deserializer, unchecked (ObjectCheck::complete is
// false); element counts of the containers around it (sensory frame, action collection) have
// been checked against the bytes left by then, since MRPT allocates the elements first.
#include <toposlam/io/GridMapIO.h>
#include <cstddef>
#include <stdexcept>
#include <string>

#include "LookaheadStream.h"

namespace toposlam::io {

/// A malformed object; what() names the (nested) object and what is wrong with it.
class MalformedObject : public std::runtime_error {
  public:
    MalformedObject(const std::string& topClass, const std::string& what)
        : std::runtime_error(what), topClass_(topClass) {}
    /// The top-level object's class as its header names it ("" if unreadable).
    const std::string& topClass() const { return topClass_; }

  private:
    std::string topClass_;
};

struct ObjectCheck {
    std::string className;  ///< of the top-level object; "" when no byte is left
    bool complete = false;  ///< every byte of the object was checked
    std::size_t size = 0;   ///< bytes of the object, when complete
};

/// Checks the object that starts at the read position of `in`, without consuming it.
/// Throws MalformedObject.
ObjectCheck checkNextObject(LookaheadStream& in);

}  // namespace toposlam::io
