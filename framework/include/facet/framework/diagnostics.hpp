#pragma once
// Compiler-style diagnostics: every problem found in a graph is collected, then all are printed
// as `file:line:col: error: message`, optionally followed by notes.

#include <ostream>
#include <string>
#include <vector>

namespace facet {

// The file name of diagnostics about command-line options (--param, --set, --variant).
inline constexpr const char* kCommandLineFile = "<command line>";

// 1-based line and column; 0 means "unknown" (the location is then printed as `file:`).
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
};

enum class Severity { error, warning, note };

struct Diagnostic {
  Severity severity = Severity::error;
  SourceLocation where;
  std::string message;
};

class Diagnostics {
 public:
  void error(SourceLocation where, std::string message);
  void warning(SourceLocation where, std::string message);
  void note(SourceLocation where, std::string message);

  // Every later error or warning in `file` is followed by the note `message` at `where`: a base
  // graph's problems then also point at the `extends:` that brought the base in, and through it
  // at each graph further up the chain.
  void add_file_context(std::string file, SourceLocation where, std::string message);

  bool has_errors() const { return error_count_ > 0; }
  int error_count() const { return error_count_; }
  const std::vector<Diagnostic>& all() const { return items_; }

  // One line per diagnostic, in the order they were reported.
  void print(std::ostream& out) const;
  std::string str() const;

 private:
  struct FileContext {
    std::string file;
    Diagnostic note;
  };
  void add_context_notes(const std::string& file);

  std::vector<Diagnostic> items_;
  std::vector<FileContext> contexts_;
  int error_count_ = 0;
};

std::string format_location(const SourceLocation& where);

// The candidate closest to `name` by edit distance, if it is close enough to be a plausible typo;
// empty otherwise. Used for "did you mean 'normals.cross'?".
std::string did_you_mean(const std::string& name, const std::vector<std::string>& candidates);

}  // namespace facet
