// Every design note the code cites exists, with the section it names: `docs/NAME.md` must be a
// file, `docs/NAME.md "Title"` (or `, "Title"`) must find the title in it, and `docs/NAME.md
// section N` a heading numbered N. Comments wrap, so a citation may run over the next comment
// line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The citations in `text` (comment continuations joined) that do not resolve under `root`.
std::vector<std::string> broken_citations(const std::string& text, const fs::path& root) {
  const std::string joined = std::regex_replace(text, std::regex(R"(\n\s*(//|#)\s*)"), " ");
  const std::regex cite(R"re((docs/[a-z_-]+\.md)(?:,?\s*\(?\s*(?:"([^"\n]+)"|section (\d+)))?)re");
  std::vector<std::string> bad;
  for (std::sregex_iterator m(joined.begin(), joined.end(), cite), end; m != end; ++m) {
    const fs::path doc = root / (*m)[1].str();
    if (!fs::exists(doc)) {
      bad.push_back((*m)[0].str() + ": no such note");
      continue;
    }
    const std::string note = read(doc);
    if ((*m)[2].matched && note.find((*m)[2].str()) == std::string::npos)
      bad.push_back((*m)[0].str() + ": no such section");
    if ((*m)[3].matched &&
        !std::regex_search(note, std::regex("(^|\n)#+ " + (*m)[3].str() + "\\.")))
      bad.push_back((*m)[0].str() + ": no such numbered section");
  }
  return bad;
}

bool is_source(const fs::path& p) {
  static const std::vector<std::string> kinds = {".cpp", ".hpp",  ".toml", ".txt",  ".cmake",
                                                 ".py",  ".glsl", ".comp", ".frag", ".vert"};
  for (const std::string& k : kinds)
    if (p.extension() == k) return true;
  return p.parent_path().filename() == "scripts";
}

TEST(DocCitations, EveryCitedNoteAndSectionExists) {
  const fs::path root = CLOTHLAB_SOURCE_DIR;
  int files = 0;
  for (const char* folder : {"sim", "gl", "gpu", "vis", "apps", "bench", "load", "music", "tests",
                             "shaders", "scenes", "scripts", "cmake", "python"}) {
    for (const auto& e : fs::recursive_directory_iterator(root / folder)) {
      if (!e.is_regular_file() || !is_source(e.path())) continue;
      if (e.path().filename() == "doc_citations_test.cpp") continue;  // its own broken examples
      ++files;
      for (const std::string& b : broken_citations(read(e.path()), root))
        ADD_FAILURE() << fs::relative(e.path(), root).string() << ": " << b;
    }
  }
  EXPECT_GT(files, 300);
}

TEST(DocCitations, TheCheckFindsBrokenOnes) {
  const fs::path root = CLOTHLAB_SOURCE_DIR;
  EXPECT_TRUE(
      broken_citations("// see docs/solver.md, \"Small steps\n// at scale\"", root).empty());
  EXPECT_EQ(broken_citations("// docs/nowhere.md", root).size(), 1u);
  EXPECT_EQ(broken_citations("// docs/solver.md \"A section it lacks\"", root).size(), 1u);
  EXPECT_EQ(broken_citations("// docs/rendering.md section 99", root).size(), 1u);
  EXPECT_TRUE(broken_citations("// docs/rendering.md section 1", root).empty());
}

}  // namespace
