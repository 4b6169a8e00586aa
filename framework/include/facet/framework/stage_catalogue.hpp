#pragma once
// Finding stages in a registry by what a person types: part of a name, plugin or summary
// (`facet list FILTER`), a family (`normals` for normals.*), or a plugin (`facet_normals`).

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "facet/framework/registry.hpp"

namespace facet {

// The stages whose name, plugin name or one-line summary contains `filter`, ignoring case, in
// name order. An empty filter matches every stage.
std::vector<const StageEntry*> stages_matching(const Registry& registry, std::string_view filter);

// "normals" for "normals.cross": the part of a stage name before its first dot.
std::string_view stage_family(std::string_view stage_name);

// The stages of one family (`family` exactly, e.g. "normals"), in name order.
std::vector<const StageEntry*> stages_of_family(const Registry& registry, std::string_view family);

// The loaded plugin called `name` (e.g. "facet_normals"), or nullptr.
const PluginInfo* find_plugin(const Registry& registry, std::string_view name);

// What closest_catalogue_names offers: what `facet inspect` accepts (stage, family and plugin
// names), or also the part of a stage name after the family ("median" of filter.median), which
// is a good filter for `facet list`.
enum class CatalogueNames { inspectable, filter_words };

// Up to `count` names close to `wanted` (plausible typos), closest first.
std::vector<std::string> closest_catalogue_names(const Registry& registry,
                                                 const std::string& wanted, std::size_t count,
                                                 CatalogueNames kinds);

}  // namespace facet
