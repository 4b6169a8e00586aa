#include "openni2/openni_doctor.hpp"

#include <OpenNI.h>
#include <dlfcn.h>
#include <link.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <set>
#include <system_error>

#include "openni2/openni_runtime.hpp"

namespace fs = std::filesystem;

namespace facet::openni2 {
namespace {

// Debian's OpenNI2 reads its settings from here; upstream builds read OpenNI.ini next to the
// library.
const fs::path kDebianIni = "/etc/openni2/OpenNI.ini";
// OpenNI2's default driver repository, relative to the directory of libOpenNI2.so.
const fs::path kDefaultRepository = "OpenNI2/Drivers";

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r\n");
  return text.substr(first, last - first + 1);
}

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// The file libOpenNI2 was loaded from, as the dynamic linker resolved it.
fs::path openni_library_file() {
  void* handle = dlopen("libOpenNI2.so.0", RTLD_LAZY | RTLD_NOLOAD);
  if (handle == nullptr) return {};
  fs::path file;
  link_map* map = nullptr;
  if (dlinfo(handle, RTLD_DI_LINKMAP, &map) == 0 && map != nullptr && map->l_name != nullptr) {
    std::error_code error;
    file = fs::canonical(map->l_name, error);
    if (error) file = map->l_name;
  }
  dlclose(handle);
  return file;
}

std::string hex4(unsigned value) {
  char text[8];
  std::snprintf(text, sizeof(text), "%04x", value & 0xffffu);
  return text;
}

}  // namespace

std::string driver_purpose(const std::string& file_name) {
  const std::string name = lower(file_name);
  if (name.find("onifile") != std::string::npos) return ".oni recordings";
  if (name.find("ps1080") != std::string::npos)
    return "PrimeSense Carmine, Asus Xtion (PS1080 chip)";
  if (name.find("pslink") != std::string::npos) return "PrimeSense PSLink devices (Capri)";
  if (name.find("freenect") != std::string::npos) return "Kinect for Xbox 360 (libfreenect)";
  if (name.find("orbbec") != std::string::npos) return "Orbbec Astra (Orbbec's driver)";
  if (name.find("kinect") != std::string::npos) return "Kinect (Microsoft SDK)";
  if (name.find("dummy") != std::string::npos) return "OpenNI2's test driver, no devices";
  return "";
}

std::vector<std::string> driver_files(const fs::path& dir) {
  std::set<std::string> names;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(dir, error)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("lib", 0) == 0 && name.size() > 3 && name.ends_with(".so")) names.insert(name);
  }
  return {names.begin(), names.end()};
}

std::string ini_repository(const fs::path& ini_file) {
  std::ifstream in(ini_file);
  std::string line;
  bool in_drivers = false;
  while (std::getline(in, line)) {
    line = trim(line);
    if (line.empty() || line[0] == ';' || line[0] == '#') continue;
    if (line.front() == '[') {
      in_drivers = lower(line) == "[drivers]";
      continue;
    }
    const auto equals = line.find('=');
    if (in_drivers && equals != std::string::npos &&
        lower(trim(line.substr(0, equals))) == "repository") {
      return trim(line.substr(equals + 1));
    }
  }
  return "";
}

std::string openni_doctor_report() {
  std::string text;
  const auto runtime = OpenNiRuntime::acquire();  // throws with OpenNI2's message
  const fs::path library = openni_library_file();
  text += "OpenNI2 " + runtime->version() +
          (library.empty() ? std::string() : " (" + library.string() + ")") + "\n";

  // Where the drivers come from: the ini file's Repository, relative to the library's folder.
  const fs::path library_dir = library.parent_path();
  fs::path ini = library_dir / "OpenNI.ini";
  std::error_code error;
  if (!fs::exists(ini, error)) ini = kDebianIni;
  const bool have_ini = fs::exists(ini, error);
  const std::string repository = have_ini ? ini_repository(ini) : "";
  fs::path drivers = repository.empty() ? kDefaultRepository : fs::path(repository);
  if (drivers.is_relative()) drivers = library_dir / drivers;
  text += "settings: " + (have_ini ? ini.string() : std::string("(no OpenNI.ini found)")) +
          (repository.empty() ? " (drivers from the default " + kDefaultRepository.string() +
                                    " next to the library)"
                              : " (Repository=" + repository + ")") +
          "\n";
  text += "drivers loaded from " + drivers.string() + ":";
  const auto files = driver_files(drivers);
  if (files.empty()) text += " none (no lib*.so there: OpenNI2 finds no camera)";
  text += "\n";
  for (const auto& file : files) {
    const std::string purpose = driver_purpose(file);
    text += "  " + file + (purpose.empty() ? std::string() : "  (" + purpose + ")") + "\n";
  }

  openni::Array<openni::DeviceInfo> devices;
  openni::OpenNI::enumerateDevices(&devices);
  if (devices.getSize() == 0) {
    text +=
        "devices: none found (plugged in? powered? the udev rules let this user open it? "
        "its driver among those above? see docs/cameras.md)\n";
  } else {
    text += "devices:\n";
    for (int i = 0; i < devices.getSize(); ++i) {
      const openni::DeviceInfo& device = devices[i];
      text += std::string("  uri '") + device.getUri() + "'  " + device.getVendor() + " " +
              device.getName() + "  (USB " + hex4(device.getUsbVendorId()) + ":" +
              hex4(device.getUsbProductId()) + ")\n";
    }
  }
  return text;
}

}  // namespace facet::openni2
