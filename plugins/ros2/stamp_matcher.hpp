#pragma once
// Pairs depth images with the camera_info of the same header stamp. The two topics arrive on
// separate DDS readers, so either may come first; both come in stamp order from one publisher.

#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <opencv2/core/mat.hpp>
#include <optional>
#include <string>

#include "facet/types/frame.hpp"

namespace facet::ros2 {

struct ReceivedImage {
  std::int64_t stamp_ns = 0;
  std::string frame_id;
  cv::Mat depth;
  std::int64_t received_ns = 0;  // the receiver's clock when it was taken from DDS
};

struct MatchedFrame {
  ReceivedImage image;
  CameraIntrinsics camera;
};

class StampMatcher {
 public:
  // At most `max_pending_images` images wait for their camera_info (the oldest is dropped
  // beyond that); the last `max_infos` camera_infos are kept.
  StampMatcher(std::size_t max_pending_images, std::size_t max_infos);

  void add_image(ReceivedImage image);
  void add_info(std::int64_t stamp_ns, const CameraIntrinsics& camera);

  // Every frame in order: the oldest image once its camera_info is there. An image older than
  // the newest camera_info that has none of its own is dropped (its camera_info was lost).
  std::optional<MatchedFrame> take_oldest();
  // The present: the newest image that has its camera_info; the older ones are dropped.
  std::optional<MatchedFrame> take_newest();

  // Images dropped since the last call: never matched, or passed over by take_newest.
  std::size_t take_dropped_count();
  // Images dropped because no camera_info of their stamp came, since the start.
  std::size_t unmatched_total() const { return unmatched_total_; }
  std::size_t pending_images() const { return images_.size(); }

 private:
  void drop_oldest_image(bool unmatched);
  std::optional<CameraIntrinsics> info_for(std::int64_t stamp_ns) const;

  std::size_t max_pending_images_;
  std::size_t max_infos_;
  std::deque<ReceivedImage> images_;                // in arrival order
  std::map<std::int64_t, CameraIntrinsics> infos_;  // by stamp
  std::size_t dropped_ = 0;
  std::size_t unmatched_total_ = 0;
};

}  // namespace facet::ros2
