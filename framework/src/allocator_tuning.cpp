#include "facet/framework/allocator_tuning.hpp"

#if __has_include(<malloc.h>)
#include <malloc.h>  // glibc's mallopt and its M_* options; other C libraries may lack them
#endif

namespace facet {

void keep_frame_buffers_mapped() {
#if defined(M_MMAP_THRESHOLD) && defined(M_TRIM_THRESHOLD)
  // Blocks under 32 MiB (glibc's largest mmap threshold) come from the heap, and up to 256 MiB
  // of free heap stays mapped: a few frames' worth of images at 640x480, reused frame after
  // frame.
  constexpr int kMmapThresholdBytes = 32 << 20;
  constexpr int kTrimThresholdBytes = 256 << 20;
  mallopt(M_MMAP_THRESHOLD, kMmapThresholdBytes);
  mallopt(M_TRIM_THRESHOLD, kTrimThresholdBytes);
#endif
}

void share_one_heap_between_threads() {
#if defined(M_ARENA_MAX)
  mallopt(M_ARENA_MAX, 1);
#endif
}

}  // namespace facet
