#include "warning_throttle.hpp"

#include <algorithm>
#include <cctype>

namespace facet::cli {
namespace {

constexpr std::string_view kNodePrefix = "warning: node '";

// "warning: node 'N', frame I: message" -> N and the message; other lines are their own kind.
bool split_line(const std::string& line, std::string& node, std::string& message) {
  if (line.rfind(kNodePrefix, 0) != 0) return false;
  const std::size_t node_end = line.find('\'', kNodePrefix.size());
  if (node_end == std::string::npos) return false;
  node = line.substr(kNodePrefix.size(), node_end - kNodePrefix.size());
  const std::size_t colon = line.find(": ", node_end);
  message = colon == std::string::npos ? std::string() : line.substr(colon + 2);
  return true;
}

// Digits and quoted text blanked: what stays is the wording, which is the kind.
std::string kind_of(const std::string& message) {
  std::string kind;
  bool quoted = false;
  for (const char c : message) {
    if (c == '\'') {
      quoted = !quoted;
      kind += c;
    } else if (quoted) {
      continue;
    } else if (std::isdigit(static_cast<unsigned char>(c)) != 0) {
      if (kind.empty() || kind.back() != '#') kind += '#';
    } else {
      kind += c;
    }
  }
  return kind;
}

}  // namespace

bool WarningThrottle::admit(const std::string& line) {
  std::string node;
  std::string message;
  if (!split_line(line, node, message)) return true;
  const std::string key = node + '\n' + kind_of(message);
  auto [it, inserted] = kinds_.try_emplace(key);
  Kind& kind = it->second;
  if (inserted) {
    kind.order = static_cast<std::int64_t>(kinds_.size());
    kind.node = node;
  }
  ++kind.seen;
  if (kind.seen <= printed_per_kind_) return true;
  kind.last = message;
  return false;
}

std::vector<std::string> WarningThrottle::summary() const {
  std::vector<const Kind*> held;
  for (const auto& [key, kind] : kinds_) {
    if (kind.seen > printed_per_kind_) held.push_back(&kind);
  }
  std::sort(held.begin(), held.end(),
            [](const Kind* a, const Kind* b) { return a->order < b->order; });
  std::vector<std::string> lines;
  for (const Kind* kind : held) {
    lines.push_back(std::string(kNodePrefix) + kind->node +
                    "': " + std::to_string(kind->seen - printed_per_kind_) +
                    " more like this, not printed: " + kind->last);
  }
  return lines;
}

}  // namespace facet::cli
