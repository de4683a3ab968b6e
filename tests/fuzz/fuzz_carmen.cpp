// Fuzzes the CARMEN log reader (libs/io LaserLogReader on text logs, plain or gzip).
// Input: one flag byte ('1': the rest is gzip-compressed before reading) + the log.
#include <toposlam/io/LaserLogReader.h>

#include "FuzzInput.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 1)
        return 0;
    const std::string_view log(reinterpret_cast<const char*>(data + 1), size - 1);
    const std::string path = toposlam::fuzz::writeScratchFile("log.clf", log, data[0] == '1');
    toposlam::fuzz::expectOnlyInputErrors("carmen", [&] {
        toposlam::io::LaserLogReader reader(path);
        toposlam::io::LaserLogRecord record;
        while (reader.next(record))
            (void)reader.fractionRead();
    });
    return 0;
}
