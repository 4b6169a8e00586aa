// The depth PNG reader on untrusted bytes: the codec's header, integrity check and decoder in
// memory, then the path a dataset frame takes from its file (size against the intrinsics, the
// general decoder for what the codec leaves to it). An exception is a refusal, which is what bad
// bytes should get; a crash, a hang, a huge allocation or a sanitizer report is a finding.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <span>

#include "io/png_codec.hpp"
#include "io/png_files.hpp"
#include "scratch_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace png = facet::io::png;
  const std::span<const std::uint8_t> bytes(data, size);
  try {
    if (png::has_signature(bytes)) (void)png::read_info(bytes);
  } catch (const std::exception&) {
  }
  try {
    png::check_integrity(bytes);
  } catch (const std::exception&) {
  }
  try {
    (void)png::decode(bytes);
  } catch (const std::exception&) {
  }
  // A Kinect-sized camera, as the bundled datasets declare.
  const facet::CameraIntrinsics camera{525.0, 525.0, 319.5, 239.5, 640, 480};
  const auto file = facet::fuzz::scratch().write("depth.png", bytes);
  try {
    (void)facet::io::read_depth_png(file, camera);
  } catch (const std::exception&) {
  }
  try {
    (void)facet::io::read_label_png(file, camera);
  } catch (const std::exception&) {
  }
  return 0;
}
