#pragma once
// Input that io.frames does not read but another source stage does: PCD point clouds (io.pcd)
// and OpenNI2 recordings (io.openni2). A user who points `input=` at one should learn which
// stage reads it and how to run it, not only that it is no dataset folder.

#include <filesystem>
#include <string>
#include <vector>

namespace facet::io {

enum class OtherSource { none, pcd, oni };

// By extension, ignoring case: a.pcd, take.ONI.
OtherSource other_source_of_file(const std::filesystem::path& file);

// The kind most of `files` have, when every one of them is of one other kind; none otherwise
// (or when `files` is empty).
OtherSource other_source_of_files(const std::vector<std::filesystem::path>& files);

// What a folder holds instead of depth PNGs: pcd when it holds *.pcd files, oni when it holds
// *.oni files (and no *.pcd), none otherwise.
OtherSource other_source_in_folder(const std::filesystem::path& folder);

// Whether the path a user gave is one file, or a folder or glob of several.
enum class PathHolds { one_file, several };

// The sentence that names the stage reading `kind` and how to run it on `path`, e.g.
// "'take.oni' is an OpenNI2 recording, which io.frames does not read: ... `facet run
// graphs/live.yaml --param uri=take.oni` ...". Empty for none.
std::string other_source_advice(OtherSource kind, const std::string& path, PathHolds holds);

}  // namespace facet::io
