// `clothlab view [SCENE] [--set k=v]...`: parses the scene, then hands it to the interactive
// window (apps/view/view_app.hpp). Only wiring and the mapping of errors to exit statuses.
#include <cstdio>
#include <exception>

#include "apps/clothlab/commands.hpp"
#include "apps/view/view_app.hpp"
#include "gl/gl_error.hpp"
#include "sim/scene/scene_parser.hpp"

namespace clothlab::app {

int run_view(const ViewArgs& args) {
  const std::string path = args.scene.empty() ? std::string(CLOTHLAB_DEFAULT_SCENE) : args.scene;
  std::optional<Scene> loaded = load_scene_to_run("view", path, args.overrides, false);
  if (!loaded) return kBadInput;
  Scene& scene = *loaded;
  try {
    vis::ViewApp app(std::move(scene), vis::ViewHooks::from_environment());
    if (args.copies > 1) app.change_copies(args.copies);
    return app.run();
  } catch (const SceneError& e) {  // the scene parsed but the solver could not be built from it
    std::fprintf(stderr, "clothlab view: %s\n", e.what());
    return 2;
  } catch (const vis::GlUnavailable& e) {
    std::fprintf(stderr, "clothlab view: %s\n", e.what());
    return 1;
  } catch (const vis::ShaderError& e) {
    std::fprintf(stderr, "clothlab view: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {  // e.g. a screenshot that could not be written
    std::fprintf(stderr, "clothlab view: %s\n", e.what());
    return 1;
  }
}

}  // namespace clothlab::app
