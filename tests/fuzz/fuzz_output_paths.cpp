// Output paths (issue 40): the bytes of an input choose a command (trace --out, render --video,
// render --out, render --music-out), a path built from the entries of a prepared directory
// (regular and read-only files, directories, symbolic links to each and to nowhere, a loop, a
// device node, a pipe, a socket, missing parents, a file used as a directory, long and odd
// names, relative or absolute, `--opt P` or `--opt=P`), and `clothlab` runs on it. Whatever it
// does, the properties of docs/command-line.md hold:
// - it ends by itself within kTimeoutSeconds with status 0, 1 or 2 (no signal, no hang: a pipe
//   opened for writing would block);
// - on failure nothing changed: every entry of the directory has the same type, mode, size,
//   content and link target as before, and no new entry (no partial or temporary file);
// - on success only the named output changed: a regular file (or the frames' directory) where
//   there was nothing or a regular file (or a directory), holding a complete header; a device,
//   pipe, socket or link is never replaced.
#include <fcntl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "tests/fuzz/fuzz_targets.hpp"
#include "tests/fuzz/mutations.hpp"

namespace clothlab::fuzz {
namespace {

namespace fs = std::filesystem;
constexpr int kTimeoutSeconds = 60;

// The input's bytes as a stream of choices; past its end, a generator seeded by its hash.
class Choices {
 public:
  Choices(const std::uint8_t* data, std::size_t size)
      : data_(data), size_(size), random_(hash(data, size)) {}
  std::size_t pick(std::size_t n) { return next_ < size_ ? data_[next_++] % n : random_.below(n); }

 private:
  static std::uint64_t hash(const std::uint8_t* data, std::size_t size) {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a
    for (std::size_t i = 0; i < size; ++i) h = (h ^ data[i]) * 1099511628211ull;
    return h;
  }
  const std::uint8_t* data_;
  std::size_t size_, next_ = 0;
  Random random_;
};

struct Entry {
  fs::file_type type = fs::file_type::none;
  unsigned mode = 0;
  std::string content;  // regular files' bytes, links' targets
  bool operator==(const Entry&) const = default;
};
using Snapshot = std::map<std::string, Entry>;

Snapshot snapshot(const fs::path& root) {
  Snapshot s;
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator();
       ++it) {
    struct stat st {};
    ::lstat(it->path().c_str(), &st);
    Entry e{it->symlink_status().type(), unsigned(st.st_mode), {}};
    if (e.type == fs::file_type::symlink) e.content = fs::read_symlink(it->path()).string();
    if (e.type == fs::file_type::regular) {
      std::ifstream in(it->path(), std::ios::binary);
      e.content.assign(std::istreambuf_iterator<char>(in), {});
    }
    s[it->path().string()] = e;
  }
  return s;
}

void write_text(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

// The entries a path may name; the device node and the socket only where this process may make
// them (mknod needs CAP_MKNOD; a socket's path must fit sockaddr_un).
void prepare(const fs::path& dir) {
  fs::create_directories(dir / "dir");
  fs::create_directories(dir / "ro_dir");
  write_text(dir / "file.csv", "keep me\n");
  write_text(dir / "ro.csv", "read only\n");
  write_text(dir / "dir" / "inner.txt", "inside\n");
  fs::permissions(dir / "ro.csv", fs::perms::owner_read | fs::perms::group_read);
  fs::permissions(dir / "ro_dir", fs::perms::owner_read | fs::perms::owner_exec);
  fs::create_symlink("file.csv", dir / "link_file");
  fs::create_symlink("dir", dir / "link_dir");
  fs::create_symlink("nowhere.csv", dir / "dangling");
  fs::create_symlink("loop", dir / "loop");
  ::mkfifo((dir / "fifo").c_str(), 0644);
  ::mknod((dir / "dev").c_str(), S_IFCHR | 0666, makedev(1, 3));  // /dev/null's numbers
  const std::string sock = (dir / "sock").string();
  sockaddr_un addr{};
  if (sock.size() < sizeof addr.sun_path) {
    addr.sun_family = AF_UNIX;
    sock.copy(addr.sun_path, sock.size());
    const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
    if (fd >= 0) {
      ::bind(fd, reinterpret_cast<const sockaddr*>(&addr), sizeof addr);
      ::close(fd);
    }
  }
}

std::string make_path(Choices& c, const fs::path& dir) {
  static const char* kBases[] = {
      "",     ".",        "..",           "file.csv", "ro.csv",     "dir",
      "dir/", "ro_dir/x", "link_file",    "link_dir", "link_dir/",  "dangling",
      "loop", "fifo",     "dev",          "sock",     "missing/x",  "file.csv/x",
      "new",  "dir/new",  "link_dir/new", "a b é",    "dir/../new", "-dash"};
  static const char* kSuffixes[] = {"", "", ".csv", ".mp4", ".wav", ".tmp", "/", "/x.csv"};
  std::string p = kBases[c.pick(std::size(kBases))];
  p += kSuffixes[c.pick(std::size(kSuffixes))];
  if (c.pick(8) == 0) p += std::string(300, 'n');  // beyond NAME_MAX
  if (c.pick(2) == 0 && !p.empty()) p = (dir / p).string();
  return p;
}

struct Case {
  std::vector<std::string> args;
  std::string option, path;
  bool directory = false;  // render --out: frames in a directory
  std::string magic;       // what a complete file begins with (at offset 4 for MP4's "ftyp")
};

Case make_case(Choices& c, const fs::path& dir, const fs::path& frames) {
  const std::string scenes = context().scene_dir;
  Case k;
  k.path = make_path(c, dir);
  switch (c.pick(4)) {
    case 0:
      k = {{"trace", scenes + "/default.toml", "--duration", "0.01"},
           "--out",
           k.path,
           false,
           "step,"};
      break;
    case 1:
      k = {{"render", scenes + "/default.toml", "--frames", "2", "--size", "32x32"},
           "--video",
           k.path,
           false,
           "ftyp"};
      break;
    case 2:
      k = {{"render", scenes + "/default.toml", "--frames", "1", "--size", "32x32"},
           "--out",
           k.path,
           true,
           ""};
      break;
    default:
      k = {{"render", scenes + "/dance.toml", "--frames", "1", "--size", "32x32", "--out",
            frames.string()},
           "--music-out",
           k.path,
           false,
           "RIFF"};
  }
  k.args.push_back("--quiet");
  if (c.pick(2) == 0) {
    k.args.push_back(k.option + "=" + k.path);
  } else {
    k.args.push_back(k.option);
    k.args.push_back(k.path);
  }
  return k;
}

// Runs the program in `cwd` with its output in `log`; the exit status, or a finding.
int run(const std::vector<std::string>& args, const fs::path& cwd, const fs::path& log) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, 1);
    ::dup2(fd, 2);
    if (::chdir(cwd.c_str()) != 0) ::_exit(127);
    std::vector<char*> argv{const_cast<char*>(context().program.c_str())};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(kTimeoutSeconds);
  int status = 0;
  while (::waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      finding("clothlab ran longer than " + std::to_string(kTimeoutSeconds) + " s");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (WIFSIGNALED(status))
    finding("clothlab was killed by signal " + std::to_string(WTERMSIG(status)));
  return WEXITSTATUS(status);
}

// Where the output lands: the path with its existing links followed, relative to `cwd`.
std::string landing(const std::string& path, const fs::path& cwd) {
  const fs::path p = fs::path(path).is_absolute() ? fs::path(path) : cwd / path;
  std::error_code ec;
  fs::path real = fs::weakly_canonical(p, ec);
  if (ec) real = p.lexically_normal();
  std::string s = real.string();
  while (s.size() > 1 && s.back() == '/') s.pop_back();
  return s;
}

bool allowed_change(const Case& k, const std::string& target, const std::string& path,
                    const Entry* before, const Entry* after) {
  const fs::file_type kind = k.directory ? fs::file_type::directory : fs::file_type::regular;
  if (path == target) return (!before || before->type == kind) && after && after->type == kind;
  // Frames inside the target directory, and parent directories render --out made for it.
  if (k.directory && path.rfind(target + "/", 0) == 0) return true;
  return !before && after && after->type == fs::file_type::directory &&
         target.rfind(path + "/", 0) == 0;
}

void check_outcome(const Case& k, int rc, const std::string& log, const Snapshot& before,
                   const Snapshot& after, const std::string& target) {
  const std::string what = "clothlab " + k.args[0] + " " + k.option + " '" + k.path + "'";
  if (rc != 0 && rc != 1 && rc != 2)
    finding(what + ": exit status " + std::to_string(rc) + "\n" + log);
  if (rc == 2 && log.find(k.option) == std::string::npos)
    finding(what + ": exit 2 without naming " + k.option + "\n" + log);
  std::map<std::string, std::pair<const Entry*, const Entry*>> all;
  for (const auto& [p, e] : before) all[p].first = &e;
  for (const auto& [p, e] : after) all[p].second = &e;
  for (const auto& [p, e] : all) {
    if (e.first && e.second && *e.first == *e.second) continue;
    if (rc == 0 && allowed_change(k, target, p, e.first, e.second)) continue;
    finding(what + ": exit " + std::to_string(rc) + " and '" + p + "' " +
            (!e.first    ? "appeared"
             : !e.second ? "vanished"
                         : "changed") +
            "\n" + log);
  }
  const auto it = after.find(target);
  if (rc != 0 || k.directory || it == after.end()) return;  // written through a link: unseen
  const std::string& bytes = it->second.content;
  const std::size_t at = k.magic == "ftyp" ? 4 : 0;
  if (bytes.compare(at, k.magic.size(), k.magic) != 0)
    finding(what + ": exit 0 but the file does not begin with '" + k.magic + "'");
}

}  // namespace

int fuzz_output_paths(const std::uint8_t* data, std::size_t size) {
  const fs::path root = fs::path(context().scratch_dir) / "outputs";
  const fs::path dir = root / "case", frames = fs::path(context().scratch_dir) / "frames";
  std::error_code ec;
  if (fs::exists(root / "case" / "ro_dir"))
    fs::permissions(root / "case" / "ro_dir", fs::perms::owner_all, ec);
  fs::remove_all(root, ec);
  fs::remove_all(frames, ec);
  prepare(dir);
  Choices choices(data, size);
  const Case k = make_case(choices, dir, frames);
  const Snapshot before = snapshot(root);
  const fs::path log = fs::path(context().scratch_dir) / "outputs.log";
  const int rc = run(k.args, dir, log);
  std::ifstream in(log);
  const std::string text(std::istreambuf_iterator<char>(in), {});

  check_outcome(k, rc, text, before, snapshot(root), landing(k.path, dir));
  return 0;
}

}  // namespace clothlab::fuzz
