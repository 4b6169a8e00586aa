#include "facet/framework/stage_doc.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <type_traits>
#include <variant>

namespace facet {
namespace {

std::string bound(const ParamSpec& param, double value) {
  return param.type == ParamType::integer
             ? format_param_value(ParamValue(static_cast<std::int64_t>(value)))
             : format_param_value(ParamValue(value));
}

std::string range_text(const ParamSpec& param) {
  const auto& o = param.options;
  if (!o.choices.empty()) {
    std::string text = "one of {";
    for (std::size_t i = 0; i < o.choices.size(); ++i) {
      text += (i ? ", " : "") + format_param_value(o.choices[i]);
    }
    return text + "}";
  }
  if (o.min && o.max) return "range [" + bound(param, *o.min) + ", " + bound(param, *o.max) + "]";
  if (o.min) return "≥ " + bound(param, *o.min);
  if (o.max) return "≤ " + bound(param, *o.max);
  return {};
}

std::string plugin_text(const StageEntry& entry) {
  const auto& plugin = *entry.plugin;
  std::string text = plugin.name + " " + plugin.version;
  if (!plugin.file.empty()) text += " (" + plugin.file.string() + ")";
  return text;
}

// Indents every line of a multi-line doc string.
std::string indented(const std::string& text, const std::string& indent) {
  std::string out = indent;
  for (const char c : text) {
    out += c;
    if (c == '\n') out += indent;
  }
  return out;
}

// Text for a Markdown table cell: one line, with the column separator escaped.
std::string table_cell(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::string out;
  for (const char c : text) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

// The summary line as a paragraph of its own, then the details.
std::string markdown_doc(const std::string& doc) {
  const auto newline = doc.find('\n');
  if (newline == std::string::npos) return doc;
  return doc.substr(0, newline) + "\n\n" + doc.substr(newline + 1);
}

void write_param_value(JsonWriter& json, const ParamValue& value) {
  std::visit(
      [&json](const auto& v) {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::string>) {
          json.value(std::string_view(v));
        } else {
          json.value(v);
        }
      },
      value);
}

// A bound of an integer parameter is written as an integer, like its default.
void write_bound(JsonWriter& json, const ParamSpec& param, const std::optional<double>& bound) {
  if (!bound) {
    json.null();
  } else if (param.type == ParamType::integer) {
    json.value(static_cast<std::int64_t>(*bound));
  } else {
    json.value(*bound);
  }
}

void write_ports_json(JsonWriter& json, const std::vector<PortSpec>& ports, bool inputs) {
  json.begin_array();
  for (const auto& port : ports) {
    json.begin_object();
    json.key("name").value(port.name);
    json.key("type_key").value(port.type_key);
    if (inputs) json.key("required").value(port.required);
    json.key("doc").value(port.doc);
    json.end_object();
  }
  json.end_array();
}

void write_param_json(JsonWriter& json, const ParamSpec& param) {
  const ParamOptions& o = param.options;
  json.begin_object();
  json.key("name").value(param.name);
  json.key("type").value(to_string(param.type));
  json.key("required").value(o.required);
  json.key("default");
  write_param_value(json, param.default_value);
  json.key("min");
  write_bound(json, param, o.min);
  json.key("max");
  write_bound(json, param, o.max);
  json.key("choices");
  if (o.choices.empty()) {
    json.null();
  } else {
    json.begin_array();
    for (const auto& choice : o.choices)
      write_param_value(json, choice);
    json.end_array();
  }
  json.key("unit");
  o.unit.empty() ? json.null() : json.value(o.unit);
  json.key("doc").value(param.doc);
  json.key("default_origin");
  o.origin.empty() ? json.null() : json.value(o.origin);
  json.end_object();
}

}  // namespace

std::string describe_param(const ParamSpec& param) {
  std::string text = std::string(to_string(param.type));
  const std::string value = format_param_value(param.default_value);
  text += param.options.required ? ", required" : ", default " + (value.empty() ? "\"\"" : value);
  if (const auto range = range_text(param); !range.empty()) text += ", " + range;
  if (!param.options.unit.empty()) text += ", unit " + param.options.unit;
  return text;
}

void write_stage_text(std::ostream& out, const StageEntry& entry) {
  const StageSpec& spec = entry.spec;
  out << spec.name() << "\n" << indented(spec.doc(), "  ") << "\n\n";
  out << "  plugin:      " << plugin_text(entry) << "\n";
  out << "  concurrency: " << to_string(spec.concurrency()) << "\n";
  const auto port_width = [&] {
    std::size_t width = 4;
    for (const auto& p : spec.inputs())
      width = std::max(width, p.name.size());
    for (const auto& p : spec.outputs())
      width = std::max(width, p.name.size());
    return width;
  }();
  out << "\ninputs:" << (spec.inputs().empty() ? " none (source)\n" : "\n");
  for (const auto& port : spec.inputs()) {
    out << fmt::format("  {:<{}}  {:<22} {:<9} {}\n", port.name, port_width, port.type_key,
                       port.required ? "required" : "optional", port.doc);
  }
  out << "\noutputs:" << (spec.outputs().empty() ? " none (sink)\n" : "\n");
  for (const auto& port : spec.outputs()) {
    out << fmt::format("  {:<{}}  {:<22} {}\n", port.name, port_width, port.type_key, port.doc);
  }
  out << "\nparameters:" << (spec.params().empty() ? " none\n" : "\n");
  for (const auto& param : spec.params()) {
    out << "  " << param.name << "  (" << describe_param(param) << ")\n";
    out << indented(param.doc, "      ") << "\n";
    if (!param.options.origin.empty())
      out << "      default from: " << param.options.origin << "\n";
  }
}

void write_stage_markdown(std::ostream& out, const StageEntry& entry) {
  const StageSpec& spec = entry.spec;
  out << "### `" << spec.name() << "`\n\n" << markdown_doc(spec.doc()) << "\n\n";
  out << "Plugin `" << entry.plugin->name << "`, concurrency `" << to_string(spec.concurrency())
      << "`.\n\n";
  if (!spec.inputs().empty() || !spec.outputs().empty()) {
    out << "| port | direction | type | doc |\n|---|---|---|---|\n";
    for (const auto& port : spec.inputs()) {
      out << "| `" << port.name << "` | in" << (port.required ? "" : " (optional)") << " | `"
          << port.type_key << "` | " << table_cell(port.doc) << " |\n";
    }
    for (const auto& port : spec.outputs()) {
      out << "| `" << port.name << "` | out | `" << port.type_key << "` | " << table_cell(port.doc)
          << " |\n";
    }
    out << "\n";
  }
  if (!spec.params().empty()) {
    out << "| parameter | type | default | range | unit | doc | default from |\n";
    out << "|---|---|---|---|---|---|---|\n";
    for (const auto& param : spec.params()) {
      out << "| `" << param.name << "` | " << to_string(param.type) << " | "
          << (param.options.required ? std::string("required")
                                     : fmt::format("`{}`", format_param_value(param.default_value)))
          << " | " << range_text(param) << " | " << param.options.unit << " | "
          << table_cell(param.doc) << " | " << table_cell(param.options.origin) << " |\n";
    }
    out << "\n";
  }
}

void write_stage_json(JsonWriter& json, const StageEntry& entry) {
  const StageSpec& spec = entry.spec;
  const PluginInfo& plugin = *entry.plugin;
  json.begin_object();
  json.key("name").value(spec.name());
  json.key("summary").value(spec.summary());
  json.key("doc").value(spec.doc());
  json.key("plugin").begin_object();
  json.key("name").value(plugin.name);
  json.key("version").value(plugin.version);
  json.key("file");
  plugin.file.empty() ? json.null() : json.value(plugin.file.string());
  json.end_object();
  json.key("concurrency").value(to_string(spec.concurrency()));
  json.key("inputs");
  write_ports_json(json, spec.inputs(), true);
  json.key("outputs");
  write_ports_json(json, spec.outputs(), false);
  json.key("parameters").begin_array();
  for (const auto& param : spec.params())
    write_param_json(json, param);
  json.end_array();
  json.end_object();
}

}  // namespace facet
