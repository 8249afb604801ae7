#include "apps/clothlab/output_path.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace clothlab::app {

namespace {

// A file is written beside its path and renamed, so its directory must exist and be writable:
// said when the command line is read (exit 2), never after a whole run (trace) or by ffmpeg.
std::string directory_problem(const std::string& path) {
  const std::filesystem::path dir = std::filesystem::absolute(path).parent_path();
  std::error_code ec;
  const char* why = nullptr;
  if (!std::filesystem::is_directory(dir, ec))
    why = "no such directory";
  else if (::access(dir.c_str(), W_OK | X_OK) != 0)
    why = "the directory is not writable";
  return why ? "cannot write '" + path + "': " + why + " ('" + dir.string() + "')" : std::string();
}

}  // namespace

std::string output_path_problem(const std::string& path, bool directory_ok) {
  if (path.empty()) return "an empty path names no file";
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0) {
    // Nothing there yet: written and renamed, where its directory takes files. Any other
    // failure (a name too long, a file used as a directory, a loop of links) is said as it is.
    if (errno != ENOENT) return "cannot use '" + path + "': " + std::strerror(errno);
    return directory_ok ? std::string() : directory_problem(path);
  }
  // A link to a directory is fine where a directory is: files are written inside it.
  struct stat target {};
  if (S_ISLNK(st.st_mode) && directory_ok && ::stat(path.c_str(), &target) == 0 &&
      S_ISDIR(target.st_mode))
    return {};
  if (S_ISLNK(st.st_mode))
    return "'" + path + "' is a symbolic link, which the finished file would replace; name the " +
           "file it points to";
  if (S_ISDIR(st.st_mode))
    return directory_ok ? std::string() : "'" + path + "' is a directory; name a file in it";
  if (!S_ISREG(st.st_mode))
    return "'" + path + "' is a device, pipe or socket, which the finished file (written beside " +
           "it and renamed) would replace; name a regular file";
  return directory_ok ? std::string() : directory_problem(path);
}

namespace {

CLI::Validator output_check(bool directory_ok, const char* what) {
  return CLI::Validator(
      [directory_ok](std::string& s) { return output_path_problem(s, directory_ok); }, what);
}

}  // namespace

CLI::Validator output_file() {
  return output_check(false, "FILE");
}

CLI::Validator output_file_or_directory() {
  return output_check(true, "PATH");
}

}  // namespace clothlab::app
