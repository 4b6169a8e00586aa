// Segments one depth image with a graph file, as a perception node would: the program reads the
// image itself, hands it to facet::Pipeline and prints the objects it gets back.
//
//   segment_frame GRAPH DEPTH_PNG [fx fy cx cy]     (default intrinsics: 525 525 319.5 239.5)

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <facet/pipeline.hpp>
#include <facet/types/geometry.hpp>
#include <facet/types/images.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>

int main(int argc, char** argv) {
  if (argc != 3 && argc != 7) {
    std::fprintf(stderr, "usage: %s GRAPH DEPTH_PNG [fx fy cx cy]\n", argv[0]);
    return 2;
  }
  facet::DepthImage depth;
  depth.depth = cv::imread(argv[2], cv::IMREAD_UNCHANGED);
  if (depth.depth.empty() || depth.depth.type() != CV_16UC1) {
    std::fprintf(stderr, "%s: not a 16-bit depth PNG in millimetres\n", argv[2]);
    return 1;
  }
  const auto number = [&](int i) { return std::strtod(argv[i], nullptr); };
  depth.camera = argc == 7 ? facet::CameraIntrinsics{number(3), number(4),        number(5),
                                                     number(6), depth.depth.cols, depth.depth.rows}
                           : facet::CameraIntrinsics{
                                 525.0, 525.0, 319.5, 239.5, depth.depth.cols, depth.depth.rows};
  try {
    facet::Pipeline pipeline(argv[1]);
    const facet::FrameResult out = pipeline.process({{"depth", facet::Packet::make(depth)}});
    const auto* objects = out.outputs.at("objects").get_if<facet::ObjectList>();
    if (objects == nullptr) {
      std::printf("no objects\n");
      return 0;
    }
    double total_ms = 0.0;
    for (const auto& timing : out.timings)
      total_ms += timing.ms;
    std::printf("%zu objects in %.1f ms\n", objects->objects.size(), total_ms);
    for (const auto& object : objects->objects) {
      const auto& c = object.centroid_m;
      std::printf("object %d: %lld px, centroid (%.3f, %.3f, %.3f) m, grasp %s\n", object.id,
                  static_cast<long long>(object.pixel_count), c.x(), c.y(), c.z(),
                  std::string(facet::to_string(object.grasp)).c_str());
    }
  } catch (const facet::GraphError& error) {
    std::fprintf(stderr, "%s", error.what());
    return 3;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return 1;
  }
  return 0;
}
