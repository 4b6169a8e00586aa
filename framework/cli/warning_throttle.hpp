#pragma once
// The warnings of a run as a person reads them: the first few of each kind printed, the rest
// counted and said once at the end. A stage that warns on every frame of a long recording then
// prints three lines and a count, not thousands of lines that bury everything else.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace facet::cli {

class WarningThrottle {
 public:
  explicit WarningThrottle(int printed_per_kind = 3) : printed_per_kind_(printed_per_kind) {}

  // Whether to print `line`, a warning as the executor words it ("warning: node 'N', frame I:
  // message"). Its kind is the node and the message with numbers and quoted names blanked, so
  // "no valid depth in 'learn3.png'" and "... 'learn4.png'" are one kind.
  bool admit(const std::string& line);

  // One line per kind some of whose warnings were held back, in the order the kinds first
  // appeared: "warning: node 'N': 12 more like: <the last one held back>".
  std::vector<std::string> summary() const;

 private:
  struct Kind {
    std::int64_t seen = 0;
    std::int64_t order = 0;
    std::string node;
    std::string last;
  };
  int printed_per_kind_;
  std::map<std::string, Kind> kinds_;
};

}  // namespace facet::cli
