#include "ros2/stamp_matcher.hpp"

#include <algorithm>
#include <utility>

namespace facet::ros2 {

StampMatcher::StampMatcher(std::size_t max_pending_images, std::size_t max_infos)
    : max_pending_images_(std::max<std::size_t>(max_pending_images, 1)),
      max_infos_(std::max<std::size_t>(max_infos, 1)) {}

void StampMatcher::add_image(ReceivedImage image) {
  images_.push_back(std::move(image));
  while (images_.size() > max_pending_images_)
    drop_oldest_image(true);
}

void StampMatcher::add_info(std::int64_t stamp_ns, const CameraIntrinsics& camera) {
  infos_[stamp_ns] = camera;
  while (infos_.size() > max_infos_)
    infos_.erase(infos_.begin());
}

std::optional<CameraIntrinsics> StampMatcher::info_for(std::int64_t stamp_ns) const {
  const auto found = infos_.find(stamp_ns);
  if (found == infos_.end()) return std::nullopt;
  return found->second;
}

void StampMatcher::drop_oldest_image(bool unmatched) {
  images_.pop_front();
  ++dropped_;
  if (unmatched) ++unmatched_total_;
}

std::optional<MatchedFrame> StampMatcher::take_oldest() {
  while (!images_.empty()) {
    const auto camera = info_for(images_.front().stamp_ns);
    if (camera) {
      MatchedFrame frame{std::move(images_.front()), *camera};
      images_.pop_front();
      return frame;
    }
    // camera_infos come in stamp order: one newer than this image means its own was lost.
    const bool lost = !infos_.empty() && infos_.rbegin()->first > images_.front().stamp_ns;
    if (!lost) return std::nullopt;
    drop_oldest_image(true);
  }
  return std::nullopt;
}

std::optional<MatchedFrame> StampMatcher::take_newest() {
  for (auto newest = images_.rbegin(); newest != images_.rend(); ++newest) {
    const auto camera = info_for(newest->stamp_ns);
    if (!camera) continue;
    MatchedFrame frame{std::move(*newest), *camera};
    // Everything before it is older than the present; what came after waits for its info.
    const auto taken = static_cast<std::size_t>(images_.rend() - newest) - 1;
    images_.erase(images_.begin() + static_cast<std::ptrdiff_t>(taken));
    for (std::size_t i = 0; i < taken; ++i)
      drop_oldest_image(false);
    return frame;
  }
  return std::nullopt;
}

std::size_t StampMatcher::take_dropped_count() {
  return std::exchange(dropped_, 0);
}

}  // namespace facet::ros2
