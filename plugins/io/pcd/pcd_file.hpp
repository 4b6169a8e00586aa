#pragma once
// Reading a PCD file with PCL's reader (any PCD data encoding: ascii, binary,
// binary_compressed).

#include <filesystem>

#include "pcd/cloud_images.hpp"

namespace facet::pcd {

// Reads the fields x, y, z (float or double) and, when present, label (any integer type) of a
// PCD file. Throws facet::StageError naming the file when it is missing, when PCL cannot read it
// (with what PCL reported), or when it lacks x, y or z.
CloudPoints read_pcd(const std::filesystem::path& file);

}  // namespace facet::pcd
