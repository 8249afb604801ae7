// Paths the programs write to (apps/clothlab/output_path.hpp): an empty path, a directory where
// a file is wanted, a symbolic link and a pipe are refused when the command line is read (exit
// 2, the option and the reason named), and what the path named is left as it was, with nothing
// written beside it. (A device node needs root to make; a pipe takes the same branch.)
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

struct Outcome {
  int rc = -1;
  std::string err;
};

// `clothlab ARGS` in `dir`, stderr captured.
Outcome clothlab(const fs::path& dir, const std::string& args) {
  const fs::path err = dir / "stderr.txt";
  const std::string cmd = "cd '" + dir.string() + "' && '" + std::string(CLOTHLAB_BINARY) + "' " +
                          args + " >/dev/null 2>'" + err.string() + "'";
  const int status = std::system(cmd.c_str());
  std::ifstream in(err);
  std::ostringstream text;
  text << in.rdbuf();
  fs::remove(err);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

class OutputPaths : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("clothlab_output_paths_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "folder");
    std::ofstream(dir_ / "real.csv") << "keep me\n";
    fs::create_symlink("real.csv", dir_ / "link.csv");
    ASSERT_EQ(::mkfifo((dir_ / "pipe").c_str(), 0644), 0);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // The scratch directory holds exactly what SetUp made, each of its kind, real.csv unchanged.
  void expect_untouched() const {
    int entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir_)) ++entries;
    EXPECT_EQ(entries, 4) << "a file was written beside the refused path";
    EXPECT_TRUE(fs::is_symlink(dir_ / "link.csv"));
    EXPECT_TRUE(fs::is_fifo(dir_ / "pipe"));
    EXPECT_TRUE(fs::is_directory(dir_ / "folder"));
    std::ifstream in(dir_ / "real.csv");
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "keep me");
  }

  fs::path dir_;
  const std::string scene_ = "'" CLOTHLAB_SOURCE_DIR "/scenes/default.toml'";
};

TEST_F(OutputPaths, TraceRefusesEmptyDirectoryLinkAndPipe) {
  const std::string trace = "trace " + scene_ + " --duration 0.01 --out ";
  const struct {
    std::string path, says;
  } cases[] = {{"''", "--out: an empty path"},
               {"folder", "--out: 'folder' is a directory"},
               {"link.csv", "--out: 'link.csv' is a symbolic link"},
               {"pipe", "--out: 'pipe' is a device, pipe or socket"}};
  for (const auto& c : cases) {
    const Outcome r = clothlab(dir_, trace + c.path);
    EXPECT_EQ(r.rc, 2) << c.path << ": " << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
  }
  expect_untouched();
}

TEST_F(OutputPaths, RenderAndBenchRefuseThemToo) {
  const std::string render = "render " + scene_ + " --frames 1 --quiet ";
  const struct {
    std::string args, says;
  } cases[] = {{render + "--video ''", "--video: an empty path"},
               {render + "--video folder", "--video: 'folder' is a directory"},
               {render + "--video pipe", "--video: 'pipe' is a device, pipe or socket"},
               {render + "--out folder --music-out ''", "--music-out: an empty path"},
               {render + "--out folder --music-out link.csv", "--music-out: 'link.csv' is a symb"},
               {render + "--out ''", "--out: an empty path"},
               {"bench --suite accuracy --quick --out ''", "--out: an empty path"},
               {"bench --suite accuracy --quick --out pipe", "--out: 'pipe' is a device"}};
  for (const auto& c : cases) {
    const Outcome r = clothlab(dir_, c.args);
    EXPECT_EQ(r.rc, 2) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << ": " << r.err;
  }
  expect_untouched();
}

// The check is not a blanket refusal: a regular file is overwritten (through a temporary file
// renamed over it), a new name in the directory is created, and a link to a directory is taken
// where a directory is (render's frames go inside it).
TEST_F(OutputPaths, TraceWritesARegularFileAndANewOneRenderALinkedDirectory) {
  fs::create_directory_symlink("folder", dir_ / "frames");
  const Outcome r =
      clothlab(dir_, "render " + scene_ + " --frames 1 --size 64x64 --quiet --out frames");
  EXPECT_EQ(r.rc, 0) << r.err;
  EXPECT_TRUE(fs::is_regular_file(dir_ / "folder/frame_00000.png"));
  EXPECT_EQ(clothlab(dir_, "trace " + scene_ + " --duration 0.01 --out real.csv").rc, 0);
  EXPECT_EQ(clothlab(dir_, "trace " + scene_ + " --duration 0.01 --out folder/new.csv").rc, 0);
  std::ifstream in(dir_ / "real.csv");
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header.rfind("step,time", 0), 0u) << header;
  EXPECT_TRUE(fs::is_regular_file(dir_ / "folder/new.csv"));
}

}  // namespace
