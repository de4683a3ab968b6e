// Extractors reuse their workspaces: once warmed up on scans of a given size, extracting
// another scan performs no heap allocation at all. Counted by replacing the global operator
// new in this test binary.
#include <gtest/gtest.h>
#include <toposlam/featureeval/SyntheticRooms.h>
#include <toposlam/features/FeatureExtractor.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "FeatureTestScenes.h"

// The replacements pair malloc with free; GCC cannot see that they replace new/delete as a
// whole and warns about "mismatched" calls once they are inlined into callers.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif

namespace {
std::atomic<bool> counting{false};
std::atomic<std::size_t> allocations{0};
}  // namespace

void* operator new(std::size_t n) {
    if (counting)
        ++allocations;
    if (void* p = std::malloc(n ? n : 1))
        return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t n) {
    if (counting)
        ++allocations;
    if (void* p = std::malloc(n ? n : 1))
        return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete[](void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    std::free(p);
}

using namespace toposlam;

TEST(Extractors, AllocateNothingOnceWarmedUp) {
    std::vector<mrpt::obs::CObservation2DRangeScan> scans;
    std::mt19937 rng(17);
    for (int room = 0; room < 4; ++room) {
        const auto scene = featureeval::makeSyntheticRoom(rng);
        for (const auto& pose : scene.poses) {
            scans.push_back(test::scanOf(scene, pose, 1081, 1.5 * M_PI, 0.01, room));
        }
    }
    for (const std::string& name : features::featureExtractorNames()) {
        auto ex = features::makeFeatureExtractor(name);
        features::ScanFeatures f;
        for (const auto& scan : scans)
            ex->extract(scan, f);  // warm-up
        allocations = 0;
        counting = true;
        for (const auto& scan : scans)
            ex->extract(scan, f);
        counting = false;
        EXPECT_EQ(allocations.load(), 0u) << name;
        EXPECT_FALSE(f.segments.empty()) << name;
    }
}
