// Fuzzes the MRPT rawlog reader (libs/io LaserLogReader on binary logs, both rawlog formats,
// plain or gzip), with TopoSLAM's own classes registered as in the apps.
// Input: one flag byte ('1': the rest is gzip-compressed before reading) + the rawlog.
#include <toposlam/classes/TopoSlamClasses.h>
#include <toposlam/io/LaserLogReader.h>

#include "FuzzInput.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const bool registered = (toposlam::classes::registerTopoSlamClasses(), true);
    (void)registered;
    if (size < 1)
        return 0;
    const std::string_view log(reinterpret_cast<const char*>(data + 1), size - 1);
    const std::string path = toposlam::fuzz::writeScratchFile("log.rawlog", log, data[0] == '1');
    toposlam::fuzz::expectOnlyInputErrors("rawlog", [&] {
        toposlam::io::LaserLogReader reader(path);
        toposlam::io::LaserLogRecord record;
        while (reader.next(record))
            (void)reader.fractionRead();
    });
    return 0;
}
