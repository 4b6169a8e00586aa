#pragma once
// Keeps the ids of segments stable over the frames of a video: each frame's segments are paired
// one to one with the tracks of earlier frames by pixel overlap (eval/segment_matching.hpp), a
// paired segment takes its track's id, an unpaired one starts a new track with an id never used
// before. A track that finds no segment is remembered for a few frames with the pixels it last
// had, so an object hidden for a moment gets its id back.

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "eval/segment_matching.hpp"

namespace facet::track {

struct TrackOptions {
  eval::OverlapMeasure measure = eval::OverlapMeasure::mean_ratio;
  // A segment continues a track when their overlap is above this.
  double min_overlap = 0.3;
  // Frames a track may go unseen and still be continued; 0 forgets it the first frame it is lost.
  std::int64_t memory_frames = 10;
};

class LabelTracker {
 public:
  explicit LabelTracker(TrackOptions options) : options_(options) {}

  // `labels`: CV_32SC1 segment ids (0 = none) of one frame, frames in order, all of one size.
  // Returns the same segments with their track ids (0 stays 0). Throws std::invalid_argument on
  // a wrong type or a size different from the first frame's.
  cv::Mat update(const cv::Mat& labels);

  std::int32_t largest_id() const { return next_id_ - 1; }
  std::size_t remembered_tracks() const { return tracks_.size(); }

 private:
  struct Track {
    std::int32_t id = 0;
    std::vector<int> pixels;  // row-major indices of its last appearance
    std::int64_t last_seen = 0;
  };

  TrackOptions options_;
  std::vector<Track> tracks_;  // ascending ids
  std::int32_t next_id_ = 1;
  std::int64_t frame_ = 0;
  cv::Size size_;
};

}  // namespace facet::track
