#pragma once
// A look at a plugin file before the dynamic loader maps it. dlopen() trusts the ELF headers: a
// truncated library (a copy cut short, a download interrupted) is mapped beyond the end of the
// file, and the loader dies of SIGBUS touching it, taking `facet list` and every run with it even
// when no graph needs that plugin.

#include <filesystem>
#include <optional>
#include <string>

namespace facet::detail {

// Why `file` cannot be a shared library of this machine's kind, or nothing: not an ELF file, the
// wrong class, byte order, machine or type, or headers and loadable segments that reach past the
// end of the file. Reads only the ELF and program headers.
std::optional<std::string> check_elf_file(const std::filesystem::path& file);

}  // namespace facet::detail
