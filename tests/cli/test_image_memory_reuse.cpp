// cli::reuseFreedImageMemory: large images come from glibc's heap and stay there when freed.
#include <gtest/gtest.h>
#include <toposlam/cli/ImageMemoryReuse.h>

#include <cstdlib>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

// AddressSanitizer replaces malloc: GCC says so with __SANITIZE_ADDRESS__, clang with
// __has_feature.
#if defined(__SANITIZE_ADDRESS__)
#define TOPOSLAM_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TOPOSLAM_ASAN 1
#endif
#endif

namespace {

constexpr std::size_t kImageBytes = 16u << 20;  // a 4 Mpx CV_32S label image

TEST(ImageMemoryReuse, LargeImagesComeFromTheHeapAndStayThereWhenFreed) {
#if !defined(__GLIBC__) || defined(TOPOSLAM_ASAN)
    GTEST_SKIP() << "glibc's own allocator only (AddressSanitizer replaces it)";
#else
    toposlam::cli::reuseFreedImageMemory();
    const std::size_t mappedBefore = mallinfo2().hblkhd;
    char* volatile image = static_cast<char*>(std::malloc(kImageBytes));
    ASSERT_NE(image, nullptr);
    image[kImageBytes - 1] = 1;
    // Without the settings glibc maps a block this large on its own and unmaps it on free.
    EXPECT_EQ(mallinfo2().hblkhd, mappedBefore);
    std::free(image);
    EXPECT_GE(mallinfo2().arena, kImageBytes) << "the freed image was returned to the kernel";
#endif
}

}  // namespace
