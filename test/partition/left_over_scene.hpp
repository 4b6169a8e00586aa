#pragma once
// A one-blob scene for the rules that place left-over pixels (unclaimed cores, bodies in front
// of a face): the left columns are claimed by object 1, the rest is left over.

#include <opencv2/core.hpp>

#include "partition/segment_plane.hpp"

namespace facet::partition {

struct LeftOverScene {
  cv::Mat blobs;    // one blob, id 1, over the whole image
  cv::Mat objects;  // object 1 in the left `claimed_cols` columns, 0 elsewhere
  cv::Mat points;   // every point at (0, 0, z_m)
};

inline LeftOverScene left_over_scene(int width_px, int height_px, int claimed_cols, float z_m) {
  LeftOverScene s;
  s.blobs = cv::Mat(height_px, width_px, CV_32SC1, cv::Scalar(1));
  s.objects = cv::Mat::zeros(height_px, width_px, CV_32SC1);
  s.objects.colRange(0, claimed_cols).setTo(1);
  s.points = cv::Mat(height_px, width_px, CV_32FC3, cv::Scalar(0.0F, 0.0F, z_m));
  return s;
}

// The plane z = z_m, facing the camera: a face of the claimed object.
inline FittedPlane facing_plane(float z_m) {
  FittedPlane plane;
  plane.normal = {0.0F, 0.0F, -1.0F};
  plane.offset_m = z_m;
  plane.centroid_m = {0.0F, 0.0F, z_m};
  plane.valid = true;
  return plane;
}

}  // namespace facet::partition
