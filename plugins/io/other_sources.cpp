#include "io/other_sources.hpp"

#include <algorithm>
#include <cctype>
#include <system_error>

namespace fs = std::filesystem;

namespace facet::io {

OtherSource other_source_of_file(const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".pcd") return OtherSource::pcd;
  if (ext == ".oni") return OtherSource::oni;
  return OtherSource::none;
}

OtherSource other_source_of_files(const std::vector<fs::path>& files) {
  if (files.empty()) return OtherSource::none;
  const OtherSource first = other_source_of_file(files.front());
  const bool all_alike = std::all_of(files.begin(), files.end(), [&](const fs::path& file) {
    return other_source_of_file(file) == first;
  });
  return all_alike ? first : OtherSource::none;
}

OtherSource other_source_in_folder(const fs::path& folder) {
  bool oni = false;
  std::error_code error;
  // Only asked after the folder was found to hold no frames: an unreadable entry simply ends
  // the survey, the caller's own error still stands.
  for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    if (!it->is_regular_file(error)) continue;
    const OtherSource kind = other_source_of_file(it->path());
    if (kind == OtherSource::pcd) return OtherSource::pcd;
    oni = oni || kind == OtherSource::oni;
  }
  return oni ? OtherSource::oni : OtherSource::none;
}

std::string other_source_advice(OtherSource kind, const std::string& path, PathHolds holds) {
  const bool one = holds == PathHolds::one_file;
  switch (kind) {
    case OtherSource::pcd:
      // No shipped graph reads PCD: the advice swaps the one node on the command line.
      return "'" + path + (one ? "' is a PCD point cloud" : "' holds PCD point clouds") +
             ", which io.frames does not read: the source stage io.pcd (plugin facet_pcd, built "
             "where PCL is found; `facet list pcd` shows whether it is here) reads a .pcd file, "
             "a folder or a glob of them. Run the graph on it with `--replace source=io.pcd "
             "--set source.path='" +
             path + "'` (docs/data-formats.md, 'PCD point clouds')";
    case OtherSource::oni:
      // live.yaml is the tabletop chain on io.openni2; its `uri` takes one recording.
      return "'" + path + (one ? "' is an OpenNI2 recording" : "' holds OpenNI2 recordings") +
             ", which io.frames does not read: the source stage io.openni2 (plugin "
             "facet_openni2, built where OpenNI2 is found; `facet list openni2` shows whether "
             "it is here) plays " +
             (one ? "it: `facet run graphs/live.yaml --param uri=" + path + "`"
                  : std::string("one at a time: `facet run graphs/live.yaml --param "
                                "uri=<one of them>.oni`")) +
             " runs the tabletop chain on it (docs/cameras.md)";
    case OtherSource::none:
      break;
  }
  return {};
}

}  // namespace facet::io
