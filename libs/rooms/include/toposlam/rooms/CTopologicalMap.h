#pragma once
// The topological map as an MRPT serializable object, so that it travels in MRPT archives and
// rawlogs and MRPT's own tools can read it: the class is registered with mrpt-rtti when
// libtoposlam-rooms is loaded (it is part of libtoposlam-plugin.so: RawLogViewer -l, rawlog-edit
// -p), under the name "toposlam::rooms::CTopologicalMap". RawLogViewer shows asString().
//   CFileGZOutputStream f("rooms.topomap.gz"); archiveFrom(f) << CTopologicalMap(map);
#include <toposlam/rooms/TopologicalMap.h>

#include <mrpt/core/Stringifyable.h>
#include <mrpt/serialization/CSerializable.h>

#include <string>

namespace toposlam::rooms {

class CTopologicalMap : public mrpt::serialization::CSerializable, public mrpt::Stringifyable {
    DEFINE_SERIALIZABLE(CTopologicalMap, toposlam::rooms)

  public:
    CTopologicalMap() = default;
    explicit CTopologicalMap(TopologicalMap m) : map(std::move(m)) {}

    TopologicalMap map;

    /// Summary: rooms (id, name, area, centroid), doors (rooms joined, width).
    std::string asString() const override;
};

}  // namespace toposlam::rooms
