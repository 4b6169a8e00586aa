#include "facet/framework/stage_catalogue.hpp"

#include <algorithm>
#include <cctype>
#include <set>

#include "facet/framework/diagnostics.hpp"

namespace facet {
namespace {

std::string lowercase(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

bool contains_ignoring_case(std::string_view text, const std::string& lowercase_part) {
  return lowercase(text).find(lowercase_part) != std::string::npos;
}

}  // namespace

std::vector<const StageEntry*> stages_matching(const Registry& registry, std::string_view filter) {
  const std::string wanted = lowercase(filter);
  std::vector<const StageEntry*> found;
  for (const auto& name : registry.stage_names()) {
    const StageEntry& entry = *registry.find(name);
    if (contains_ignoring_case(name, wanted) ||
        contains_ignoring_case(entry.plugin->name, wanted) ||
        contains_ignoring_case(entry.spec.summary(), wanted)) {
      found.push_back(&entry);
    }
  }
  return found;
}

std::string_view stage_family(std::string_view stage_name) {
  return stage_name.substr(0, stage_name.find('.'));
}

std::vector<const StageEntry*> stages_of_family(const Registry& registry, std::string_view family) {
  std::vector<const StageEntry*> found;
  for (const auto& name : registry.stage_names()) {
    // A name without a dot is its own family only when asked by its full name, which an exact
    // lookup answers first; a family has at least one "family." member.
    if (name.find('.') != std::string::npos && stage_family(name) == family)
      found.push_back(registry.find(name));
  }
  return found;
}

const PluginInfo* find_plugin(const Registry& registry, std::string_view name) {
  for (const auto& plugin : registry.plugins()) {
    if (plugin->name == name) return plugin.get();
  }
  return nullptr;
}

std::vector<std::string> closest_catalogue_names(const Registry& registry,
                                                 const std::string& wanted, std::size_t count,
                                                 CatalogueNames kinds) {
  // Every name a person may mean, once each: stages, their families, plugins.
  std::set<std::string> unique;
  for (const auto& name : registry.stage_names()) {
    unique.insert(name);
    const std::string_view family = stage_family(name);
    unique.insert(std::string(family));
    if (kinds == CatalogueNames::filter_words && family.size() < name.size())
      unique.insert(name.substr(family.size() + 1));
  }
  for (const auto& plugin : registry.plugins())
    unique.insert(plugin->name);
  std::vector<std::string> candidates(unique.begin(), unique.end());
  // did_you_mean gives the single closest; taking it out and asking again gives the next.
  std::vector<std::string> closest;
  while (closest.size() < count) {
    std::string next = did_you_mean(wanted, candidates);
    if (next.empty()) break;
    candidates.erase(std::find(candidates.begin(), candidates.end(), next));
    closest.push_back(std::move(next));
  }
  return closest;
}

}  // namespace facet
