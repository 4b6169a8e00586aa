#pragma once
// Finishing an object label image: blob pixels no object claimed, and deterministic ids.

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <span>
#include <vector>

namespace facet::partition {

// `objects` (CV_32SC1, continuous, same size as `blobs`) holds object ids > 0 for the pixels a
// stage placed. Every other pixel of a blob (no valid point, no patch) takes the object of the
// claimed pixel of the same blob it is fewest 8-neighbour steps from, never crossing into another
// blob. A connected part of a blob that reaches no claimed pixel becomes an object of its own,
// with ids from `next_id` on. Pixels outside every blob stay 0.
void fill_blob_gaps(cv::Mat& objects, const cv::Mat& blobs, std::int32_t next_id);

// The same, for `gaps` that collect_blob_gaps found in `objects` (both images continuous).
void fill_blob_gaps(cv::Mat& objects, const cv::Mat& blobs, std::int32_t next_id,
                    std::span<const std::int32_t> gaps);

// The flat indices, ascending, of the pixels of a blob without an object label (both images
// CV_32SC1, continuous, of one size).
void collect_blob_gaps(const cv::Mat& objects, const cv::Mat& blobs,
                       std::vector<std::int32_t>& gaps);

// Renumbers the ids to 1..N in raster order of each object's first pixel and returns N.
std::int32_t relabel_in_raster_order(cv::Mat& objects);

}  // namespace facet::partition
