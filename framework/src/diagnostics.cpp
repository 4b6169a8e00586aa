#include "facet/framework/diagnostics.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <utility>

namespace facet {
namespace {

std::string_view severity_name(Severity severity) {
  switch (severity) {
    case Severity::error:
      return "error";
    case Severity::warning:
      return "warning";
    case Severity::note:
      return "note";
  }
  return "error";
}

std::string lowercase(const std::string& text) {
  std::string out = text;
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

// Optimal string alignment distance: Levenshtein plus swaps of adjacent characters, because
// "medain" for "median" is one slip of the fingers, not two.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  const std::size_t rows = a.size() + 1;
  const std::size_t cols = b.size() + 1;
  std::vector<std::size_t> d(rows * cols, 0);
  const auto at = [cols, &d](std::size_t i, std::size_t j) -> std::size_t& {
    return d[i * cols + j];
  };
  for (std::size_t i = 0; i < rows; ++i)
    at(i, 0) = i;
  for (std::size_t j = 0; j < cols; ++j)
    at(0, j) = j;
  for (std::size_t i = 1; i < rows; ++i) {
    for (std::size_t j = 1; j < cols; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      at(i, j) = std::min({at(i - 1, j) + 1, at(i, j - 1) + 1, at(i - 1, j - 1) + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        at(i, j) = std::min(at(i, j), at(i - 2, j - 2) + 1);
      }
    }
  }
  return at(rows - 1, cols - 1);
}

}  // namespace

void Diagnostics::error(SourceLocation where, std::string message) {
  const std::string file = where.file;
  items_.push_back({Severity::error, std::move(where), std::move(message)});
  ++error_count_;
  add_context_notes(file);
}

void Diagnostics::warning(SourceLocation where, std::string message) {
  const std::string file = where.file;
  items_.push_back({Severity::warning, std::move(where), std::move(message)});
  add_context_notes(file);
}

void Diagnostics::add_file_context(std::string file, SourceLocation where, std::string message) {
  contexts_.push_back({std::move(file), {Severity::note, std::move(where), std::move(message)}});
}

void Diagnostics::add_context_notes(const std::string& file) {
  // Up the chain of contexts; each at most once, so that a cycle cannot loop.
  std::string current = file;
  for (std::size_t step = 0; step < contexts_.size(); ++step) {
    const auto it =
        std::find_if(contexts_.begin(), contexts_.end(),
                     [&](const FileContext& context) { return context.file == current; });
    if (it == contexts_.end()) return;
    items_.push_back(it->note);
    current = it->note.where.file;
  }
}

void Diagnostics::note(SourceLocation where, std::string message) {
  items_.push_back({Severity::note, std::move(where), std::move(message)});
}

void Diagnostics::print(std::ostream& out) const {
  for (const auto& item : items_) {
    const std::string location = format_location(item.where);
    if (!location.empty()) out << location << ": ";
    out << severity_name(item.severity) << ": " << item.message << '\n';
  }
}

std::string Diagnostics::str() const {
  std::ostringstream out;
  print(out);
  return out.str();
}

std::string format_location(const SourceLocation& where) {
  std::string text = where.file;
  if (where.line <= 0) return text;
  text += ':' + std::to_string(where.line);
  if (where.column > 0) text += ':' + std::to_string(where.column);
  return text;
}

std::string did_you_mean(const std::string& name, const std::vector<std::string>& candidates) {
  // A name longer than any identifier a person types is no typo: no suggestion, and no
  // quadratic edit distance over a megabyte-long name.
  constexpr std::size_t kMaxSuggestedLength = 128;
  if (name.empty() || name.size() > kMaxSuggestedLength) return {};
  const std::string wanted = lowercase(name);
  // Allow roughly one typo per three characters: enough for slips, few absurd suggestions.
  const std::size_t limit = std::max<std::size_t>(1, wanted.size() / 3);
  std::string best;
  std::size_t best_distance = limit + 1;
  for (const auto& candidate : candidates) {
    if (candidate == name) continue;
    // The edit distance is at least the difference in length: most candidates are ruled out
    // without computing it.
    const std::size_t length_gap = candidate.size() > wanted.size()
                                       ? candidate.size() - wanted.size()
                                       : wanted.size() - candidate.size();
    if (length_gap >= best_distance) continue;
    const std::size_t distance = edit_distance(wanted, lowercase(candidate));
    // Strictly better only, so that ties go to the first candidate and the answer is stable.
    if (distance < best_distance) {
      best = candidate;
      best_distance = distance;
    }
  }
  return best;
}

}  // namespace facet
