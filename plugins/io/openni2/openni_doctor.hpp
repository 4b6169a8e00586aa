#pragma once
// The OpenNI2 section of `facet doctor`: the library, where it loads its drivers from, the
// driver files there, and the devices it finds.

#include <filesystem>
#include <string>
#include <vector>

namespace facet::openni2 {

// What a driver file gives, for the known ones ("" for others), e.g. libOniFile.so -> ".oni
// recordings".
std::string driver_purpose(const std::string& file_name);

// The driver files of `dir` (lib*.so, each once), sorted.
std::vector<std::string> driver_files(const std::filesystem::path& dir);

// The `Repository` setting of an OpenNI.ini file's [Drivers] section; "" when it is not set.
std::string ini_repository(const std::filesystem::path& ini_file);

// The whole section; initialises OpenNI2 (through OpenNiRuntime) to enumerate devices.
std::string openni_doctor_report();

}  // namespace facet::openni2
