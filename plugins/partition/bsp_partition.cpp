#include "partition/bsp_partition.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace facet::partition {
namespace {

// Signed distances of a bounding box's points to a plane lie within [low, high].
struct DistanceRange {
  float low;
  float high;
};

DistanceRange box_distance(const Bounds& box, const FittedPlane& plane) {
  float centre = plane.offset_m;
  float radius = 0.0F;
  for (int a = 0; a < 3; ++a) {
    const float c = 0.5F * (box.min_m[a] + box.max_m[a]);
    const float h = 0.5F * (box.max_m[a] - box.min_m[a]);
    centre += plane.normal[a] * c;
    radius += std::abs(plane.normal[a]) * h;
  }
  return {centre - radius, centre + radius};
}

// Points of [begin, end) behind (d < -tol) and in front (d > tol) of the plane.
void count_sides(const BlobSegments& points, std::int32_t begin, std::int32_t end,
                 const FittedPlane& plane, float tol, std::int32_t& behind, std::int32_t& front) {
  const float nx = plane.normal[0];
  const float ny = plane.normal[1];
  const float nz = plane.normal[2];
  const float d0 = plane.offset_m;
  const float* x = points.x.data();
  const float* y = points.y.data();
  const float* z = points.z.data();
  std::int32_t b = 0;
  std::int32_t f = 0;
  for (std::int32_t k = begin; k < end; ++k) {
    const float d = nx * x[k] + ny * y[k] + nz * z[k] + d0;
    b += static_cast<std::int32_t>(d < -tol);
    f += static_cast<std::int32_t>(d > tol);
  }
  behind = b;
  front = f;
}

// Eq. (5): L1 distance between the corners of two bounding boxes.
float box_difference(const Bounds& a, const Bounds& b) {
  if (a.empty || b.empty) return std::numeric_limits<float>::infinity();
  float sum = 0.0F;
  for (int i = 0; i < 3; ++i) {
    sum += std::abs(a.min_m[i] - b.min_m[i]) + std::abs(a.max_m[i] - b.max_m[i]);
  }
  return sum;
}

}  // namespace

std::int32_t BspPartitioner::partition(BlobSegments& points, const BlobRange& blob,
                                       std::int32_t* labels, std::int32_t next_id) {
  atoms_.clear();
  faces_.clear();
  std::int64_t face_px = 0;
  for (std::int32_t s = blob.segment_begin; s < blob.segment_end; ++s) {
    const Segment& segment = points.segments[static_cast<std::size_t>(s)];
    Atom atom;
    atom.begin = segment.begin;
    atom.end = segment.end;
    atom.splittable = segment.patch == 0 || !rule_.keep_patches;
    atom.box = bounds_of(points, segment.begin, segment.end);
    if (segment.patch != 0 && segment.size() >= rule_.min_face_px) {
      Face face{fit_plane(points, segment.begin, segment.end), segment.size(), false};
      if (face.plane.valid) {
        atom.face = static_cast<std::int32_t>(faces_.size());
        faces_.push_back(face);
        face_px += segment.size();
      }
    }
    atoms_.push_back(atom);
  }

  // The paper's gate: too few face points (P_f < N_f, or P_f / P_e < k_fe) to partition by.
  const std::int64_t other_px = (blob.end - blob.begin) - face_px;
  std::int32_t parts = 0;
  const bool splittable_blob =
      face_px >= rule_.min_face_px &&
      static_cast<double>(face_px) >= rule_.min_face_ratio * static_cast<double>(other_px);
  stack_.clear();
  stack_.emplace_back();
  for (std::int32_t a = 0; a < static_cast<std::int32_t>(atoms_.size()); ++a) {
    stack_.back().push_back(a);
  }
  std::int32_t blob_splits = 0;
  std::vector<std::int32_t> other;
  while (!stack_.empty()) {
    std::vector<std::int32_t> part = std::move(stack_.back());
    stack_.pop_back();
    bool split = splittable_blob;
    while (split) {
      split = false;
      // Untried faces of this part, largest first (ties by face index: deterministic).
      candidates_.clear();
      for (const std::int32_t a : part) {
        const std::int32_t f = atoms_[static_cast<std::size_t>(a)].face;
        if (f >= 0 && !faces_[static_cast<std::size_t>(f)].tried) candidates_.push_back(f);
      }
      std::sort(candidates_.begin(), candidates_.end(), [&](std::int32_t l, std::int32_t r) {
        const auto sl = faces_[static_cast<std::size_t>(l)].size_px;
        const auto sr = faces_[static_cast<std::size_t>(r)].size_px;
        return sl != sr ? sl > sr : l < r;
      });
      for (const std::int32_t f : candidates_) {
        if (blob_splits >= rule_.max_splits) break;
        Face& face = faces_[static_cast<std::size_t>(f)];
        face.tried = true;
        other.clear();
        if (try_split(points, face, part, other)) {
          ++blob_splits;
          stack_.push_back(other);
          split = true;
          break;
        }
      }
    }
    const std::int32_t id = next_id + parts;
    ++parts;
    for (const std::int32_t a : part) {
      const Atom& atom = atoms_[static_cast<std::size_t>(a)];
      for (std::int32_t k = atom.begin; k < atom.end; ++k) {
        labels[points.pixel[static_cast<std::size_t>(k)]] = id;
      }
    }
  }
  splits_ += blob_splits;
  return parts;
}

bool BspPartitioner::try_split(BlobSegments& points, const Face& face,
                               std::vector<std::int32_t>& part, std::vector<std::int32_t>& other) {
  const auto tol = static_cast<float>(rule_.tolerance_m);
  const FittedPlane& plane = face.plane;
  counts_.resize(atoms_.size());
  std::int64_t behind_px = 0;
  std::int64_t front_px = 0;
  for (const std::int32_t a : part) {
    const Atom& atom = atoms_[static_cast<std::size_t>(a)];
    AtomCounts& c = counts_[static_cast<std::size_t>(a)];
    const std::int32_t size = atom.end - atom.begin;
    const DistanceRange range = box_distance(atom.box, plane);
    c = AtomCounts{};
    if (range.low > tol) {
      c.side[front] = size;
    } else if (range.high < -tol) {
      c.side[behind] = size;
    } else if (range.low >= -tol && range.high <= tol) {
      c.side[on] = size;
    } else {
      count_sides(points, atom.begin, atom.end, plane, tol, c.side[behind], c.side[front]);
      c.side[on] = size - c.side[behind] - c.side[front];
    }
    if (!atom.splittable) {
      // A kept patch counts wholly for the side holding most of its points.
      const Side majority = c.side[on] >= std::max(c.side[behind], c.side[front])
                                ? on
                                : (c.side[behind] >= c.side[front] ? behind : front);
      c = AtomCounts{};
      c.side[majority] = size;
    }
    behind_px += c.side[behind];
    front_px += c.side[front];
  }
  if (behind_px < rule_.min_split_px || front_px < rule_.min_split_px) return false;

  const Side plane_goes_to =
      rule_.plane_owner == PlaneOwner::behind ? behind : plane_side(points, plane, part);
  std::vector<std::int32_t> keep;
  keep.reserve(part.size());
  for (const std::int32_t a : part) {
    const AtomCounts c = counts_[static_cast<std::size_t>(a)];
    const std::int32_t size =
        atoms_[static_cast<std::size_t>(a)].end - atoms_[static_cast<std::size_t>(a)].begin;
    const std::int32_t to_plane_side = c.side[plane_goes_to] + c.side[on];
    if (to_plane_side == size) {
      keep.push_back(a);
      continue;
    }
    if (to_plane_side == 0) {
      other.push_back(a);
      continue;
    }
    // A splittable atom with points on both sides: cut it in two.
    Atom first = atoms_[static_cast<std::size_t>(a)];
    const std::int32_t cut = cut_atom(points, first, plane, plane_goes_to);
    if (cut == first.end || cut == first.begin) {
      // Rounding at the band's edge left one piece empty.
      (cut == first.end ? keep : other).push_back(a);
      continue;
    }
    Atom second = first;
    first.end = cut;
    second.begin = cut;
    first.box = bounds_of(points, first.begin, first.end);
    second.box = bounds_of(points, second.begin, second.end);
    // The face stays with its larger piece; the smaller piece is a plain cut-off.
    if (first.face >= 0) {
      (first.end - first.begin >= second.end - second.begin ? second : first).face = -1;
    }
    atoms_[static_cast<std::size_t>(a)] = first;
    atoms_.push_back(second);
    const auto b = static_cast<std::int32_t>(atoms_.size()) - 1;
    // cut_atom puts the plane's side first.
    keep.push_back(a);
    other.push_back(b);
  }
  part.swap(keep);
  return true;
}

BspPartitioner::Side BspPartitioner::plane_side(const BlobSegments& points,
                                                const FittedPlane& plane,
                                                const std::vector<std::int32_t>& part) const {
  // Bounding boxes of the slice within 2 delta of the plane, split into on / behind / in front;
  // the plane goes to the side whose slice box is more like the on-plane box (eq. 5).
  const auto tol = static_cast<float>(rule_.tolerance_m);
  const float slice = 2.0F * tol;
  Bounds box[3];
  const float* x = points.x.data();
  const float* y = points.y.data();
  const float* z = points.z.data();
  for (const std::int32_t a : part) {
    const Atom& atom = atoms_[static_cast<std::size_t>(a)];
    const DistanceRange range = box_distance(atom.box, plane);
    if (range.low > slice || range.high < -slice) continue;
    for (std::int32_t k = atom.begin; k < atom.end; ++k) {
      const float d = plane.signed_distance_m(x[k], y[k], z[k]);
      if (d < -slice || d > slice) continue;
      const Side s = d < -tol ? behind : (d > tol ? front : on);
      box[s].add(x[k], y[k], z[k]);
    }
  }
  const float e_behind = box_difference(box[behind], box[on]);
  const float e_front = box_difference(box[front], box[on]);
  return e_behind < e_front ? behind : front;
}

std::int32_t BspPartitioner::cut_atom(BlobSegments& points, const Atom& atom,
                                      const FittedPlane& plane, Side plane_goes_to) {
  const auto tol = static_cast<float>(rule_.tolerance_m);
  const auto n = static_cast<std::size_t>(atom.end - atom.begin);
  scratch_pixel_.resize(n);
  scratch_xyz_.resize(3 * n);
  // Stable two-way partition through a scratch buffer: the plane's side first, raster order kept.
  std::size_t head = 0;
  std::size_t tail = n;
  for (std::int32_t k = atom.begin; k < atom.end; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const float d = plane.signed_distance_m(points.x[i], points.y[i], points.z[i]);
    const Side s = d < -tol ? behind : (d > tol ? front : plane_goes_to);
    std::size_t slot = 0;
    if (s == plane_goes_to) {
      slot = head++;
    } else {
      slot = --tail;
    }
    scratch_pixel_[slot] = points.pixel[i];
    scratch_xyz_[3 * slot] = points.x[i];
    scratch_xyz_[3 * slot + 1] = points.y[i];
    scratch_xyz_[3 * slot + 2] = points.z[i];
  }
  // The other side was filled from the back; reading it backwards restores raster order.
  for (std::size_t j = 0; j < n; ++j) {
    const auto i = static_cast<std::size_t>(atom.begin) + j;
    const std::size_t src = j < head ? j : head + (n - 1 - j);
    points.pixel[i] = scratch_pixel_[src];
    points.x[i] = scratch_xyz_[3 * src];
    points.y[i] = scratch_xyz_[3 * src + 1];
    points.z[i] = scratch_xyz_[3 * src + 2];
  }
  return atom.begin + static_cast<std::int32_t>(head);
}

}  // namespace facet::partition
