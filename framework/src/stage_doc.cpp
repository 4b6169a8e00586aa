#include "facet/framework/stage_doc.hpp"

#include <fmt/format.h>

#include <algorithm>

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

}  // namespace facet
