#include "yaml_checks.hpp"

#include <yaml-cpp/eventhandler.h>

#include <map>
#include <optional>
#include <sstream>
#include <unordered_set>

namespace facet::detail {

SourceLocation location_of(const YAML::Node& node, const std::string& file) {
  const YAML::Mark mark = node.Mark();
  if (mark.is_null()) return {file, 0, 0};
  return {file, mark.line + 1, mark.column + 1};
}

std::string_view kind_name(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Map:
      return "a map";
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Scalar:
      return "a scalar";
    case YAML::NodeType::Null:
    case YAML::NodeType::Undefined:
      return "nothing";
  }
  return "nothing";
}

namespace {

// Events of the YAML parser, remembering where the first alias is.
class AliasFinder final : public YAML::EventHandler {
 public:
  std::optional<YAML::Mark> first_alias;

  void OnAlias(const YAML::Mark& mark, YAML::anchor_t /*anchor*/) override {
    if (!first_alias) first_alias = mark;
  }
  void OnDocumentStart(const YAML::Mark& /*mark*/) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& /*mark*/, YAML::anchor_t /*anchor*/) override {}
  void OnScalar(const YAML::Mark& /*mark*/, const std::string& /*tag*/, YAML::anchor_t /*anchor*/,
                const std::string& /*value*/) override {}
  void OnSequenceStart(const YAML::Mark& /*mark*/, const std::string& /*tag*/,
                       YAML::anchor_t /*anchor*/, YAML::EmitterStyle::value /*style*/) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& /*mark*/, const std::string& /*tag*/, YAML::anchor_t /*anchor*/,
                  YAML::EmitterStyle::value /*style*/) override {}
  void OnMapEnd() override {}
};

}  // namespace

bool refuse_aliases(const std::string& yaml, const std::string& file, Diagnostics& diagnostics) {
  std::istringstream stream(yaml);
  YAML::Parser parser(stream);
  AliasFinder finder;
  // The first document only: it is the one YAML::Load reads. yaml-cpp 0.7's parser can also
  // report a next document forever at the end of some malformed streams (a found hang: a leading
  // ',' and a byte that is not UTF-8), so no loop over documents.
  parser.HandleNextDocument(finder);
  if (!finder.first_alias) return true;
  const YAML::Mark& mark = *finder.first_alias;
  diagnostics.error({file, mark.line + 1, mark.column + 1},
                    "YAML aliases (*name) are not allowed in graph files: write the value out, "
                    "or give it a graph parameter and use ${name}");
  return false;
}

void report_duplicate_keys(const YAML::Node& root, const std::string& file,
                           Diagnostics& diagnostics) {
  if (root.IsSequence()) {
    for (const auto& item : root)
      report_duplicate_keys(item, file, diagnostics);
    return;
  }
  if (!root.IsMap()) return;
  std::map<std::string, SourceLocation> first_seen;
  for (const auto& entry : root) {
    if (entry.first.IsScalar()) {
      const SourceLocation where = location_of(entry.first, file);
      const auto [it, inserted] = first_seen.emplace(entry.first.Scalar(), where);
      if (!inserted) {
        diagnostics.error(where, "duplicate key '" + entry.first.Scalar() +
                                     "' (first defined at line " + std::to_string(it->second.line) +
                                     ")");
      }
    }
    report_duplicate_keys(entry.second, file, diagnostics);
  }
}

std::vector<MapEntry> map_entries(const YAML::Node& map, const std::string& file,
                                  Diagnostics& diagnostics) {
  std::vector<MapEntry> entries;
  if (!map.IsMap()) return entries;
  std::unordered_set<std::string> seen;
  for (const auto& entry : map) {
    const SourceLocation where = location_of(entry.first, file);
    if (!entry.first.IsScalar()) {
      diagnostics.error(
          where, std::string("a key must be a scalar, got ") + std::string(kind_name(entry.first)));
      continue;
    }
    const std::string& key = entry.first.Scalar();
    if (seen.insert(key).second) entries.push_back({key, where, entry.second});
  }
  return entries;
}

namespace {

bool expect_kind(bool ok, const YAML::Node& node, const SourceLocation& where,
                 std::string_view what, std::string_view expected, Diagnostics& diagnostics) {
  if (!ok) {
    diagnostics.error(where, std::string(what) + " must be " + std::string(expected) + ", got " +
                                 std::string(kind_name(node)));
  }
  return ok;
}

}  // namespace

bool expect_map(const YAML::Node& node, const SourceLocation& where, std::string_view what,
                Diagnostics& diagnostics) {
  return expect_kind(node.IsMap(), node, where, what, "a map", diagnostics);
}

bool expect_scalar(const YAML::Node& node, const SourceLocation& where, std::string_view what,
                   Diagnostics& diagnostics) {
  return expect_kind(node.IsScalar(), node, where, what, "a scalar", diagnostics);
}

bool expect_sequence(const YAML::Node& node, const SourceLocation& where, std::string_view what,
                     Diagnostics& diagnostics) {
  return expect_kind(node.IsSequence(), node, where, what, "a list", diagnostics);
}

std::string suggestion_suffix(const std::string& name, const std::vector<std::string>& candidates,
                              std::string_view fallback_label) {
  const std::string guess = did_you_mean(name, candidates);
  if (!guess.empty()) return "; did you mean '" + guess + "'?";
  if (fallback_label.empty() || candidates.empty()) return {};
  return "; " + std::string(fallback_label) + ": " + join(candidates, ", ");
}

void report_unknown_key(const MapEntry& entry, std::string_view context,
                        const std::vector<std::string>& allowed, Diagnostics& diagnostics) {
  diagnostics.error(entry.key_where, "unknown key '" + entry.key + "' in " + std::string(context) +
                                         suggestion_suffix(entry.key, allowed, "expected one of"));
}

bool is_identifier(std::string_view text) {
  const auto alpha = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); };
  const auto digit = [](char c) { return c >= '0' && c <= '9'; };
  if (text.empty() || !(alpha(text.front()) || text.front() == '_')) return false;
  for (const char c : text) {
    if (!(alpha(c) || digit(c) || c == '_')) return false;
  }
  return true;
}

std::string join(const std::vector<std::string>& items, std::string_view separator) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) out += separator;
    out += items[i];
  }
  return out;
}

std::string in_quotes(const std::string& text) {
  return "'" + text + "'";
}

}  // namespace facet::detail
