#pragma once
// A frame of the bundled mOSD data (data/mosd: 640x480 uint16 mm depth PNGs with the dataset's
// intrinsics.yaml), read by the io plugin's own readers, for tests and benchmarks that need real
// sensor data. Link facet_io_stages.

#include <filesystem>
#include <string>

#include "facet/types/images.hpp"
#include "io/intrinsics_file.hpp"
#include "io/png_files.hpp"

namespace facet::test {

inline DepthImage bundled_mosd_frame(const std::filesystem::path& mosd_dir,
                                     const std::string& stem = "learn0") {
  DepthImage image;
  image.camera = io::read_intrinsics(mosd_dir / "intrinsics.yaml");
  image.depth = io::read_depth_png(mosd_dir / "depth" / (stem + ".png"), image.camera);
  image.frame.stem = stem;
  return image;
}

}  // namespace facet::test
