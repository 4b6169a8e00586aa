#pragma once
// Binary space partitioning of one blob by the planes of its faces (paper sec. II-B f, Fig. 5,
// eq. 5), with the paper's announced fix: a surface patch is never split.
//
// Cost. A blob is held as "atoms": index ranges of the gathered points that move as a unit (a
// kept patch) or may be cut (points in no patch; every patch when patches are not kept). A plane
// is tested per atom first through the atom's bounding box; only atoms whose box straddles the
// tolerance band are visited point by point. A face that failed to split a part can never split a
// subset of that part (each side only loses points), so every face is tried at most once per
// blob: the work is about (faces x atoms) plus the points of straddling atoms, not exponential.

#include <cstdint>
#include <vector>

#include "partition/blob_segments.hpp"
#include "partition/segment_plane.hpp"

namespace facet::partition {

// Which side of a splitting plane its on-plane points (the face among them) join.
enum class PlaneOwner {
  boxes,   // paper eq. (5): the side whose slice bounding box is most like the plane's
  behind,  // the side behind the face: a visible face's body lies behind it
};

struct BspRule {
  double tolerance_m = 0.012;      // delta: points within it are "on" the plane
  std::int32_t min_split_px = 20;  // N_split: both sides need this many points
  std::int32_t min_face_px = 30;   // N_f: a face's least size; also the blob's least face total
  double min_face_ratio = 0.1;     // k_fe: face points / other points below it: blob not split
  bool keep_patches = true;        // a patch goes whole to the side holding most of its points
  std::int32_t max_splits = 64;    // per blob, a guard against pathological input
  PlaneOwner plane_owner = PlaneOwner::behind;
};

class BspPartitioner {
 public:
  explicit BspPartitioner(BspRule rule) : rule_(rule) {}

  // For a frame of another resolution (its pixel counts scaled).
  void set_rule(const BspRule& rule) { rule_ = rule; }

  // Partitions `blob`; writes part ids next_id, next_id + 1, ... to labels[pixel] of its points
  // and returns the number of parts. Reorders points within the blob's range.
  std::int32_t partition(BlobSegments& points, const BlobRange& blob, std::int32_t* labels,
                         std::int32_t next_id);

  std::int64_t splits() const { return splits_; }
  void reset_counters() { splits_ = 0; }

 private:
  enum Side : std::int8_t { behind = 0, on = 1, front = 2 };
  struct Atom {
    std::int32_t begin = 0;
    std::int32_t end = 0;
    std::int32_t face = -1;  // index into faces_ when this atom carries a face
    bool splittable = false;
    Bounds box;
  };
  struct Face {
    FittedPlane plane;
    std::int32_t size_px = 0;
    bool tried = false;
  };
  struct AtomCounts {
    std::int32_t side[3] = {0, 0, 0};
  };

  // Tries the face's plane on `part`; on success replaces `part` with the plane's side and
  // appends the other side to `other`. Returns whether it split.
  bool try_split(BlobSegments& points, const Face& face, std::vector<std::int32_t>& part,
                 std::vector<std::int32_t>& other);
  Side plane_side(const BlobSegments& points, const FittedPlane& plane,
                  const std::vector<std::int32_t>& part) const;
  // Moves the atom's points on `side_of_plane`'s side of the plane (behind and, if the plane
  // goes behind, on) first; returns the first index of the rest.
  std::int32_t cut_atom(BlobSegments& points, const Atom& atom, const FittedPlane& plane,
                        Side plane_goes_to);

  BspRule rule_;
  std::vector<Atom> atoms_;
  std::vector<Face> faces_;
  std::vector<AtomCounts> counts_;
  std::vector<std::vector<std::int32_t>> stack_;
  std::vector<std::int32_t> candidates_;
  std::vector<std::int32_t> scratch_pixel_;
  std::vector<float> scratch_xyz_;
  std::int64_t splits_ = 0;
};

}  // namespace facet::partition
