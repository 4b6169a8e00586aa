#pragma once
// Cyclone DDS for tests: the loopback interface only, no multicast, discovery by unicast to
// 127.0.0.1, so that tests run on machines without a network and never reach another computer.
// Tests also use their own domain id and topic names with the process id in them, so that runs
// in parallel (ctest -j, two build trees) do not see each other's messages.

#include <unistd.h>

#include <cstdlib>
#include <string>

namespace facet::test {

inline const char* loopback_cyclone_config() {
  return "<CycloneDDS><Domain id=\"any\"><General><Interfaces>"
         "<NetworkInterface name=\"lo\"/></Interfaces>"
         "<AllowMulticast>false</AllowMulticast></General>"
         "<Discovery><Peers><Peer address=\"127.0.0.1\"/></Peers>"
         "<ParticipantIndex>auto</ParticipantIndex>"
         "<MaxAutoParticipantIndex>50</MaxAutoParticipantIndex></Discovery>"
         "</Domain></CycloneDDS>";
}

// For participants created in this process; call before the first one.
inline void use_loopback_dds() {
  ::setenv("CYCLONEDDS_URI", loopback_cyclone_config(), 1);
  ::unsetenv("ROS_DOMAIN_ID");
}

// "/facet_test/<name>_<pid>": a topic no other test process uses.
inline std::string unique_topic(const std::string& name) {
  return "/facet_test/" + name + "_" + std::to_string(::getpid());
}

}  // namespace facet::test
