#include <toposlam/cli/ImageMemoryReuse.h>

#include <cstdlib>  // defines __GLIBC__ on glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace toposlam::cli {

void reuseFreedImageMemory() {
#if defined(__GLIBC__)
    constexpr int kMmapThreshold = 32 << 20;  // glibc's maximum on 64-bit
    constexpr int kTrimThreshold = 512 << 20;
    mallopt(M_MMAP_THRESHOLD, kMmapThreshold);
    mallopt(M_TRIM_THRESHOLD, kTrimThreshold);
#endif
}

}  // namespace toposlam::cli
