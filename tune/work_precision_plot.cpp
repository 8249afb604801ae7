#include "tune/work_precision_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

#include "vis/textures/image.hpp"

// stb_easy_font is a header of static C functions; some go unused here and it casts freely.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_easy_font.h>
#pragma GCC diagnostic pop

namespace clothlab::tune {

namespace {

struct Rgb {
  float r, g, b;
};

constexpr int kWidth = 1000, kHeight = 660;
constexpr int kLeft = 110, kRight = 740, kTop = 50, kBottom = 580;  // the plot area
constexpr int kTextScale = 2;

struct Canvas {
  Image image{kWidth, kHeight};
  Canvas() { fill(0, 0, kWidth, kHeight, {1, 1, 1}); }
  void fill(int x0, int y0, int x1, int y1, Rgb c) {
    for (int y = std::max(0, y0); y < std::min(kHeight, y1); ++y)
      for (int x = std::max(0, x0); x < std::min(kWidth, x1); ++x)
        image.set_rgb(x, y, c.r, c.g, c.b);
  }
  void disk(double cx, double cy, double radius, Rgb c, double inner = 0.0) {
    for (int y = int(cy - radius); y <= int(cy + radius) + 1; ++y)
      for (int x = int(cx - radius); x <= int(cx + radius) + 1; ++x) {
        const double d = std::hypot(x - cx, y - cy);
        if (d <= radius && d >= inner) fill(x, y, x + 1, y + 1, c);
      }
  }
  // A line two pixels wide; `dash` > 0 leaves gaps of that many pixels.
  void line(double x0, double y0, double x1, double y1, Rgb c, int dash = 0) {
    const int n = int(std::max(std::abs(x1 - x0), std::abs(y1 - y0))) + 1;
    for (int i = 0; i <= n; ++i) {
      if (dash > 0 && (i / dash) % 2 == 1) continue;
      const double t = double(i) / n;
      const int x = int(std::lround(x0 + t * (x1 - x0))), y = int(std::lround(y0 + t * (y1 - y0)));
      fill(x, y, x + 2, y + 2, c);
    }
  }
  // Text with its top left corner at (x, y); returns its width in pixels.
  int text(int x, int y, const std::string& s, Rgb c) {
    std::vector<char> buffer(s.size() * 300 + 64);
    std::string copy = s;
    const int quads =
        stb_easy_font_print(0, 0, copy.data(), nullptr, buffer.data(), int(buffer.size()));
    const float* v = reinterpret_cast<const float*>(buffer.data());
    for (int q = 0; q < quads; ++q) {
      const float* a = v + q * 16;  // four vertices of x, y, z and a packed colour
      const float* b = a + 8;
      fill(x + int(a[0] * kTextScale), y + int(a[1] * kTextScale), x + int(b[0] * kTextScale),
           y + int(b[1] * kTextScale), c);
    }
    return stb_easy_font_width(copy.data()) * kTextScale;
  }
};

// Decades spanned by positive values (at least one).
struct LogRange {
  double lo = 0.0, hi = 1.0;  // log10
  void cover(double v) {
    if (!(v > 0.0) || !std::isfinite(v)) return;
    lo = std::min(lo, std::floor(std::log10(v)));
    hi = std::max(hi, std::ceil(std::log10(v)));
  }
};

struct Axes {
  LogRange x, y;
  double px(double cost) const {
    return kLeft + (std::log10(cost) - x.lo) / (x.hi - x.lo) * (kRight - kLeft);
  }
  double py(double error) const {
    return kBottom - (std::log10(std::max(error, 1e-12)) - y.lo) / (y.hi - y.lo) * (kBottom - kTop);
  }
};

Rgb family_colour(const std::string& family) {
  static const std::map<std::string, Rgb> colours = {{"explicit", {0.12f, 0.47f, 0.71f}},
                                                     {"implicit", {1.0f, 0.5f, 0.05f}},
                                                     {"constraints", {0.17f, 0.63f, 0.17f}},
                                                     {"descent", {0.58f, 0.40f, 0.74f}}};
  const auto it = colours.find(family);
  return it == colours.end() ? Rgb{0.3f, 0.3f, 0.3f} : it->second;
}

Axes axes_for(const Result& r, const PlotLabels& labels) {
  Axes a;
  a.x = {1e9, -1e9};
  a.y = {1e9, -1e9};
  a.x.cover(1.0);  // real time is always shown
  a.x.cover(r.reference.cost);
  if (labels.tolerance) a.y.cover(*labels.tolerance);
  for (const Row& row : r.rows)
    if (row.ok()) {
      a.x.cover(row.cost);
      a.y.cover(std::max(row.worst_rms(), 1e-9));
    }
  // The reference's own error may lie far below every candidate: a decade below them at most
  // (its line is then drawn at the bottom, labelled as below).
  const double below = a.y.lo - 1.0;
  a.y.cover(std::max(r.reference.worst_self(), 1e-9));
  a.y.lo = std::max(a.y.lo, below);
  if (a.y.hi <= a.y.lo) a.y.hi = a.y.lo + 1;
  return a;
}

std::string decade(double exponent, double scale, const char* unit) {
  char text[32];
  std::snprintf(text, sizeof text, "%g%s", std::pow(10.0, exponent) * scale, unit);
  return text;
}

void draw_grid(Canvas& c, const Axes& a) {
  const Rgb grid{0.88f, 0.88f, 0.88f}, ink{0.1f, 0.1f, 0.1f};
  for (double e = a.x.lo; e <= a.x.hi + 1e-9; e += 1.0) {
    const double x = a.px(std::pow(10.0, e));
    c.line(x, kTop, x, kBottom, grid);
    const std::string label = decade(e, 1.0, "");
    c.text(int(x) - 4 * int(label.size()), kBottom + 10, label, ink);
  }
  for (double e = a.y.lo; e <= a.y.hi + 1e-9; e += 1.0) {
    const double y = a.py(std::pow(10.0, e));
    c.line(kLeft, y, kRight, y, grid);
    const std::string label = decade(e, 1e3, " mm");
    c.text(kLeft - 12 - 10 * int(label.size()), int(y) - 7, label, ink);
  }
  c.line(kLeft, kTop, kLeft, kBottom, ink);
  c.line(kLeft, kBottom, kRight, kBottom, ink);
  c.text(kLeft + 120, kBottom + 40,
         "wall time per simulated second (s; left of 1 is faster than real time)", ink);
}

void draw_guides(Canvas& c, const Axes& a, const Result& r, const PlotLabels& labels) {
  const double rt = a.px(1.0);
  c.line(rt, kTop, rt, kBottom, {0.4f, 0.4f, 0.4f}, 6);
  c.text(int(rt) - 100, kTop + 6, "real time", {0.4f, 0.4f, 0.4f});
  const double self = std::min(a.py(std::max(r.reference.worst_self(), 1e-12)), double(kBottom));
  c.line(kLeft, self, kRight, self, {0.5f, 0.5f, 0.5f}, 3);
  c.text(kLeft + 6, int(self) - 20,
         self >= kBottom ? "the reference's own error (below)" : "the reference's own error",
         {0.5f, 0.5f, 0.5f});
  if (labels.tolerance) {
    const double y = a.py(*labels.tolerance);
    c.line(kLeft, y, kRight, y, {0.84f, 0.15f, 0.16f}, 8);
    c.text(kLeft + 6, int(y) - 20, "tolerance", {0.84f, 0.15f, 0.16f});
  }
}

void draw_points(Canvas& c, const Axes& a, const Result& r, const PlotLabels& labels) {
  const std::vector<std::size_t> front = frontier(r.rows);
  for (std::size_t k = 1; k < front.size(); ++k) {
    const Row &p = r.rows[front[k - 1]], &q = r.rows[front[k]];
    c.line(a.px(p.cost), a.py(p.worst_rms()), a.px(q.cost), a.py(q.worst_rms()),
           {0.2f, 0.2f, 0.2f});
  }
  for (const Row& row : r.rows)
    if (row.ok())
      c.disk(a.px(row.cost), a.py(row.worst_rms()), 6, family_colour(row.setting.family));
  if (labels.chosen)
    c.disk(a.px(r.rows[*labels.chosen].cost), a.py(r.rows[*labels.chosen].worst_rms()), 12,
           {0.84f, 0.15f, 0.16f}, 9);
  const double rx = a.px(r.reference.cost);
  const double ry = std::min(a.py(std::max(r.reference.worst_self(), 1e-12)), double(kBottom));
  c.fill(int(rx) - 6, int(ry) - 6, int(rx) + 7, int(ry) + 7, {0, 0, 0});
}

void draw_legend(Canvas& c) {
  const Rgb ink{0.1f, 0.1f, 0.1f};
  int y = kTop + 10;
  for (const char* family : {"explicit", "implicit", "constraints", "descent"}) {
    c.disk(kRight + 50, y + 7, 6, family_colour(family));
    c.text(kRight + 65, y, family, ink);
    y += 30;
  }
  c.fill(kRight + 44, y + 1, kRight + 57, y + 14, {0, 0, 0});
  c.text(kRight + 65, y, "reference", ink);
  y += 30;
  c.disk(kRight + 50, y + 7, 12, {0.84f, 0.15f, 0.16f}, 9);
  c.text(kRight + 65, y, "recommended", ink);
  c.text(kRight + 40, y + 40, "line: the frontier", ink);
}

}  // namespace

void write_work_precision_plot(const Result& result, const PlotLabels& labels,
                               const std::string& path) {
  Canvas c;
  const Axes a = axes_for(result, labels);
  draw_grid(c, a);
  draw_guides(c, a, result, labels);
  draw_points(c, a, result, labels);
  draw_legend(c);
  const Rgb ink{0.1f, 0.1f, 0.1f};
  c.text(kLeft, 6, labels.title, ink);
  c.text(10, kTop - 22, "worst RMS distance from the reference", ink);
  write_png(c.image, path);
}

}  // namespace clothlab::tune
