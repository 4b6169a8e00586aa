#include "track/label_tracker.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

namespace facet::track {

cv::Mat LabelTracker::update(const cv::Mat& labels) {
  if (labels.type() != CV_32SC1) {
    throw std::invalid_argument("expected CV_32SC1 segment ids");
  }
  if (frame_ == 0) {
    size_ = labels.size();
  } else if (labels.size() != size_) {
    throw std::invalid_argument("the frame is " + std::to_string(labels.cols) + "x" +
                                std::to_string(labels.rows) + ", the first was " +
                                std::to_string(size_.width) + "x" + std::to_string(size_.height));
  }
  CV_Assert(labels.isContinuous());
  const auto* ids = labels.ptr<std::int32_t>(0);
  const int pixel_count = labels.rows * labels.cols;

  // Side a: the remembered tracks; side b: this frame's segments, ascending ids.
  eval::OverlapTable table;
  std::map<std::int32_t, std::vector<int>> segment_pixels;
  for (int i = 0; i < pixel_count; ++i) {
    if (ids[i] != 0) segment_pixels[ids[i]].push_back(i);
  }
  for (const auto& [id, pixels] : segment_pixels) {
    table.ids_b.push_back(id);
    table.pixels_b.push_back(static_cast<std::int64_t>(pixels.size()));
  }
  std::map<std::int32_t, std::size_t> segment_index;
  for (std::size_t b = 0; b < table.ids_b.size(); ++b)
    segment_index[table.ids_b[b]] = b;
  for (const Track& track : tracks_) {
    table.ids_a.push_back(track.id);
    table.pixels_a.push_back(static_cast<std::int64_t>(track.pixels.size()));
  }
  table.both.assign(table.ids_a.size() * table.ids_b.size(), 0);
  for (std::size_t a = 0; a < tracks_.size(); ++a) {
    for (const int i : tracks_[a].pixels) {
      if (ids[i] != 0) ++table.both[a * table.ids_b.size() + segment_index[ids[i]]];
    }
  }

  std::vector<std::int32_t> track_of_segment(table.ids_b.size(), 0);
  for (const eval::SegmentPair& pair :
       eval::match_segments(table, options_.measure, options_.min_overlap)) {
    Track& track = tracks_[pair.a];
    track_of_segment[pair.b] = track.id;
    track.pixels = segment_pixels[table.ids_b[pair.b]];
    track.last_seen = frame_;
  }
  for (std::size_t b = 0; b < table.ids_b.size(); ++b) {
    if (track_of_segment[b] != 0) continue;
    track_of_segment[b] = next_id_++;
    tracks_.push_back({track_of_segment[b], segment_pixels[table.ids_b[b]], frame_});
  }
  // Forget tracks unseen for longer than the memory; new tracks were appended with the largest
  // ids, so the list stays sorted.
  std::erase_if(tracks_, [&](const Track& track) {
    return frame_ - track.last_seen > options_.memory_frames;
  });

  cv::Mat tracked = cv::Mat::zeros(labels.size(), CV_32SC1);
  auto* out = tracked.ptr<std::int32_t>(0);
  for (std::size_t b = 0; b < table.ids_b.size(); ++b) {
    for (const int i : segment_pixels[table.ids_b[b]])
      out[i] = track_of_segment[b];
  }
  ++frame_;
  return tracked;
}

}  // namespace facet::track
