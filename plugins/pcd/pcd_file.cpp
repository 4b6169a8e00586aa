#include "pcd/pcd_file.hpp"

#include <pcl/PCLPointCloud2.h>
#include <pcl/io/pcd_io.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <string>

#include "facet/error.hpp"

namespace facet::pcd {
namespace {

// PCL reports why it cannot read a file only on stderr (PCL_ERROR). While a file is being read,
// stderr goes to a temporary file; afterwards the text is handed to the caller (to put into the
// error) and, when the read succeeded, written back to stderr so that nothing is lost.
class StderrCapture {
 public:
  StderrCapture() {
    std::fflush(stderr);
    file_ = std::tmpfile();
    if (file_ == nullptr) return;
    saved_ = ::dup(STDERR_FILENO);
    if (saved_ < 0 || ::dup2(::fileno(file_), STDERR_FILENO) < 0) restore();
  }
  ~StderrCapture() { restore(); }
  StderrCapture(const StderrCapture&) = delete;
  StderrCapture& operator=(const StderrCapture&) = delete;

  // Stops capturing and returns what was written meanwhile.
  std::string finish() {
    std::string text;
    if (file_ == nullptr) return text;
    std::fflush(stderr);
    restore_fd();
    std::rewind(file_);
    char buffer[4096];
    std::size_t got = 0;
    while ((got = std::fread(buffer, 1, sizeof(buffer), file_)) > 0)
      text.append(buffer, got);
    restore();
    return text;
  }

 private:
  void restore_fd() {
    if (saved_ >= 0) {
      ::dup2(saved_, STDERR_FILENO);
      ::close(saved_);
      saved_ = -1;
    }
  }
  void restore() {
    std::fflush(stderr);
    restore_fd();
    if (file_ != nullptr) {
      std::fclose(file_);
      file_ = nullptr;
    }
  }

  std::FILE* file_ = nullptr;
  int saved_ = -1;
};

// PCL's messages end with newlines and carry terminal colour codes; one line without them reads
// better inside an error message.
std::string one_line(const std::string& text) {
  std::string line;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\x1b') {  // ESC [ ... m
      while (i < text.size() && text[i] != 'm')
        ++i;
      continue;
    }
    if (text[i] == '\n' || text[i] == '\r') {
      if (!line.empty() && line.back() != ' ') line += ' ';
      continue;
    }
    line += text[i];
  }
  while (!line.empty() && line.back() == ' ')
    line.pop_back();
  return line;
}

const pcl::PCLPointField* find_field(const pcl::PCLPointCloud2& cloud, const char* name) {
  for (const auto& field : cloud.fields) {
    if (field.name == name) return &field;
  }
  return nullptr;
}

double read_value(const std::uint8_t* data, std::uint8_t datatype) {
  switch (datatype) {
    case pcl::PCLPointField::INT8: {
      std::int8_t v;
      std::memcpy(&v, data, sizeof(v));
      return v;
    }
    case pcl::PCLPointField::UINT8:
      return *data;
    case pcl::PCLPointField::INT16: {
      std::int16_t v;
      std::memcpy(&v, data, sizeof(v));
      return v;
    }
    case pcl::PCLPointField::UINT16: {
      std::uint16_t v;
      std::memcpy(&v, data, sizeof(v));
      return v;
    }
    case pcl::PCLPointField::INT32: {
      std::int32_t v;
      std::memcpy(&v, data, sizeof(v));
      return v;
    }
    case pcl::PCLPointField::UINT32: {
      std::uint32_t v;
      std::memcpy(&v, data, sizeof(v));
      return v;
    }
    case pcl::PCLPointField::FLOAT32: {
      float v;
      std::memcpy(&v, data, sizeof(v));
      return v;
    }
    case pcl::PCLPointField::FLOAT64: {
      double v;
      std::memcpy(&v, data, sizeof(v));
      return v;
    }
    default:
      return std::numeric_limits<double>::quiet_NaN();
  }
}

}  // namespace

CloudPoints read_pcd(const std::filesystem::path& file) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) {
    throw StageError("PCD file '" + file.string() + "' not found");
  }
  pcl::PCLPointCloud2 cloud;
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
  int version = 0;
  int status = 0;
  std::string reported;
  {
    StderrCapture capture;
    try {
      // PCL 1.13 crashes in read() on a file whose header has no fields or no points (it
      // reports "No points to read" and returns success from readHeader); such a file is
      // refused after readHeader.
      pcl::PCDReader reader;
      int data_type = 0;
      unsigned int data_index = 0;
      status = reader.readHeader(file.string(), cloud, origin, orientation, version, data_type,
                                 data_index);
      if (status >= 0 && (cloud.fields.empty() || cloud.width == 0 || cloud.height == 0)) {
        status = -1;
      } else if (status >= 0) {
        status = reader.read(file.string(), cloud, origin, orientation, version);
      }
    } catch (const std::exception& e) {
      status = -1;
      reported = e.what();
    }
    const std::string text = capture.finish();
    if (status >= 0 && !text.empty()) std::fputs(text.c_str(), stderr);
    if (reported.empty()) reported = one_line(text);
  }
  if (status < 0) {
    throw StageError("cannot read PCD file '" + file.string() + "': PCL reported: " +
                     (reported.empty()
                          ? "no fields or no points (error " + std::to_string(status) + ")"
                          : reported));
  }

  const pcl::PCLPointField* fields[3] = {find_field(cloud, "x"), find_field(cloud, "y"),
                                         find_field(cloud, "z")};
  for (int axis = 0; axis < 3; ++axis) {
    const pcl::PCLPointField* field = fields[axis];
    if (field == nullptr || (field->datatype != pcl::PCLPointField::FLOAT32 &&
                             field->datatype != pcl::PCLPointField::FLOAT64)) {
      throw StageError("PCD file '" + file.string() + "' has no float field '" +
                       std::string(1, static_cast<char>('x' + axis)) +
                       "' (io.pcd needs x, y, z in metres)");
    }
  }
  const pcl::PCLPointField* label = find_field(cloud, "label");

  CloudPoints points;
  points.width = static_cast<int>(cloud.width);
  points.height = static_cast<int>(cloud.height);
  const std::size_t count = static_cast<std::size_t>(cloud.width) * cloud.height;
  if (cloud.data.size() < count * cloud.point_step) {
    throw StageError("PCD file '" + file.string() + "' holds fewer points than its header says");
  }
  points.x.resize(count);
  points.y.resize(count);
  points.z.resize(count);
  if (label != nullptr) points.labels.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint8_t* point = cloud.data.data() + i * cloud.point_step;
    points.x[i] = static_cast<float>(read_value(point + fields[0]->offset, fields[0]->datatype));
    points.y[i] = static_cast<float>(read_value(point + fields[1]->offset, fields[1]->datatype));
    points.z[i] = static_cast<float>(read_value(point + fields[2]->offset, fields[2]->datatype));
    if (label != nullptr) {
      const double value = read_value(point + label->offset, label->datatype);
      points.labels[i] =
          std::isfinite(value) && value > 0.0 ? static_cast<std::uint32_t>(value) : 0U;
    }
  }
  return points;
}

}  // namespace facet::pcd
