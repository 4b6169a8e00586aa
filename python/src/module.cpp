// The Python module `facet._facet` (wrapped by python/facet/__init__.py): facet::Pipeline with
// numpy arrays in and out. Arrays are shared, not copied, where the layout allows it: a
// C-contiguous depth array becomes the input image, and label and depth images come back as
// read-only views that keep their packet alive. The GIL is released while a graph runs.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "facet/pipeline.hpp"
#include "facet/types/geometry.hpp"
#include "facet/types/images.hpp"
#include "io/objects_sink.hpp"

namespace py = pybind11;
using namespace py::literals;

namespace facet::python {
namespace {

// Graph params and --set values as the graph file would spell them.
std::string param_text(const py::handle& value) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  return py::str(value).cast<std::string>();
}

PipelineOptions options_from(const py::dict& params, const py::dict& sets,
                             const std::string& variant,
                             const std::vector<std::filesystem::path>& plugin_path,
                             bool run_sinks) {
  PipelineOptions options;
  for (const auto& [name, value] : params)
    options.params[py::str(name).cast<std::string>()] = param_text(value);
  for (const auto& [name, value] : sets)
    options.sets.emplace_back(py::str(name).cast<std::string>(), param_text(value));
  options.variant = variant;
  options.plugin_paths = plugin_path;
  options.run_sinks = run_sinks;
  return options;
}

double finite_number(const py::handle& value, const char* what) {
  double number = 0.0;
  try {
    number = value.cast<double>();
  } catch (const py::cast_error&) {
    throw py::type_error(std::string("intrinsics: ") + what + " must be a number");
  }
  if (!std::isfinite(number)) {
    throw py::value_error(std::string("intrinsics: ") + what + " must be finite");
  }
  return number;
}

// (fx, fy, cx, cy), {"fx": .., "fy": .., "cx": .., "cy": ..} or a 3×3 camera matrix.
CameraIntrinsics intrinsics_from(const py::object& value, int width, int height) {
  CameraIntrinsics camera;
  camera.width = width;
  camera.height = height;
  const char* expected =
      "intrinsics must be (fx, fy, cx, cy), a dict with fx, fy, cx and cy, or a 3x3 camera matrix";
  if (value.is_none()) throw py::value_error(std::string("missing intrinsics: ") + expected);
  if (py::isinstance<py::dict>(value)) {
    const auto dict = value.cast<py::dict>();
    for (const char* key : {"fx", "fy", "cx", "cy"}) {
      if (!dict.contains(key)) {
        throw py::value_error(std::string("intrinsics: the dict has no '") + key + "'; " +
                              expected);
      }
    }
    camera.fx = finite_number(dict["fx"], "fx");
    camera.fy = finite_number(dict["fy"], "fy");
    camera.cx = finite_number(dict["cx"], "cx");
    camera.cy = finite_number(dict["cy"], "cy");
  } else if (py::isinstance<py::array>(value) && value.cast<py::array>().ndim() == 2) {
    const auto matrix = py::array_t<double, py::array::forcecast>(value);
    if (matrix.shape(0) != 3 || matrix.shape(1) != 3) {
      throw py::value_error(std::string("intrinsics: a camera matrix must be 3x3; ") + expected);
    }
    const auto k = matrix.unchecked<2>();
    camera.fx = finite_number(py::float_(k(0, 0)), "fx");
    camera.fy = finite_number(py::float_(k(1, 1)), "fy");
    camera.cx = finite_number(py::float_(k(0, 2)), "cx");
    camera.cy = finite_number(py::float_(k(1, 2)), "cy");
  } else if (py::isinstance<py::sequence>(value) && !py::isinstance<py::str>(value)) {
    const auto items = value.cast<py::sequence>();
    if (items.size() != 4) {
      throw py::value_error("intrinsics: got " + std::to_string(items.size()) + " numbers; " +
                            expected);
    }
    camera.fx = finite_number(items[0], "fx");
    camera.fy = finite_number(items[1], "fy");
    camera.cx = finite_number(items[2], "cx");
    camera.cy = finite_number(items[3], "cy");
  } else {
    throw py::type_error(expected);
  }
  if (camera.fx <= 0.0 || camera.fy <= 0.0) {
    throw py::value_error("intrinsics: fx and fy must be positive focal lengths in pixels");
  }
  return camera;
}

// Keeps a numpy array alive for as long as a packet shares its memory. The packet may be released
// on a thread that does not hold the GIL.
struct ArrayOwner {
  py::object array;
  ~ArrayOwner() {
    py::gil_scoped_acquire gil;
    array = py::object();
  }
};

Packet depth_packet(const py::array& given, const py::object& intrinsics, std::int64_t index,
                    const std::string& stem) {
  const bool millimetres = given.dtype().is(py::dtype::of<std::uint16_t>());
  const bool metres = given.dtype().is(py::dtype::of<float>());
  if (!millimetres && !metres) {
    throw py::type_error("depth must be uint16 (millimetres) or float32 (metres), got " +
                         py::str(given.dtype()).cast<std::string>());
  }
  if (given.ndim() != 2) {
    throw py::value_error("depth must be a 2-D array (height x width), got shape " +
                          py::str(given.attr("shape")).cast<std::string>());
  }
  if (given.shape(0) == 0 || given.shape(1) == 0) {
    throw py::value_error("depth is empty: shape " +
                          py::str(given.attr("shape")).cast<std::string>());
  }
  py::array array = given;
  if (!(given.flags() & py::array::c_style)) {
    PyErr_WarnEx(PyExc_RuntimeWarning,
                 "depth is not C-contiguous (a slice or a transposed view); it was copied", 1);
    array = py::array::ensure(given, py::array::c_style);
  }
  const int height = static_cast<int>(array.shape(0));
  const int width = static_cast<int>(array.shape(1));
  auto owner = std::make_shared<ArrayOwner>();
  owner->array = array;
  auto image = std::shared_ptr<DepthImage>(new DepthImage(), [owner](DepthImage* p) {
    delete p;  // drops the cv::Mat header first, then (with the owner) the numpy array
  });
  image->depth =
      cv::Mat(height, width, millimetres ? CV_16UC1 : CV_32FC1, const_cast<void*>(array.data()),
              static_cast<std::size_t>(array.strides(0)));
  image->camera = intrinsics_from(intrinsics, width, height);
  image->frame.index = index;
  image->frame.stem = stem.empty() ? "frame_" + std::to_string(index) : stem;
  return Packet::share<DepthImage>(std::move(image));
}

// A read-only numpy view of `mat` that keeps `packet` (which owns the pixels) alive.
template <class T>
py::array view_of(const cv::Mat& mat, const Packet& packet) {
  auto* keep = new Packet(packet);
  py::capsule base(keep, [](void* p) { delete static_cast<Packet*>(p); });
  std::vector<py::ssize_t> shape = {mat.rows, mat.cols};
  std::vector<py::ssize_t> strides = {static_cast<py::ssize_t>(mat.step[0]),
                                      static_cast<py::ssize_t>(mat.elemSize())};
  if (mat.channels() > 1) {
    shape.push_back(mat.channels());
    strides.push_back(static_cast<py::ssize_t>(mat.elemSize1()));
  }
  py::array array(py::dtype::of<T>(), shape, strides, mat.data, base);
  // Read-only as pybind11 makes its own read-only views of Eigen matrices: the flag is cleared
  // directly; calling the array's setflags method took longer than making the view.
  py::detail::array_proxy(array.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return array;
}

// dict[key] = value for the dicts built here; a literal key.
void set_item(const py::dict& dict, const char* key, const py::object& value) {
  if (PyDict_SetItemString(dict.ptr(), key, value.ptr()) != 0) throw py::error_already_set();
}

py::list vector_list(const Eigen::Vector3d& v) {
  py::list list(3);
  for (std::size_t i = 0; i < 3; ++i)
    list[i] = py::float_(v[static_cast<Eigen::Index>(i)]);
  return list;
}

py::dict planes_dict(const SupportPlanes& planes) {
  py::list list(planes.planes.size());
  for (std::size_t i = 0; i < planes.planes.size(); ++i) {
    const Plane& plane = planes.planes[i];
    const char* role = plane.role == PlaneRole::table   ? "table"
                       : plane.role == PlaneRole::floor ? "floor"
                                                        : "wall";
    py::dict item;
    set_item(item, "id", py::int_(plane.id));
    set_item(item, "role", py::str(role));
    set_item(item, "normal", vector_list(plane.normal));
    set_item(item, "offset_m", py::float_(plane.offset_m));
    set_item(item, "inliers", py::int_(plane.inliers));
    set_item(item, "rms_m", py::float_(plane.rms_m));
    set_item(item, "horizontal", py::bool_(plane.horizontal));
    list[i] = std::move(item);
  }
  py::list outline(planes.table_outline_m.size());
  for (std::size_t i = 0; i < planes.table_outline_m.size(); ++i)
    outline[i] = vector_list(planes.table_outline_m[i]);
  py::dict out;
  set_item(out, "planes", list);
  set_item(out, "up", vector_list(planes.up));
  set_item(out, "table_id", py::int_(planes.table_id));
  set_item(out, "table_outline_m", outline);
  return out;
}

// The objects as json.loads gives them from the text io.objects writes (the same layout,
// io::write_object), built directly: a program reads what the files hold, without the cost of
// printing the text and parsing it again, which was most of what a call added to the graph's own
// time (docs/performance.md). Numbers are rounded to the text's 9 significant digits; a number
// the text spells without a point or an exponent is an int, a non-finite one None, as in JSON.
class ObjectDicts {
 public:
  void open_object(std::string_view key = {}) { open(key, py::dict()); }
  void open_array(std::string_view key = {}) { open(key, py::list()); }
  void close_object() { open_.pop_back(); }
  void close_array() { open_.pop_back(); }
  void number(std::string_view key, double value) { add(key, json_number(value)); }
  template <class Vector>
  void numbers(std::string_view key, const Vector& values) {
    py::list list(static_cast<std::size_t>(values.size()));
    for (Eigen::Index i = 0; i < values.size(); ++i)
      list[static_cast<std::size_t>(i)] = json_number(values[i]);
    add(key, std::move(list));
  }
  void integer(std::string_view key, long long value) { add(key, py::int_(value)); }
  void string(std::string_view key, std::string_view value) {
    add(key, py::str(value.data(), value.size()));
  }
  void null(std::string_view key) { add(key, py::none()); }
  py::object result() const { return result_; }

 private:
  // The value json.loads gives for the text "%.9g" makes of `value`.
  static py::object json_number(double value) {
    if (!std::isfinite(value)) return py::none();
    char text[32];
    const auto end =
        std::to_chars(text, text + sizeof text, value, std::chars_format::general, 9).ptr;
    if (std::find_if(text, end, [](char c) { return c == '.' || c == 'e'; }) == end) {
      long long whole = 0;
      std::from_chars(text, end, whole);
      return py::int_(whole);
    }
    double rounded = 0.0;
    std::from_chars(text, end, rounded);
    return py::float_(rounded);
  }
  void add(std::string_view key, py::object value) {
    if (open_.empty()) {
      result_ = std::move(value);
    } else if (key.empty()) {
      py::reinterpret_borrow<py::list>(open_.back()).append(value);
    } else {
      py::reinterpret_borrow<py::dict>(open_.back())[py::str(key.data(), key.size())] = value;
    }
  }
  void open(std::string_view key, py::object container) {
    add(key, container);
    open_.push_back(std::move(container));
  }

  py::object result_;
  std::vector<py::object> open_;
};

// A graph output as Python sees it.
py::object to_python(const Packet& packet) {
  if (packet.empty()) return py::none();
  if (const auto* labels = packet.get_if<LabelImage>()) {
    return view_of<std::int32_t>(labels->labels, packet);
  }
  if (const auto* depth = packet.get_if<DepthImage>()) {
    return depth->in_millimetres() ? view_of<std::uint16_t>(depth->depth, packet)
                                   : view_of<float>(depth->depth, packet);
  }
  if (const auto* points = packet.get_if<PointImage>())
    return view_of<float>(points->points, packet);
  if (const auto* normals = packet.get_if<NormalImage>()) {
    return view_of<float>(normals->normals, packet);
  }
  if (const auto* edges = packet.get_if<EdgeImage>()) {
    return py::dict("score"_a = view_of<float>(edges->score, packet),
                    "mask"_a = view_of<std::uint8_t>(edges->mask, packet));
  }
  if (const auto* objects = packet.get_if<ObjectList>()) {
    ObjectDicts out;
    out.open_array();
    for (const ObjectModel& object : objects->objects)
      io::write_object(out, object);
    out.close_array();
    return out.result();
  }
  if (const auto* planes = packet.get_if<SupportPlanes>()) return planes_dict(*planes);
  throw py::type_error("graph output of type " + std::string(packet.type_key()) +
                       " has no Python form; declare an output of another type");
}

class PyPipeline {
 public:
  PyPipeline(const std::filesystem::path& graph, const py::dict& params, const py::dict& sets,
             const std::string& variant, const std::vector<std::filesystem::path>& plugin_path,
             bool run_sinks) {
    const PipelineOptions options = options_from(params, sets, variant, plugin_path, run_sinks);
    py::gil_scoped_release release;
    pipeline_ = std::make_unique<Pipeline>(graph, options);
  }

  // (outputs, timings, warnings, frame index); None at the end of the graph's own stream.
  py::object call(const py::object& depth, const py::object& intrinsics, const std::string& stem,
                  const py::dict& named_inputs) {
    std::map<std::string, Packet, std::less<>> inputs;
    const auto& ports = pipeline_->inputs();
    if (!depth.is_none()) {
      if (ports.size() != 1) {
        throw py::value_error(
            ports.empty() ? "graph '" + pipeline_->name() +
                                "' declares no inputs (it reads its own source): call it without "
                                "a depth image"
                          : "graph '" + pipeline_->name() +
                                "' has several inputs: pass them by name, inputs={name: array}");
      }
      inputs[ports.front().name] = packet_for(ports.front(), depth, intrinsics, stem);
    }
    for (const auto& [name, value] : named_inputs) {
      const auto key = py::str(name).cast<std::string>();
      const auto port = std::find_if(ports.begin(), ports.end(),
                                     [&](const PortInfo& p) { return p.name == key; });
      if (port == ports.end()) {
        std::string names;
        for (const auto& p : ports)
          names += (names.empty() ? "'" : ", '") + p.name + "'";
        throw py::value_error("graph '" + pipeline_->name() + "' has no input '" + key + "'" +
                              (names.empty() ? "; it declares none" : "; its inputs are " + names));
      }
      inputs[key] = packet_for(*port, value.cast<py::object>(), intrinsics, stem);
    }

    FrameResult result;
    {
      py::gil_scoped_release release;
      result = pipeline_->process(inputs);
      // This call's references go now; the pipeline itself keeps the frame's input packets until
      // the next call, so the last reference may be dropped there, without the GIL (ArrayOwner).
      inputs.clear();
    }
    ++frames_;
    if (result.end_of_stream) return py::none();
    py::dict outputs;
    for (const auto& [name, packet] : result.outputs)
      outputs[py::str(name)] = to_python(packet);
    py::dict timings;
    for (const auto& timing : result.timings)
      timings[py::str(timing.node)] = timing.ms;
    return py::make_tuple(outputs, timings, result.warnings, result.frame_index);
  }

  std::string name() const { return pipeline_->name(); }
  py::list ports(const std::vector<PortInfo>& list) const {
    py::list out;
    for (const auto& port : list)
      out.append(py::make_tuple(port.name, port.type_key));
    return out;
  }
  py::list inputs() const { return ports(pipeline_->inputs()); }
  py::list outputs() const { return ports(pipeline_->outputs()); }
  std::vector<std::string> nodes() const { return pipeline_->nodes(); }
  void close() {
    py::gil_scoped_release release;
    pipeline_->close();
  }

 private:
  Packet packet_for(const PortInfo& port, const py::object& value, const py::object& intrinsics,
                    const std::string& stem) {
    if (port.type_key != type_key<DepthImage>()) {
      throw py::type_error("graph input '" + port.name + "' takes " + port.type_key +
                           ", which Python cannot make; only depth images (" +
                           std::string(type_key<DepthImage>()) + ") can be fed");
    }
    if (!py::isinstance<py::array>(value)) {
      throw py::type_error("depth must be a numpy array (uint16 millimetres or float32 metres)");
    }
    return depth_packet(value.cast<py::array>(), intrinsics, frames_, stem);
  }

  std::unique_ptr<Pipeline> pipeline_;
  std::int64_t frames_ = 0;  // the index the next frame's depth image carries
};

py::list diagnostics_list(const std::vector<GraphDiagnostic>& diagnostics) {
  py::list out;
  for (const auto& d : diagnostics) {
    const char* severity = d.severity == GraphDiagnostic::Severity::error     ? "error"
                           : d.severity == GraphDiagnostic::Severity::warning ? "warning"
                                                                              : "note";
    out.append(py::dict("severity"_a = severity, "file"_a = d.file, "line"_a = d.line,
                        "column"_a = d.column, "message"_a = d.message));
  }
  return out;
}

}  // namespace
}  // namespace facet::python

PYBIND11_MODULE(_facet, m) {
  using facet::python::PyPipeline;
  m.doc() = "facet: model-free 3D scene segmentation from depth images (docs/embedding.md)";

  static py::exception<facet::GraphError> graph_error(m, "GraphError", PyExc_ValueError);
  static py::exception<facet::ProcessError> process_error(m, "ProcessError", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr pending) {
    try {
      if (pending) std::rethrow_exception(pending);
    } catch (const facet::GraphError& error) {
      const auto type = py::reinterpret_borrow<py::object>(graph_error.ptr());
      py::object instance = type(error.what());
      instance.attr("diagnostics") = facet::python::diagnostics_list(error.diagnostics());
      PyErr_SetObject(graph_error.ptr(), instance.ptr());
    } catch (const facet::ProcessError& error) {
      process_error(error.what());
    }
  });

  py::class_<PyPipeline>(m, "_Pipeline")
      .def(py::init<const std::filesystem::path&, const py::dict&, const py::dict&,
                    const std::string&, const std::vector<std::filesystem::path>&, bool>(),
           "graph"_a, "params"_a, "sets"_a, "variant"_a, "plugin_path"_a, "run_sinks"_a)
      .def("call", &PyPipeline::call, "depth"_a, "intrinsics"_a, "stem"_a, "inputs"_a)
      .def_property_readonly("name", &PyPipeline::name)
      .def_property_readonly("inputs", &PyPipeline::inputs)
      .def_property_readonly("outputs", &PyPipeline::outputs)
      .def_property_readonly("nodes", &PyPipeline::nodes)
      .def("close", &PyPipeline::close);

  m.def(
      "stages",
      [](const std::vector<std::filesystem::path>& plugin_path) {
        py::list out;
        for (const auto& stage : facet::list_stages(plugin_path)) {
          out.append(py::dict("name"_a = stage.name, "plugin"_a = stage.plugin,
                              "summary"_a = stage.summary));
        }
        return out;
      },
      "plugin_path"_a = std::vector<std::filesystem::path>{});
  m.def("inspect", &facet::inspect_stage, "name"_a,
        "plugin_path"_a = std::vector<std::filesystem::path>{});
}
