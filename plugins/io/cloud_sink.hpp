#pragma once
// io.cloud: writes each frame's valid 3D points as <dir>/<stem>.ply, with a segment id and its
// colour per point, for MeshLab, CloudCompare, Open3D and the like.

#include <cstdint>
#include <filesystem>
#include <opencv2/core/mat.hpp>
#include <string>

#include "facet/stage.hpp"
#include "io/output_folder.hpp"

namespace facet::io {

enum class PlyFormat { binary_little_endian, ascii };

struct PlyCloud {
  std::string header;         // from "ply" to "end_header\n" inclusive
  std::string body;           // the vertices
  std::int64_t vertices = 0;  // as stated in the header
};

// The PLY file of the finite points of `points` (CV_32FC3, metres; a point with a NaN coordinate
// is skipped). `labels` is CV_32SC1 ids >= 0 of the same size, or empty for all 0. With
// `labelled_only`, points with label 0 are skipped too. `comment` goes into the header.
PlyCloud make_ply(const cv::Mat& points, const cv::Mat& labels, PlyFormat format,
                  bool labelled_only, const std::string& comment);

class CloudSink final : public Stage {
 public:
  static StageSpec spec();
  explicit CloudSink(const Params& params);

  void open(const OpenContext& ctx) override;
  void process(ProcessContext& ctx) override;

 private:
  std::filesystem::path dir_;
  EarlierResults earlier_;  // what the folder held before this run
  PlyFormat format_;
  bool labelled_only_;
};

}  // namespace facet::io
