// clothlab.render: `clothlab render`'s headless path (EGL, the window's renderer) into a numpy
// image, with the display mode and the scientific views `render`'s options set.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "factory/solver_factory.hpp"
#include "python/bindings/bindings.hpp"
#include "sim/fields/frame_fields.hpp"
#include "sim/scene/name_list.hpp"
#include "sim/solver.hpp"
#include "vis/colormap/colormap.hpp"
#include "vis/render/headless_renderer.hpp"
#include "vis/render/scalar_field.hpp"
#include "vis/render/view_settings.hpp"

namespace py = pybind11;

namespace clothlab::py_bindings {

namespace {

// The element of `all` named `name` by `name_of`, or a ValueError listing the names.
template <class T, std::size_t N, class NameOf>
T by_name(const std::array<T, N>& all, NameOf name_of, const std::string& name, const char* what) {
  for (const T& item : all)
    if (name_of(item) == name) return item;
  throw py::value_error(std::string("clothlab.render: unknown ") + what + " '" + name + "' (" +
                        comma_list(all, name_of) + ")");
}

struct ViewOptions {
  int mode = 3;
  std::optional<std::string> color_by, colormap, force_source;
  std::vector<std::string> arrows;
};

void apply(const ViewOptions& o, vis::ViewSettings& view) {
  if (o.mode < 1 || o.mode > 9)
    throw py::value_error("clothlab.render: mode must be 1 to 9 (got " + std::to_string(o.mode) +
                          ")");
  view.mode = static_cast<vis::DisplayMode>(o.mode);
  if (o.color_by)
    view.color.field =
        by_name(vis::kColourScalars, vis::scalar_field_name, *o.color_by, "color_by");
  if (o.colormap)
    view.color.map = by_name(vis::kAllColorMaps, vis::colormap_name, *o.colormap, "colormap");
  if (o.force_source) {
    view.force_source =
        by_name(kAllForceSources, force_source_name, *o.force_source, "force_source");
    view.springs_at_rest = false;
  }
  for (const std::string& a : o.arrows) {
    if (a == "force")
      view.arrows.force = true;
    else if (a == "normals")
      view.arrows.normals = true;
    else
      throw py::value_error("clothlab.render: unknown arrows '" + a + "' (force, normals)");
  }
}

// Frame 0 is the initial state, each later one 1 / fps of simulated time more (as `render`);
// returns the last frame as (height, width, 3) uint8.
py::array_t<std::uint8_t> render(const SceneSource& source, int frames, std::pair<int, int> size,
                                 double fps, const ViewOptions& options) {
  const auto [width, height] = size;
  if (frames < 1) throw py::value_error("clothlab.render: frames must be >= 1");
  if (width < 1 || height < 1 || width > 8192 || height > 8192)
    throw py::value_error("clothlab.render: size must be 1 to 8192 pixels a side");
  if (!(fps > 0.0)) throw py::value_error("clothlab.render: fps must be > 0");
  const Scene scene = source.load();
  std::vector<std::uint8_t> rgba;
  {
    py::gil_scoped_release release;
    vis::HeadlessRenderer renderer(width, height);  // first: a GPU scene steps in its context
    std::string note;
    const auto solver = make_backend_solver(scene, note);
    renderer.set_cloth(*solver);
    renderer.set_scene(scene.render, *solver, scene.colliders);
    vis::ViewSettings view = vis::scene_view(scene, *solver);
    apply(options, view);
    FieldSnapshot snapshot;
    for (int frame = 1; frame < frames; ++frame) {
      const AdvanceResult r = solver->advance(1.0 / fps);
      if (r.divergence) {
        py::gil_scoped_acquire gil;
        raise_divergence(*r.divergence);
      }
    }
    rgba = renderer.render(*solver, snapshot.take(*solver, renderer.request(view)), view);
  }
  py::array_t<std::uint8_t> out({py::ssize_t(height), py::ssize_t(width), py::ssize_t(3)});
  auto w = out.mutable_unchecked<3>();
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) w(y, x, c) = rgba[(std::size_t(y) * width + x) * 4 + c];
  return out;
}

}  // namespace

void bind_render(py::module_& m) {
  m.def(
      "_render",
      [](const SceneSource& scene, int frames, std::pair<int, int> size, double fps, int mode,
         std::optional<std::string> color_by, std::optional<std::string> colormap,
         std::optional<std::string> force_source, std::vector<std::string> arrows) {
        return render(scene, frames, size, fps,
                      ViewOptions{mode, color_by, colormap, force_source, arrows});
      },
      py::arg("scene"), py::arg("frames"), py::arg("size"), py::arg("fps"), py::arg("mode"),
      py::arg("color_by"), py::arg("colormap"), py::arg("force_source"), py::arg("arrows"));
}

}  // namespace clothlab::py_bindings
