#pragma once
// Helpers for reading a YAML document strictly: every value keeps its file location, map keys
// are checked for duplicates (yaml-cpp 0.7 accepts them silently) and kinds are checked before
// use, with a diagnostic instead of an exception.

#include <yaml-cpp/yaml.h>

#include <string>
#include <string_view>
#include <vector>

#include "facet/framework/diagnostics.hpp"

namespace facet::detail {

// yaml-cpp marks are 0-based; diagnostics are 1-based. A node without a mark gets line 0.
SourceLocation location_of(const YAML::Node& node, const std::string& file);

// "a map", "a list", "a scalar", "nothing": for "expected a map, got a list".
std::string_view kind_name(const YAML::Node& node);

// Reports the first YAML alias (`*name`) in `yaml` and returns false when there is one. Graph
// files have graph parameters for repeated values; an alias can refer to itself or expand
// exponentially (`a: &a [*a]`, billion laughs), which no walk over the document survives.
bool refuse_aliases(const std::string& yaml, const std::string& file, Diagnostics& diagnostics);

// Reports every map key that occurs twice in the same map, at any depth of `root`.
void report_duplicate_keys(const YAML::Node& root, const std::string& file,
                           Diagnostics& diagnostics);

struct MapEntry {
  std::string key;
  SourceLocation key_where;
  YAML::Node value;
};

// The entries of a map in file order. A repeated key is skipped here (report_duplicate_keys has
// already reported it), so that one typo does not cascade into more errors; a key that is not a
// scalar is reported.
std::vector<MapEntry> map_entries(const YAML::Node& map, const std::string& file,
                                  Diagnostics& diagnostics);

// Reports `what` (e.g. "node 'median'") having the wrong kind. Returns whether the kind is right.
bool expect_map(const YAML::Node& node, const SourceLocation& where, std::string_view what,
                Diagnostics& diagnostics);
bool expect_scalar(const YAML::Node& node, const SourceLocation& where, std::string_view what,
                   Diagnostics& diagnostics);
bool expect_sequence(const YAML::Node& node, const SourceLocation& where, std::string_view what,
                     Diagnostics& diagnostics);

// Reports a key that is not one of `allowed`, with a suggestion or the list of allowed keys.
void report_unknown_key(const MapEntry& entry, std::string_view context,
                        const std::vector<std::string>& allowed, Diagnostics& diagnostics);

// "; did you mean 'x'?" when a close candidate exists, otherwise "; <fallback>" (or nothing).
std::string suggestion_suffix(const std::string& name, const std::vector<std::string>& candidates,
                              std::string_view fallback_label);

// [A-Za-z_][A-Za-z0-9_]*
bool is_identifier(std::string_view text);

std::string join(const std::vector<std::string>& items, std::string_view separator);

// 'text', as names appear in diagnostics.
std::string in_quotes(const std::string& text);

}  // namespace facet::detail
