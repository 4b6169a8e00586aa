// Stock PCL segmentation pipelines on the frames of a dataset, timed and written as label images,
// so that facet's quality and speed can be compared with them in one run on one machine:
//
//   facet_pcl_baselines DATASET OUT [--pipelines organized,euclidean,...] [--repeat 3]
//
// DATASET is a dataset folder (intrinsics.yaml, depth/*.png in uint16 mm). Each depth frame
// becomes an organized pcl::PointCloud<pcl::PointXYZ> (metres, NaN where the depth is 0); then
// every pipeline runs on it, one thread:
//   organized    IntegralImageNormalEstimation + OrganizedMultiPlaneSegmentation (Euclidean
//                plane comparator, refined) + OrganizedConnectedComponentSegmentation with the
//                EuclideanClusterComparator on the points of no plane (PCL's organized
//                segmentation demo; --org-remove largest keeps all planes but the largest);
//   euclidean    SACSegmentation (RANSAC plane) on the valid points, its inliers removed, then
//                EuclideanClusterExtraction (k-d tree) on the rest (PCL's cluster extraction
//                tutorial, with the dominant plane only);
//   lccp         SupervoxelClustering + LCCPSegmentation (parameters of PCL's LCCP example plus
//                its sanity criterion, k-factor 0) on all valid points; the segments lying
//                mostly on the RANSAC plane above are background;
//   lccp_before  the same, with the plane's inliers removed before the supervoxels (faster);
//   lccp_k1      as lccp with k-factor 1 (extended convexity) and no sanity criterion.
// Writes OUT/<pipeline>/labels/<stem>.png (uint16, 0 = background, 1..N segments),
// OUT/timing.csv (one row per pipeline and frame) and OUT/timing.json (median and p95 per
// pipeline). Times are steady_clock around the pipeline alone: from the organized cloud to the
// label image in memory, without PNG decoding or writing. With --repeat R each frame's time is
// the median of R runs. All parameters are options (see --help).
#include <fmt/core.h>
#include <fmt/os.h>
#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/common/angles.h>
#include <pcl/features/integral_image_normal.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/euclidean_cluster_comparator.h>
#include <pcl/segmentation/euclidean_plane_coefficient_comparator.h>
#include <pcl/segmentation/extract_clusters.h>
#include <pcl/segmentation/lccp_segmentation.h>
#include <pcl/segmentation/organized_connected_component_segmentation.h>
#include <pcl/segmentation/organized_multi_plane_segmentation.h>
#include <pcl/segmentation/sac_segmentation.h>
#include <pcl/segmentation/supervoxel_clustering.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <opencv2/core.hpp>
#include <set>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "facet/types/frame.hpp"
#include "io/frame_listing.hpp"
#include "io/intrinsics_file.hpp"
#include "io/png_files.hpp"

namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

struct Params {
  // organized
  float org_depth_change = 0.02f;    // IntegralImageNormalEstimation max depth change factor
  float org_smoothing = 20.0f;       // IntegralImageNormalEstimation normal smoothing size
  unsigned org_min_inliers = 10000;  // OrganizedMultiPlaneSegmentation
  double org_angle_deg = 2.0;
  double org_plane_distance = 0.02;
  std::string org_remove = "all";  // which planes become background: all, largest
  float org_cluster_distance = 0.01f;
  std::size_t org_min_cluster = 1000;
  // euclidean (its plane is also the one lccp removes)
  double sac_distance = 0.01;
  int sac_iterations = 1000;
  double cluster_tolerance = 0.01;
  int cluster_min = 50;
  // lccp
  float voxel = 0.0075f;
  float seed = 0.03f;
  float color_importance = 0.0f;
  float spatial_importance = 1.0f;
  float normal_importance = 4.0f;
  float concavity_deg = 10.0f;
  float smoothness = 0.1f;
  std::uint32_t min_segment = 3;  // supervoxels (the example: 0)
  bool sanity = true;             // LCCP sanity criterion for k-factor 0 (the example's -sc)
  bool sanity_k1 = false;         // the same for k-factor 1
  bool camera_transform = false;  // depth-dependent voxel grid (the example's -tvoxel)
  bool refine = false;            // supervoxel refinement (the example's -refine)
  double lccp_plane_share = 0.5;  // share of plane inliers that makes a segment background
};

// A segmentation result: one segment id per pixel, 0 = background (any ids, made consecutive
// when written).
using PixelLabels = std::vector<std::uint32_t>;

Cloud::Ptr to_cloud(const cv::Mat& depth_mm, const facet::CameraIntrinsics& camera) {
  auto cloud = std::make_shared<Cloud>(static_cast<std::uint32_t>(depth_mm.cols),
                                       static_cast<std::uint32_t>(depth_mm.rows));
  cloud->is_dense = false;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const auto fx = static_cast<float>(camera.fx);
  const auto fy = static_cast<float>(camera.fy);
  const auto cx = static_cast<float>(camera.cx);
  const auto cy = static_cast<float>(camera.cy);
  for (int v = 0; v < depth_mm.rows; ++v) {
    const auto* row = depth_mm.ptr<std::uint16_t>(v);
    for (int u = 0; u < depth_mm.cols; ++u) {
      pcl::PointXYZ& p = cloud->at(u, v);
      if (row[u] == 0) {
        p.x = p.y = p.z = nan;
        continue;
      }
      const float z = static_cast<float>(row[u]) * 0.001f;
      p.x = (static_cast<float>(u) - cx) * z / fx;
      p.y = (static_cast<float>(v) - cy) * z / fy;
      p.z = z;
    }
  }
  return cloud;
}

// The valid (finite) points of an organized cloud as a dense cloud, with their pixel indices.
struct DenseCloud {
  Cloud::Ptr cloud;
  std::vector<int> pixel;
};

DenseCloud valid_points(const Cloud& organized) {
  DenseCloud dense{std::make_shared<Cloud>(), {}};
  dense.cloud->reserve(organized.size());
  dense.pixel.reserve(organized.size());
  for (std::size_t i = 0; i < organized.size(); ++i) {
    if (!std::isfinite(organized[i].z)) continue;
    dense.cloud->push_back(organized[i]);
    dense.pixel.push_back(static_cast<int>(i));
  }
  return dense;
}

// RANSAC plane on a dense cloud; returns its inlier indices (into that cloud).
pcl::PointIndices dominant_plane(const Cloud::Ptr& cloud, const Params& params) {
  pcl::SACSegmentation<pcl::PointXYZ> sac;
  sac.setOptimizeCoefficients(true);
  sac.setModelType(pcl::SACMODEL_PLANE);
  sac.setMethodType(pcl::SAC_RANSAC);
  sac.setDistanceThreshold(params.sac_distance);
  sac.setMaxIterations(params.sac_iterations);
  sac.setInputCloud(cloud);
  pcl::PointIndices inliers;
  pcl::ModelCoefficients coefficients;
  sac.segment(inliers, coefficients);
  return inliers;
}

PixelLabels organized_pipeline(const Cloud::Ptr& cloud, const Params& params) {
  auto normals = std::make_shared<pcl::PointCloud<pcl::Normal>>();
  pcl::IntegralImageNormalEstimation<pcl::PointXYZ, pcl::Normal> ne;
  ne.setNormalEstimationMethod(ne.COVARIANCE_MATRIX);
  ne.setMaxDepthChangeFactor(params.org_depth_change);
  ne.setNormalSmoothingSize(params.org_smoothing);
  ne.setInputCloud(cloud);
  ne.compute(*normals);

  pcl::OrganizedMultiPlaneSegmentation<pcl::PointXYZ, pcl::Normal, pcl::Label> mps;
  mps.setMinInliers(params.org_min_inliers);
  mps.setAngularThreshold(pcl::deg2rad(params.org_angle_deg));
  mps.setDistanceThreshold(params.org_plane_distance);
  mps.setComparator(
      std::make_shared<pcl::EuclideanPlaneCoefficientComparator<pcl::PointXYZ, pcl::Normal>>());
  mps.setInputNormals(normals);
  mps.setInputCloud(cloud);
  std::vector<pcl::PlanarRegion<pcl::PointXYZ>,
              Eigen::aligned_allocator<pcl::PlanarRegion<pcl::PointXYZ>>>
      regions;
  std::vector<pcl::ModelCoefficients> coefficients;
  std::vector<pcl::PointIndices> inliers;
  std::vector<pcl::PointIndices> label_indices;
  std::vector<pcl::PointIndices> boundaries;
  auto plane_labels = std::make_shared<pcl::PointCloud<pcl::Label>>();
  mps.segmentAndRefine(regions, coefficients, inliers, plane_labels, label_indices, boundaries);

  // The labels of the planes that become background: every plane found, or the largest only.
  std::set<std::uint32_t> background;
  std::size_t largest = 0;
  for (const pcl::PointIndices& plane : inliers) {
    if (plane.indices.empty()) continue;
    const std::uint32_t label = (*plane_labels)[static_cast<std::size_t>(plane.indices[0])].label;
    const std::size_t size = label_indices[label].indices.size();
    if (params.org_remove == "all") {
      background.insert(label);
    } else if (size > largest) {
      largest = size;
      background = {label};
    }
  }
  // A mask cloud for the cluster comparator: 0 = plane (background), 1 = anything else. In PCL
  // 1.13 EuclideanClusterComparator joins two points only when both labels are in its
  // "exclude" set (despite the name), so the set holds the label of the points to cluster.
  auto mask = std::make_shared<pcl::PointCloud<pcl::Label>>(cloud->width, cloud->height);
  for (std::size_t i = 0; i < cloud->size(); ++i) {
    const std::uint32_t label = (*plane_labels)[i].label;
    (*mask)[i].label = background.count(label) != 0 ? 0u : 1u;
  }
  auto comparator = std::make_shared<pcl::EuclideanClusterComparator<pcl::PointXYZ, pcl::Label>>();
  comparator->setInputCloud(cloud);
  comparator->setLabels(mask);
  comparator->setExcludeLabels(std::make_shared<std::set<std::uint32_t>>(std::set{1u}));
  comparator->setDistanceThreshold(params.org_cluster_distance, false);
  pcl::OrganizedConnectedComponentSegmentation<pcl::PointXYZ, pcl::Label> components(comparator);
  components.setInputCloud(cloud);
  pcl::PointCloud<pcl::Label> cluster_labels;
  std::vector<pcl::PointIndices> clusters;
  components.segment(cluster_labels, clusters);

  PixelLabels out(cloud->size(), 0);
  std::uint32_t next = 1;
  for (const pcl::PointIndices& cluster : clusters) {
    if (cluster.indices.size() < params.org_min_cluster) continue;
    // Plane points are never joined to anything, but a large plane cannot be a singleton
    // cluster; skip clusters of plane points all the same.
    if ((*mask)[static_cast<std::size_t>(cluster.indices[0])].label == 0) continue;
    for (const int i : cluster.indices)
      out[static_cast<std::size_t>(i)] = next;
    ++next;
  }
  return out;
}

PixelLabels euclidean_pipeline(const Cloud::Ptr& cloud, const Params& params) {
  const DenseCloud dense = valid_points(*cloud);
  const pcl::PointIndices plane = dominant_plane(dense.cloud, params);
  std::vector<char> on_plane(dense.cloud->size(), 0);
  for (const int i : plane.indices)
    on_plane[static_cast<std::size_t>(i)] = 1;
  auto rest = std::make_shared<pcl::Indices>();
  rest->reserve(dense.cloud->size() - plane.indices.size());
  for (std::size_t i = 0; i < on_plane.size(); ++i)
    if (on_plane[i] == 0) rest->push_back(static_cast<int>(i));

  auto tree = std::make_shared<pcl::search::KdTree<pcl::PointXYZ>>();
  pcl::EuclideanClusterExtraction<pcl::PointXYZ> extraction;
  extraction.setClusterTolerance(params.cluster_tolerance);
  extraction.setMinClusterSize(params.cluster_min);
  extraction.setMaxClusterSize(std::numeric_limits<int>::max());
  extraction.setSearchMethod(tree);
  extraction.setInputCloud(dense.cloud);
  extraction.setIndices(rest);
  std::vector<pcl::PointIndices> clusters;
  extraction.extract(clusters);

  PixelLabels out(cloud->size(), 0);
  std::uint32_t next = 1;
  for (const pcl::PointIndices& cluster : clusters) {
    for (const int i : cluster.indices)
      out[static_cast<std::size_t>(dense.pixel[static_cast<std::size_t>(i)])] = next;
    ++next;
  }
  return out;
}

PixelLabels lccp_pipeline(const Cloud::Ptr& cloud, const Params& params, std::uint32_t k_factor,
                          bool plane_before) {
  const DenseCloud dense = valid_points(*cloud);
  const pcl::PointIndices plane = dominant_plane(dense.cloud, params);
  std::vector<char> on_plane(dense.cloud->size(), 0);
  for (const int i : plane.indices)
    on_plane[static_cast<std::size_t>(i)] = 1;

  // The supervoxels' input: every valid point, or (before) the valid points off the plane.
  Cloud::Ptr input = dense.cloud;
  std::vector<int> pixel = dense.pixel;
  if (plane_before) {
    input = std::make_shared<Cloud>();
    input->reserve(dense.cloud->size());
    pixel.clear();
    for (std::size_t i = 0; i < on_plane.size(); ++i) {
      if (on_plane[i] != 0) continue;
      input->push_back((*dense.cloud)[i]);
      pixel.push_back(dense.pixel[i]);
    }
  }

  pcl::SupervoxelClustering<pcl::PointXYZ> supervoxels(params.voxel, params.seed);
  supervoxels.setUseSingleCameraTransform(params.camera_transform);
  supervoxels.setInputCloud(input);
  supervoxels.setColorImportance(params.color_importance);
  supervoxels.setSpatialImportance(params.spatial_importance);
  supervoxels.setNormalImportance(params.normal_importance);
  std::map<std::uint32_t, pcl::Supervoxel<pcl::PointXYZ>::Ptr> clusters;
  supervoxels.extract(clusters);
  if (params.refine) supervoxels.refineSupervoxels(2, clusters);
  std::multimap<std::uint32_t, std::uint32_t> adjacency;
  supervoxels.getSupervoxelAdjacency(adjacency);

  pcl::LCCPSegmentation<pcl::PointXYZ> lccp;
  lccp.setConcavityToleranceThreshold(params.concavity_deg);
  lccp.setSanityCheck(k_factor == 0 ? params.sanity : params.sanity_k1);
  lccp.setSmoothnessCheck(true, params.voxel, params.seed, params.smoothness);
  lccp.setKFactor(k_factor);
  lccp.setInputSupervoxels(clusters, adjacency);
  lccp.setMinSegmentSize(params.min_segment);
  lccp.segment();
  const pcl::PointCloud<pcl::PointXYZL>::Ptr labeled = supervoxels.getLabeledCloud();
  lccp.relabelCloud(*labeled);

  PixelLabels out(cloud->size(), 0);
  for (std::size_t i = 0; i < labeled->size(); ++i) {
    // Supervoxel label 0 is "no supervoxel"; shift the segment labels so that 0 stays free.
    if ((*labeled)[i].label == 0) continue;
    out[static_cast<std::size_t>(pixel[i])] = (*labeled)[i].label + 1;
  }
  if (!plane_before) {
    // Background: every segment of which at least lccp_plane_share of the points are inliers of
    // the RANSAC plane (the table, in pieces where objects cut it).
    std::unordered_map<std::uint32_t, std::pair<std::size_t, std::size_t>> counts;
    for (std::size_t i = 0; i < dense.pixel.size(); ++i) {
      const std::uint32_t label = out[static_cast<std::size_t>(dense.pixel[i])];
      if (label == 0) continue;
      auto& [total, inliers] = counts[label];
      ++total;
      inliers += static_cast<std::size_t>(on_plane[i]);
    }
    for (std::uint32_t& label : out) {
      if (label == 0) continue;
      const auto& [total, inliers] = counts[label];
      if (static_cast<double>(inliers) >= params.lccp_plane_share * static_cast<double>(total))
        label = 0;
    }
  }
  return out;
}

// Label image with consecutive ids 1..N in raster order of first appearance.
cv::Mat to_label_image(const PixelLabels& labels, int width, int height, std::size_t& segments) {
  cv::Mat image(height, width, CV_16UC1, cv::Scalar(0));
  std::unordered_map<std::uint32_t, std::uint16_t> ids;
  auto* pixels = image.ptr<std::uint16_t>(0);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] == 0) continue;
    auto [it, added] = ids.try_emplace(labels[i], static_cast<std::uint16_t>(ids.size() + 1));
    pixels[i] = it->second;
  }
  segments = ids.size();
  return image;
}

double percentile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  // Nearest rank.
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(values.size())));
  return values[std::clamp<std::size_t>(rank, 1, values.size()) - 1];
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

struct Pipeline {
  std::string name;
  std::function<PixelLabels(const Cloud::Ptr&)> run;
  std::vector<double> ms;  // per frame
  std::vector<std::size_t> segments;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Stock PCL segmentation pipelines on a dataset: label images and timing"};
  std::string dataset;
  std::string out_dir;
  std::string selection = "organized,euclidean,lccp,lccp_before,lccp_k1";
  int max_frames = 0;
  int repeat = 1;
  Params params;
  app.add_option("dataset", dataset, "dataset folder (intrinsics.yaml, depth/*.png)")->required();
  app.add_option("out", out_dir, "output folder")->required();
  app.add_option("--pipelines", selection,
                 "comma-separated: organized, euclidean, lccp, lccp_before, lccp_k1")
      ->capture_default_str();
  app.add_option("--frames", max_frames, "first N frames only (0 = all)")->capture_default_str();
  app.add_option("--repeat", repeat, "runs per frame and pipeline; the frame's time is the median")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--org-depth-change", params.org_depth_change)->capture_default_str();
  app.add_option("--org-smoothing", params.org_smoothing)->capture_default_str();
  app.add_option("--org-min-inliers", params.org_min_inliers)->capture_default_str();
  app.add_option("--org-angle", params.org_angle_deg, "degrees")->capture_default_str();
  app.add_option("--org-plane-distance", params.org_plane_distance, "m")->capture_default_str();
  app.add_option("--org-remove", params.org_remove, "planes made background")
      ->capture_default_str()
      ->check(CLI::IsMember({"all", "largest"}));
  app.add_option("--org-cluster-distance", params.org_cluster_distance, "m")->capture_default_str();
  app.add_option("--org-min-cluster", params.org_min_cluster, "points")->capture_default_str();
  app.add_option("--sac-distance", params.sac_distance, "m")->capture_default_str();
  app.add_option("--sac-iterations", params.sac_iterations)->capture_default_str();
  app.add_option("--cluster-tolerance", params.cluster_tolerance, "m")->capture_default_str();
  app.add_option("--cluster-min", params.cluster_min, "points")->capture_default_str();
  app.add_option("--voxel", params.voxel, "m")->capture_default_str();
  app.add_option("--seed", params.seed, "m")->capture_default_str();
  app.add_option("--color-importance", params.color_importance)->capture_default_str();
  app.add_option("--spatial-importance", params.spatial_importance)->capture_default_str();
  app.add_option("--normal-importance", params.normal_importance)->capture_default_str();
  app.add_option("--concavity", params.concavity_deg, "degrees")->capture_default_str();
  app.add_option("--smoothness", params.smoothness)->capture_default_str();
  app.add_option("--min-segment", params.min_segment, "supervoxels")->capture_default_str();
  app.add_flag_callback(
      "--no-sanity", [&] { params.sanity = false; },
      "lccp, lccp_before: without LCCP's sanity criterion");
  app.add_flag("--sanity-k1", params.sanity_k1, "lccp_k1: with LCCP's sanity criterion");
  app.add_flag("--camera-transform", params.camera_transform,
               "supervoxels: depth-dependent voxel grid");
  app.add_flag("--refine", params.refine, "supervoxels: refine them (2 iterations)");
  app.add_option("--lccp-plane-share", params.lccp_plane_share)->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  try {
    namespace fs = std::filesystem;
    const facet::io::FrameListing listing = facet::io::list_frames(dataset);
    const facet::CameraIntrinsics camera =
        facet::io::read_intrinsics(listing.root / "intrinsics.yaml");

    std::vector<Pipeline> all;
    all.push_back(
        {"organized", [&](const Cloud::Ptr& c) { return organized_pipeline(c, params); }, {}, {}});
    all.push_back(
        {"euclidean", [&](const Cloud::Ptr& c) { return euclidean_pipeline(c, params); }, {}, {}});
    all.push_back(
        {"lccp", [&](const Cloud::Ptr& c) { return lccp_pipeline(c, params, 0, false); }, {}, {}});
    all.push_back({"lccp_before",
                   [&](const Cloud::Ptr& c) { return lccp_pipeline(c, params, 0, true); },
                   {},
                   {}});
    all.push_back({"lccp_k1",
                   [&](const Cloud::Ptr& c) { return lccp_pipeline(c, params, 1, false); },
                   {},
                   {}});
    std::vector<Pipeline> pipelines;
    std::stringstream names(selection);
    for (std::string name; std::getline(names, name, ',');) {
      const auto it =
          std::find_if(all.begin(), all.end(), [&](const Pipeline& p) { return p.name == name; });
      if (it == all.end()) throw std::runtime_error("unknown pipeline '" + name + "'");
      pipelines.push_back(*it);
    }
    for (const Pipeline& p : pipelines)
      fs::create_directories(fs::path(out_dir) / p.name / "labels");

    std::vector<std::string> stems;
    std::size_t frame_count = listing.depth_files.size();
    if (max_frames > 0) frame_count = std::min(frame_count, static_cast<std::size_t>(max_frames));
    for (std::size_t f = 0; f < frame_count; ++f) {
      const fs::path& file = listing.depth_files[f];
      const std::string stem = file.stem().string();
      stems.push_back(stem);
      const cv::Mat depth = facet::io::read_depth_png(file, camera);
      const Cloud::Ptr cloud = to_cloud(depth, camera);
      // Pipelines alternate within a frame so that a change of machine load hits all of them.
      for (Pipeline& p : pipelines) {
        std::vector<double> runs;
        PixelLabels labels;
        for (int r = 0; r < repeat; ++r) {
          const auto start = std::chrono::steady_clock::now();
          labels = p.run(cloud);
          const auto stop = std::chrono::steady_clock::now();
          runs.push_back(std::chrono::duration<double, std::milli>(stop - start).count());
        }
        std::size_t segments = 0;
        const cv::Mat image = to_label_image(labels, depth.cols, depth.rows, segments);
        facet::io::write_png(fs::path(out_dir) / p.name / "labels" / (stem + ".png"), image);
        p.ms.push_back(median(runs));
        p.segments.push_back(segments);
      }
      std::cerr << fmt::format("{:>3}/{} {}", f + 1, frame_count, stem);
      for (const Pipeline& p : pipelines)
        std::cerr << fmt::format("  {} {:.1f} ms ({} segs)", p.name, p.ms.back(),
                                 p.segments.back());
      std::cerr << '\n';
    }

    auto csv = fmt::output_file((fs::path(out_dir) / "timing.csv").string());
    csv.print("pipeline,frame,ms,segments\n");
    for (const Pipeline& p : pipelines)
      for (std::size_t f = 0; f < stems.size(); ++f)
        csv.print("{},{},{:.3f},{}\n", p.name, stems[f], p.ms[f], p.segments[f]);
    csv.close();

    auto json = fmt::output_file((fs::path(out_dir) / "timing.json").string());
    json.print("{{\n  \"frames\": {},\n  \"repeat\": {},\n  \"pipelines\": {{\n", stems.size(),
               repeat);
    fmt::print("{:<10} {:>10} {:>10} {:>10}\n", "pipeline", "median ms", "p95 ms", "segments");
    for (std::size_t i = 0; i < pipelines.size(); ++i) {
      const Pipeline& p = pipelines[i];
      std::size_t total_segments = 0;
      for (const std::size_t s : p.segments)
        total_segments += s;
      json.print("    \"{}\": {{\"median_ms\": {:.3f}, \"p95_ms\": {:.3f}, \"segments\": {}}}{}\n",
                 p.name, median(p.ms), percentile(p.ms, 0.95), total_segments,
                 i + 1 < pipelines.size() ? "," : "");
      fmt::print("{:<10} {:>10.2f} {:>10.2f} {:>10}\n", p.name, median(p.ms),
                 percentile(p.ms, 0.95), total_segments);
    }
    json.print("  }}\n}}\n");
    json.close();
  } catch (const std::exception& e) {
    std::cerr << "facet_pcl_baselines: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
