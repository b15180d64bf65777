// Test helpers: whether processes of a process group, or with a marker in their command line,
// are still alive (read from /proc; Linux).
#pragma once

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

namespace mg::test {

inline bool any_process(bool (*matches)(const std::string& stat, const std::string& cmdline, long key), long key) {
  for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream stat_file(entry.path() / "stat"), cmd_file(entry.path() / "cmdline");
    std::stringstream stat, cmd;
    stat << stat_file.rdbuf();
    cmd << cmd_file.rdbuf();
    if (matches(stat.str(), cmd.str(), key)) return true;
  }
  return false;
}

// A process of group `pgid` exists (zombies included). stat: "pid (comm) state ppid pgrp ...".
inline bool group_alive(long pgid) {
  return any_process(
      [](const std::string& stat, const std::string&, long key) {
        const std::size_t close = stat.rfind(')');
        if (close == std::string::npos) return false;
        std::istringstream rest(stat.substr(close + 2));
        std::string state;
        long ppid = 0, pgrp = 0;
        rest >> state >> ppid >> pgrp;
        return pgrp == key;
      },
      pgid);
}

// Polls for up to 5 s (generous: a loaded machine) until the group is gone.
inline bool group_gone_soon(long pgid) {
  for (int i = 0; i < 500; ++i) {
    if (!group_alive(pgid)) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

}  // namespace mg::test
