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

}  // namespace facet
