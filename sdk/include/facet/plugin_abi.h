/* The plugin ABI: the only thing the host reads from a plugin before it trusts the plugin's C++.
 *
 * Every plugin exports exactly one C symbol, FACET_PLUGIN_ENTRY_NAME, returning a pointer to a
 * facet_plugin_header. The host checks magic, ABI version, SDK version and toolchain fingerprint
 * field by field (plain C data, no C++ runtime involved) and only then calls register_stages.
 * Fields are only ever appended; header_size tells the host how much of the struct exists. */
#ifndef FACET_PLUGIN_ABI_H
#define FACET_PLUGIN_ABI_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* "FCET" read as a little-endian 32-bit integer. */
#define FACET_PLUGIN_MAGIC 0x54454346u
/* Bumped whenever the layout of facet_plugin_header or the meaning of register_stages changes,
 * which includes the virtual functions of facet::Registrar that register_stages calls.
 *   1: Registrar::add_stage
 *   2: Registrar::add_diagnostic appended (sections of `facet doctor`) */
#define FACET_PLUGIN_ABI_VERSION 2u
#define FACET_PLUGIN_ENTRY_NAME "facet_plugin_entry"

typedef struct facet_plugin_header {
  uint32_t magic;
  uint32_t abi_version;
  uint32_t header_size;
  uint32_t sdk_version_major;
  uint32_t sdk_version_minor;
  uint32_t sdk_version_patch;
  const char* toolchain;      /* see FACET_TOOLCHAIN_FINGERPRINT in facet/version.hpp */
  const char* plugin_name;    /* e.g. "facet_filters" */
  const char* plugin_version; /* free-form, e.g. "0.1.0" */
  /* Called with a facet::Registrar* once the header has been accepted. */
  void (*register_stages)(void* registrar);
} facet_plugin_header;

typedef const facet_plugin_header* (*facet_plugin_entry_fn)(void);

#ifdef __cplusplus
}
#endif

#endif /* FACET_PLUGIN_ABI_H */
