#pragma once

namespace facet {

// Keeps the allocator from handing frame-sized buffers back to the operating system between
// frames. Every frame allocates images of 1-4 MB (points, normals, labels) and frees them a
// moment later; with glibc's defaults such blocks come from mmap, or the heap top is trimmed,
// and each new frame pays a page fault per 4 KiB page: measured 1.4 ms for the 3.7 MB point
// image alone, more than computing it. Call once, at the start of main (the CLI does;
// facet::Pipeline does unless told not to). Process-wide: it sets two glibc malloc options.
// No-op off glibc.
void keep_frame_buffers_mapped();

// One malloc arena for every thread of the process. With keep_frame_buffers_mapped() each
// arena keeps its own high-water mark of frame buffers mapped, and glibc gives threads arenas
// of their own: a two-thread soak grew 210 -> 235 MB in steps over 10 000 frames, flat with one
// arena (188 -> 194 MB), at no measured cost in frame time (docs/performance.md, "Soak").
// For a process that is only facet (the CLI); an embedding host decides this for its own threads
// (MALLOC_ARENA_MAX=1 in the environment does the same). No-op off glibc.
void share_one_heap_between_threads();

}  // namespace facet
