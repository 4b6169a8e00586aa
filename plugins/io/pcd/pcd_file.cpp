#include "pcd/pcd_file.hpp"

#include <pcl/PCLPointCloud2.h>
#include <pcl/io/pcd_io.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "facet/error.hpp"
#include "pcd/pcd_header.hpp"

namespace facet::pcd {
namespace {

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
  // PCL trusts the header; an inconsistent one must not reach it (pcd/pcd_header.hpp).
  check_pcd_file(file);
  pcl::PCLPointCloud2 cloud;
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
  int version = 0;
  int status = 0;
  std::string reported;
  // PCL writes why it cannot read a file to standard error only. It is left there: taking the
  // process's stderr for the duration of a read would also swallow what other threads write
  // meanwhile (the stall watchdog's warnings among them).
  try {
    status = pcl::PCDReader().read(file.string(), cloud, origin, orientation, version);
  } catch (const std::exception& e) {
    status = -1;
    reported = e.what();
  }
  if (status < 0) {
    throw StageError("cannot read PCD file '" + file.string() + "': " +
                     (reported.empty() ? "PCL's reader failed (error " + std::to_string(status) +
                                             "; its reason is on standard error)"
                                       : "PCL reported: " + reported));
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
