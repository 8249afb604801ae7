// The folders' includes point down the data flow (docs/design.md, "Layout"): sim/ (physics) <-
// gl/ (the GL foundation) <- gpu/ (the GPU step) <- factory/ (the solver factory), and vis/ (the
// renderer) on sim/ and gl/, <- bench/ <- apps/, with music/ and load/ (the files a scene names)
// on sim/, and tune/ (`clothlab tune`) on load/ and vis/, below apps/ and python/. A file may
// include its own folder and the folders below it, never one beside or above it. And the renderer
// reads the solver: no header under vis/ takes a mutable solver (docs/design.md, "One field
// snapshot per frame"). Raw GL calls stay in gl/, the passes' draw code (vis/passes/) and the GPU
// step's dispatches (gpu/); GL objects are made and deleted only by gl/'s RAII wrappers.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// What each folder may include besides itself.
const std::map<std::string, std::set<std::string>>& allowed() {
  static const std::map<std::string, std::set<std::string>> table = {
      {"sim", {}},
      {"music", {"sim"}},
      {"load", {"sim", "music"}},
      {"gl", {}},
      {"gpu", {"sim", "gl"}},
      {"factory", {"sim", "gl", "gpu"}},
      {"vis", {"sim", "gl"}},
      {"bench", {"sim", "music", "load", "gl", "gpu", "factory", "vis"}},
      {"tune", {"sim", "music", "load", "gl", "vis"}},
      {"apps", {"sim", "music", "load", "gl", "gpu", "factory", "vis", "bench", "tune"}},
      {"python", {"sim", "music", "load", "gl", "gpu", "factory", "vis", "tune"}},
  };
  return table;
}

// Every include of a folder that `folder` may not include, in the C++ files under root/folder,
// as "file -> line".
std::vector<std::string> upward_includes(const fs::path& root, const std::string& folder) {
  const std::set<std::string>& ok = allowed().at(folder);
  const std::regex include(R"re(^\s*#\s*include\s*"([a-z_]+)/)re");
  std::vector<std::string> bad;
  for (const auto& entry : fs::recursive_directory_iterator(root / folder)) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".cpp" && ext != ".hpp") continue;
    std::ifstream in(entry.path());
    std::string line;
    while (std::getline(in, line)) {
      std::smatch m;
      if (!std::regex_search(line, m, include)) continue;
      const std::string target = m[1];
      if (target == folder || !allowed().count(target) || ok.count(target)) continue;
      bad.push_back(fs::relative(entry.path(), root).string() + " -> " + line);
    }
  }
  return bad;
}

TEST(Layering, NoFolderIncludesOneBesideOrAboveIt) {
  for (const auto& [folder, ok] : allowed()) {
    const std::vector<std::string> bad = upward_includes(CLOTHLAB_SOURCE_DIR, folder);
    EXPECT_TRUE(bad.empty()) << bad.size() << " includes out of " << folder << "/, e.g. "
                             << bad.front();
  }
}

// Every include of sim/<folder> other than `ok` in the C++ files under root/sim/<from>, as
// "file -> line".
std::vector<std::string> sim_includes_beyond(const fs::path& root, const std::string& from,
                                             const std::set<std::string>& ok) {
  const std::regex include(R"re(^\s*#\s*include\s*"sim/([a-z_]+)/)re");
  std::vector<std::string> bad;
  for (const auto& entry : fs::recursive_directory_iterator(root / "sim" / from)) {
    std::ifstream in(entry.path());
    std::string line;
    while (std::getline(in, line)) {
      std::smatch m;
      if (std::regex_search(line, m, include) && !ok.count(m[1]))
        bad.push_back(fs::relative(entry.path(), root).string() + " -> " + line);
    }
  }
  return bad;
}

// The scene layer (parsing and checking scene files) reads scene data, vectors and meshes; it
// never reaches up to what is built from a scene (cloth builders, the model, the solver).
TEST(Layering, TheSceneLayerIncludesOnlyCoreAndMesh) {
  const std::vector<std::string> bad =
      sim_includes_beyond(CLOTHLAB_SOURCE_DIR, "scene", {"scene", "core", "mesh"});
  EXPECT_TRUE(bad.empty()) << bad.size() << " includes out of sim/scene/, e.g. " << bad.front();
  const fs::path root = fs::temp_directory_path() / "clothlab_scene_layering_test";
  fs::remove_all(root);
  fs::create_directories(root / "sim/scene");
  std::ofstream(root / "sim/scene/a.cpp")
      << "#include \"sim/mesh/mesh_edges.hpp\"\n#include \"sim/cloth/mesh_cloth.hpp\"\n";
  const std::vector<std::string> found = sim_includes_beyond(root, "scene", {"scene", "mesh"});
  fs::remove_all(root);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0], "sim/scene/a.cpp -> #include \"sim/cloth/mesh_cloth.hpp\"");
}

// The scan finds a renderer file that includes the GPU backend, and passes one on the GL layer.
TEST(Layering, TheScanFindsAnIncludeBesideItsFolder) {
  const fs::path root = fs::temp_directory_path() / "clothlab_layering_test";
  fs::remove_all(root);
  fs::create_directories(root / "vis/render");
  std::ofstream(root / "vis/render/a.cpp") << "#include \"gl/objects.hpp\"\n";
  std::ofstream(root / "vis/render/b.hpp")
      << "#include <vector>\n  #include \"gpu/gpu_step.hpp\"\n";
  const std::vector<std::string> bad = upward_includes(root, "vis");
  fs::remove_all(root);
  ASSERT_EQ(bad.size(), 1u);
  EXPECT_EQ(bad[0], "vis/render/b.hpp ->   #include \"gpu/gpu_step.hpp\"");
}

// Every mention of a solver role (Solver, SolverState, SolverStepping, SolverInteraction) or of
// the device cloth by a non-const reference or pointer in the headers under root/folder, as
// "file:line: text". Comment lines are skipped.
std::vector<std::string> mutable_solver_uses(const fs::path& root, const std::string& folder) {
  const std::regex use(
      R"re(\b(const\s+)?(Solver|SolverState|SolverStepping|SolverInteraction|DeviceCloth)\s*[&*])re");
  const std::regex comment(R"re(^\s*//)re");
  std::vector<std::string> bad;
  for (const auto& entry : fs::recursive_directory_iterator(root / folder)) {
    if (entry.path().extension() != ".hpp") continue;
    std::ifstream in(entry.path());
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      if (std::regex_search(line, comment)) continue;
      for (std::sregex_iterator m(line.begin(), line.end(), use), end; m != end; ++m) {
        if ((*m)[1].matched) continue;
        bad.push_back(fs::relative(entry.path(), root).string() + ":" + std::to_string(number) +
                      ": " + line);
        break;
      }
    }
  }
  return bad;
}

TEST(Layering, TheRendererTakesTheSolverAsConst) {
  const std::vector<std::string> bad = mutable_solver_uses(CLOTHLAB_SOURCE_DIR, "vis");
  EXPECT_TRUE(bad.empty()) << bad.size() << " mutable solver uses in vis/ headers, e.g. "
                           << bad.front();
}

// The scan finds a mutable solver parameter beside const ones, and skips comments.
TEST(Layering, TheScanFindsAMutableSolver) {
  const fs::path root = fs::temp_directory_path() / "clothlab_layering_const_test";
  fs::remove_all(root);
  fs::create_directories(root / "vis/render");
  std::ofstream(root / "vis/render/a.hpp")
      << "void f(const SolverState& s, const Solver* p);\n// g(Solver& s) in a comment\n"
         "void g(const FrameFields& f, Solver &s);\nconst DeviceCloth* d;\n";
  const std::vector<std::string> bad = mutable_solver_uses(root, "vis");
  fs::remove_all(root);
  ASSERT_EQ(bad.size(), 1u);
  EXPECT_EQ(bad[0], "vis/render/a.hpp:3: void g(const FrameFields& f, Solver &s);");
}

// Every raw GL call (gl + capital, then an opening parenthesis) in the C++ files under
// root/folder outside the subfolders `allowed`, as "file:line: text"; with `objects_only`, only
// calls that create or delete GL objects (glCreate*, glGen* but glGenerate*, glDelete*).
std::vector<std::string> raw_gl_calls(const fs::path& root, const std::string& folder,
                                      const std::vector<std::string>& allowed, bool objects_only) {
  const std::regex call(objects_only ? R"re(\bgl(Create|Delete|Gen(?!erate))[A-Z]\w*\s*\()re"
                                     : R"re(\bgl[A-Z]\w*\s*\()re");
  const std::regex comment(R"re(^\s*//)re");
  std::vector<std::string> bad;
  if (!fs::exists(root / folder)) return bad;
  for (const auto& entry : fs::recursive_directory_iterator(root / folder)) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".cpp" && ext != ".hpp") continue;
    const std::string rel = fs::relative(entry.path(), root).string();
    bool exempt = false;
    for (const std::string& a : allowed) exempt = exempt || rel.rfind(a + "/", 0) == 0;
    if (exempt) continue;
    std::ifstream in(entry.path());
    std::string line;
    for (int number = 1; std::getline(in, line); ++number)
      if (!std::regex_search(line, comment) && std::regex_search(line, call))
        bad.push_back(rel + ":" + std::to_string(number) + ": " + line);
  }
  return bad;
}

TEST(Layering, RawGlCallsStayInGlPassesAndTheGpuStep) {
  for (const std::string folder : {"sim", "music", "load", "factory", "vis", "bench", "apps"}) {
    const std::vector<std::string> bad =
        raw_gl_calls(CLOTHLAB_SOURCE_DIR, folder, {"vis/passes"}, false);
    EXPECT_TRUE(bad.empty()) << bad.size() << " raw GL calls in " << folder << "/, e.g. "
                             << bad.front();
  }
}

TEST(Layering, GlObjectsComeOnlyFromTheRaiiWrappers) {
  for (const std::string folder : {"vis", "gpu", "bench", "apps"}) {
    const std::vector<std::string> bad = raw_gl_calls(CLOTHLAB_SOURCE_DIR, folder, {}, true);
    EXPECT_TRUE(bad.empty()) << bad.size() << " GL objects made by hand in " << folder << "/, e.g. "
                             << bad.front();
  }
}

// The scans find a call outside the passes (not glfw's, not in a comment), and a sampler made
// by hand in a pass but not a mipmap generated there.
TEST(Layering, TheScanFindsRawGlCalls) {
  const fs::path root = fs::temp_directory_path() / "clothlab_layering_gl_test";
  fs::remove_all(root);
  fs::create_directories(root / "vis/render");
  fs::create_directories(root / "vis/passes");
  std::ofstream(root / "vis/render/a.cpp")
      << "glfwPollEvents();\n// glEnable(GL_BLEND);\n  glEnable (GL_BLEND);\n";
  std::ofstream(root / "vis/passes/b.cpp")
      << "glGenerateTextureMipmap(t);\nglCreateSamplers(1, &s);\nglDrawArrays(m, 0, 3);\n";
  const std::vector<std::string> calls = raw_gl_calls(root, "vis", {"vis/passes"}, false);
  const std::vector<std::string> objects = raw_gl_calls(root, "vis", {}, true);
  fs::remove_all(root);
  ASSERT_EQ(calls.size(), 1u);
  EXPECT_EQ(calls[0], "vis/render/a.cpp:3:   glEnable (GL_BLEND);");
  ASSERT_EQ(objects.size(), 1u);
  EXPECT_EQ(objects[0], "vis/passes/b.cpp:2: glCreateSamplers(1, &s);");
}

}  // namespace
