#include "elf_check.hpp"

#include <elf.h>
#include <link.h>

#include <cstring>
#include <fstream>
#include <system_error>
#include <vector>

namespace facet::detail {
namespace {

// ElfW(...) is the ELF class of this build (64-bit on x86_64 and aarch64).
using Header = ElfW(Ehdr);
using ProgramHeader = ElfW(Phdr);

#if defined(__x86_64__)
constexpr int kMachine = EM_X86_64;
#elif defined(__aarch64__)
constexpr int kMachine = EM_AARCH64;
#elif defined(__i386__)
constexpr int kMachine = EM_386;
#else
constexpr int kMachine = -1;  // not checked
#endif

#if __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
constexpr unsigned char kByteOrder = ELFDATA2LSB;
#else
constexpr unsigned char kByteOrder = ELFDATA2MSB;
#endif

constexpr unsigned char kClass = sizeof(void*) == 8 ? ELFCLASS64 : ELFCLASS32;

// Whether [offset, offset + size) lies within a file of `file_size` bytes, without overflow.
bool within(std::uint64_t offset, std::uint64_t size, std::uint64_t file_size) {
  return offset <= file_size && size <= file_size - offset;
}

std::string bytes(std::uint64_t count) {
  return std::to_string(count) + " bytes";
}

}  // namespace

std::optional<std::string> check_elf_file(const std::filesystem::path& file) {
  std::error_code error;
  const std::uint64_t file_size = std::filesystem::file_size(file, error);
  if (error) return "cannot read its size: " + error.message();
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::string("cannot be opened");
  Header header{};
  if (file_size < sizeof(header) || !in.read(reinterpret_cast<char*>(&header), sizeof(header))) {
    return "not a shared library (" + bytes(file_size) + ", shorter than an ELF header)";
  }
  if (std::memcmp(header.e_ident, ELFMAG, SELFMAG) != 0) {
    return std::string("not a shared library (no ELF header)");
  }
  if (header.e_ident[EI_CLASS] != kClass || header.e_ident[EI_DATA] != kByteOrder ||
      (kMachine >= 0 && header.e_machine != kMachine)) {
    return std::string(
        "a library for another kind of machine (ELF class, byte order or "
        "machine differ from this host's)");
  }
  if (header.e_type != ET_DYN) return std::string("an ELF file but not a shared library");
  if (header.e_phentsize != sizeof(ProgramHeader) || header.e_phnum == 0) {
    return std::string("its ELF header is corrupt (program headers)");
  }
  const std::uint64_t table_bytes = std::uint64_t{header.e_phnum} * sizeof(ProgramHeader);
  if (!within(header.e_phoff, table_bytes, file_size)) {
    return "truncated or corrupt: its program headers end past the file's " + bytes(file_size);
  }
  if (header.e_shoff != 0 &&
      !within(header.e_shoff, std::uint64_t{header.e_shnum} * header.e_shentsize, file_size)) {
    return "truncated or corrupt: its section headers end past the file's " + bytes(file_size);
  }
  std::vector<ProgramHeader> segments(header.e_phnum);
  in.seekg(static_cast<std::streamoff>(header.e_phoff));
  if (!in.read(reinterpret_cast<char*>(segments.data()),
               static_cast<std::streamsize>(table_bytes))) {
    return std::string("cannot read its program headers");
  }
  for (const ProgramHeader& segment : segments) {
    if (segment.p_type != PT_LOAD && segment.p_type != PT_DYNAMIC) continue;
    if (!within(segment.p_offset, segment.p_filesz, file_size)) {
      return "truncated or corrupt: a loadable segment ends at byte " +
             std::to_string(segment.p_offset + segment.p_filesz) + ", the file has " +
             bytes(file_size);
    }
  }
  return std::nullopt;
}

}  // namespace facet::detail
