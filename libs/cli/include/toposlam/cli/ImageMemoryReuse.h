#pragma once
// Room segmentation allocates and frees dozens of full-map images (1-20 MB each) per map.
// By default glibc gives such blocks back to the kernel when they are freed: it unmaps those it
// mapped on their own and trims the top of its heap (both thresholds adapt to the blocks seen,
// from 128 KiB up). The next image's pages are then page-faulted and zeroed by the kernel again:
// on the project's 2-core VMs a fifth of B4's time per map, and 40 % of one toposlam-rooms run
// on a 4.7 Mpx map (benchmarks.md, B4 time).
// Apps that segment maps call this once, before any work.

namespace toposlam::cli {

/// Makes glibc serve blocks up to 32 MiB (its largest mmap threshold; a 4.7 Mpx label image is
/// 19 MB) from its heap, and keep up to 512 MiB of freed heap instead of returning it to the
/// kernel (mallopt M_MMAP_THRESHOLD and M_TRIM_THRESHOLD), so a freed image's pages serve the
/// next one. The heap can fragment a little: the peak RSS of toposlam-bench-rooms-time's 40 maps
/// grew from 293 to 316 MB. Has no effect off glibc (nor under AddressSanitizer).
void reuseFreedImageMemory();

}  // namespace toposlam::cli
