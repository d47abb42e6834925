#include "disk_space.h"

#include <sys/statvfs.h>

#include <cstring>
#include <filesystem>

namespace beverloo {

bool no_space_left(const std::string& path, std::string_view message) {
  for (std::string_view says : {std::string_view(std::strerror(ENOSPC)), std::string_view("disk is full")})
    if (message.find(says) != std::string_view::npos) return true;
  return file_system_full(path);
}

bool file_system_full(const std::string& path) {
  // the job's directory may be the one that could not be made: ask its nearest existing parent
  std::filesystem::path p = path.empty() ? std::filesystem::path(".") : std::filesystem::path(path);
  std::error_code ec;
  while (!std::filesystem::exists(p, ec) && p.has_parent_path() && p.parent_path() != p) p = p.parent_path();
  struct statvfs s {};
  if (::statvfs(p.c_str(), &s) != 0) return false;  // cannot tell: not a full disk as far as we know
  return static_cast<std::uint64_t>(s.f_bavail) * s.f_frsize < kFullBelowBytes;
}

}  // namespace beverloo
