#include "apps/clothlab/output_path.hpp"

#include <sys/stat.h>

namespace clothlab::app {

std::string output_path_problem(const std::string& path, bool directory_ok) {
  if (path.empty()) return "an empty path names no file";
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0) return {};  // nothing there yet: written and renamed
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
  return {};
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
