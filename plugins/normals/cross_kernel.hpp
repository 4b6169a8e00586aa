#pragma once
// Normals from the cross product of two tangents spanned by neighbours at distance r
// (the kernel behind normals.cross).

#include <opencv2/core/mat.hpp>

#include "facet/parallel.hpp"
#include "normals/depth_space.hpp"

namespace facet::normals {

// Which neighbours span the tangents of pixel p = (x, y).
//   paper:   the paper's (Fig. 2) triangle A = (x-r, y-r), B = (x+r, y-r), C = (x, y+r);
//            n = (B - A) x (C - A). Not centred on p: its centroid is r/3 above p.
//   centred: n = ((x+r, y) - (x-r, y)) x ((x, y+r) - (x, y-r)); symmetric about p.
enum class Triangle { paper, centred };

// What a pixel with depth gets when its triangle reads a neighbour without depth.
//   none:      no normal (NaN), the paper's rule.
//   one_sided: the first of four one-sided tangent pairs that avoids the hole: (p to its right
//              or left neighbour at r) x (p to the one below or above), tried right-below,
//              left-below, right-above, left-above. A pixel beside a one-pixel dropout line thus
//              keeps the normal of its own surface instead of widening the hole by r.
enum class HoleNormals { none, one_sided };

struct CrossOptions {
  int radius_px = 2;
  Triangle triangle = Triangle::paper;
  HoleNormals at_holes = HoleNormals::none;
};

// normals: CV_32FC3 unit normals of z (CV_32FC1, NaN = invalid) in the space of `grid`, oriented
// towards the camera (metric: n . p < 0 at the pixel's point p; image: negative third
// component). NaN where the pixel is invalid, within r of the border, and where a neighbour
// used is invalid (with HoleNormals::one_sided: where every tangent pair meets a hole).
// `normals` is (re)allocated to z's size. Bands of rows are computed on `runner`'s threads when
// one is given (each row depends only on z).
void cross_normals(const cv::Mat& z, const PixelGrid& grid, const CrossOptions& options,
                   cv::Mat& normals, ParallelRunner* runner = nullptr);

// Row y of the same (3 * z.cols floats into `out`), for consumers that work row by row and would
// otherwise write and re-read a whole image.
void cross_normals_row(const cv::Mat& z, const PixelGrid& grid, const CrossOptions& options, int y,
                       float* out);

}  // namespace facet::normals
