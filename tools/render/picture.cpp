#include "picture.h"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "hexadapt/core/error.h"
#include "hexadapt/io/atomic_file.h"

namespace hexadapt::render {
namespace {

constexpr double margin = 12;        // pixels around the plot
constexpr double panel_width = 170;  // pixels of the legend / colour bar column
constexpr double title_height = 22;

// Maps plane coordinates to pixels, same scale on both axes, y up.
struct View {
  double scale = 1, ox = 0, oy = 0;
  double x(double px) const { return ox + scale * px; }
  double y(double py) const { return oy - scale * py; }
};

View fit(const Window& w, double left, double top, double width, double height) {
  View v;
  const double dx = std::max(w.x1 - w.x0, 1e-300), dy = std::max(w.y1 - w.y0, 1e-300);
  v.scale = std::min(width / dx, height / dy);
  v.ox = left + 0.5 * (width - v.scale * dx) - v.scale * w.x0;
  v.oy = top + 0.5 * (height + v.scale * dy) + v.scale * w.y0;
  return v;
}

void trace(cairo_t* cr, const View& v, const Polygon& p) {
  cairo_move_to(cr, v.x(p.points[0][0]), v.y(p.points[0][1]));
  for (std::size_t i = 1; i < p.points.size(); ++i)
    cairo_line_to(cr, v.x(p.points[i][0]), v.y(p.points[i][1]));
  cairo_close_path(cr);
}

bool visible(const Polygon& p, const Window& w) {
  double x0 = p.points[0][0], x1 = x0, y0 = p.points[0][1], y1 = y0;
  for (const auto& q : p.points) {
    x0 = std::min(x0, q[0]), x1 = std::max(x1, q[0]);
    y0 = std::min(y0, q[1]), y1 = std::max(y1, q[1]);
  }
  return x1 >= w.x0 && x0 <= w.x1 && y1 >= w.y0 && y0 <= w.y1;
}

void set_rgb(cairo_t* cr, const Rgb& c) { cairo_set_source_rgb(cr, c[0], c[1], c[2]); }

// Mean width in pixels of the visible cells (square root of their mean bounding-box area).
double mean_cell_pixels(const View& v, const Window& w, const Picture& pic) {
  double area = 0;
  int n = 0;
  for (const Polygon& p : pic.polygons) {
    if (!visible(p, w)) continue;
    double x0 = p.points[0][0], x1 = x0, y0 = p.points[0][1], y1 = y0;
    for (const auto& q : p.points) {
      x0 = std::min(x0, q[0]), x1 = std::max(x1, q[0]);
      y0 = std::min(y0, q[1]), y1 = std::max(y1, q[1]);
    }
    area += (x1 - x0) * (y1 - y0);
    ++n;
  }
  return n ? v.scale * std::sqrt(area / n) : 0;
}

void draw_cells(cairo_t* cr, const View& v, const Window& w, const Picture& pic, bool edges,
                const Progress& progress) {
  const double edge_width = 0.6;
  const std::size_t n = pic.polygons.size(), step = std::max<std::size_t>(4096, n / 100);
  for (std::size_t i = 0; i < n; ++i) {
    // Filling dominates the drawing: the cells are 0.9 of the phase, the PNG the rest.
    if (progress && i % step == 0 && i > 0)
      progress("draw", 0.9 * static_cast<double>(i) / static_cast<double>(n));
    const Polygon& p = pic.polygons[i];
    if (!visible(p, w)) continue;
    trace(cr, v, p);
    set_rgb(cr, pic.colors.cell[static_cast<std::size_t>(p.cell)]);
    if (edges) {
      cairo_fill_preserve(cr);
      cairo_set_source_rgba(cr, 0.1, 0.1, 0.1, 0.8);
      cairo_set_line_width(cr, edge_width);
      cairo_stroke(cr);
    } else {
      // A hairline of the fill colour closes the anti-aliasing seams between cells.
      cairo_fill_preserve(cr);
      cairo_set_line_width(cr, 0.5);
      cairo_stroke(cr);
    }
  }
}

void draw_overlay(cairo_t* cr, const View& v, const Window& w, const Picture& pic) {
  cairo_set_source_rgba(cr, 0.85, 0.1, 0.1, 0.9);
  cairo_set_line_width(cr, 1.0);
  for (const Polygon& p : pic.overlay) {
    if (!visible(p, w)) continue;
    trace(cr, v, p);
    cairo_stroke(cr);
  }
}

void draw_arrows(cairo_t* cr, const View& v, const Picture& pic) {
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 1.0);
  for (const Arrow& a : pic.arrows) {
    const double x0 = v.x(a.from[0]), y0 = v.y(a.from[1]);
    const double x1 = v.x(a.to[0]), y1 = v.y(a.to[1]);
    const double len = std::hypot(x1 - x0, y1 - y0);
    if (len < 0.5) continue;
    cairo_move_to(cr, x0, y0);
    cairo_line_to(cr, x1, y1);
    cairo_stroke(cr);
    const double head = std::min(5.0, 0.4 * len), ang = std::atan2(y1 - y0, x1 - x0);
    cairo_move_to(cr, x1, y1);
    cairo_line_to(cr, x1 - head * std::cos(ang - 0.4), y1 - head * std::sin(ang - 0.4));
    cairo_line_to(cr, x1 - head * std::cos(ang + 0.4), y1 - head * std::sin(ang + 0.4));
    cairo_close_path(cr);
    cairo_fill(cr);
  }
}

void text(cairo_t* cr, double x, double y, const std::string& s, double size = 12) {
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_font_size(cr, size);
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, s.c_str());
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

void draw_legend(cairo_t* cr, double left, double top, const CellColors& c) {
  double y = top;
  for (const LegendEntry& e : c.legend) {
    cairo_rectangle(cr, left, y, 16, 16);
    set_rgb(cr, e.color);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    cairo_set_line_width(cr, 0.8);
    cairo_stroke(cr);
    text(cr, left + 24, y + 13, e.label);
    y += 22;
  }
}

// The colour bar: value v at height y(v), the bottom colour at scale_min. A single value
// (constant data) fills the bar with the middle colour, its one tick half-way up.
struct BarGeometry {
  double left = 0, top = 0, width = 22, height = 0;
  double y(const ColorBar& b, double v) const {
    const double span = b.scale_max - b.scale_min;
    const double t = span > 0 ? (v - b.scale_min) / span : 0.5;
    return top + height * (1 - std::clamp(t, 0.0, 1.0));
  }
};

void fill_bar(cairo_t* cr, const BarGeometry& g, const ColorBar& b) {
  cairo_rectangle(cr, g.left, g.top, g.width, g.height);
  if (b.scale_max > b.scale_min) {
    cairo_pattern_t* gradient = cairo_pattern_create_linear(0, g.top + g.height, 0, g.top);
    for (int i = 0; i <= 16; ++i) {
      const Rgb col = colormap(i / 16.0);
      cairo_pattern_add_color_stop_rgb(gradient, i / 16.0, col[0], col[1], col[2]);
    }
    cairo_set_source(cr, gradient);
    cairo_fill(cr);
    cairo_pattern_destroy(gradient);
  } else {
    set_rgb(cr, colormap(0.5));
    cairo_fill(cr);
  }
  cairo_rectangle(cr, g.left, g.top, g.width, g.height);
  cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
  cairo_set_line_width(cr, 0.8);
  cairo_stroke(cr);
}

// A label at height y unless it would overlap one already placed (12-pixel text).
void place_label(cairo_t* cr, std::vector<double>& taken, double x, double y,
                 const std::string& s) {
  for (double t : taken)
    if (std::abs(t - y) < 13) return;
  taken.push_back(y);
  text(cr, x, y + 4, s);
}

// The threshold first, so that its label wins over a tick's: a black line across the bar.
void draw_ticks(cairo_t* cr, const BarGeometry& g, const ColorBar& b) {
  std::vector<double> taken;
  const double label_x = g.left + g.width + 8;
  if (b.threshold) {
    const double y = g.y(b, *b.threshold);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 2);
    cairo_move_to(cr, g.left - 8, y);
    cairo_line_to(cr, g.left + g.width + 5, y);
    cairo_stroke(cr);
    place_label(cr, taken, label_x, y, "threshold " + number(*b.threshold));
  }
  cairo_set_line_width(cr, 1);
  for (const Tick& t : b.ticks) {
    const double y = std::round(g.y(b, t.value)) + 0.5;
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    cairo_move_to(cr, g.left + g.width, y);
    cairo_line_to(cr, g.left + g.width + 5, y);
    cairo_stroke(cr);
    place_label(cr, taken, label_x, y, t.label);
  }
}

// Under the bar: whether the scale is fixed, the cells' own range, the colours off the map.
std::vector<std::string> notes(const ColorBar& b) {
  std::vector<std::string> lines;
  if (b.fixed_scale)
    lines.push_back("fixed scale " + number(b.scale_min) + " to " + number(b.scale_max));
  if (!b.has_values) {
    lines.push_back("cells: no finite value");
    return lines;
  }
  lines.push_back("cells min " + range_label(b.data_min, b.data_min, b.data_max));
  lines.push_back("cells max " + range_label(b.data_max, b.data_min, b.data_max));
  return lines;
}

void draw_bar(cairo_t* cr, double left, double top, double height, const ColorBar& b) {
  text(cr, left, top, b.title);
  const std::vector<std::string> lines = notes(b);
  const double below = 16.0 * static_cast<double>(lines.size() + b.special.size()) + 6;
  const BarGeometry g{left, top + 12, 22, std::max(height - 12 - below, 20.0)};
  fill_bar(cr, g, b);
  draw_ticks(cr, g, b);
  double y = g.top + g.height + 18;
  for (const std::string& line : lines) {
    text(cr, left, y, line);
    y += 16;
  }
  for (const LegendEntry& e : b.special) {
    cairo_rectangle(cr, left, y - 11, 12, 12);
    set_rgb(cr, e.color);
    cairo_fill(cr);
    text(cr, left + 18, y, e.label);
    y += 16;
  }
}

cairo_status_t write_to_stream(void* closure, const unsigned char* data, unsigned int length) {
  auto* out = static_cast<io::AtomicFile*>(closure);
  out->stream().write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(length));
  return out->stream() ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

}  // namespace

Window bounding_window(const Picture& picture) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  Window w{inf, inf, -inf, -inf};
  for (const auto* polys : {&picture.polygons, &picture.overlay})
    for (const Polygon& p : *polys)
      for (const auto& q : p.points) {
        w.x0 = std::min(w.x0, q[0]), w.x1 = std::max(w.x1, q[0]);
        w.y0 = std::min(w.y0, q[1]), w.y1 = std::max(w.y1, q[1]);
      }
  if (w.x0 > w.x1) return {0, 0, 1, 1};
  const double pad = 0.02 * std::max(w.x1 - w.x0, w.y1 - w.y0);
  return {w.x0 - pad, w.y0 - pad, w.x1 + pad, w.y1 + pad};
}

void write_png(const Picture& pic, const PictureOptions& options, const std::string& path) {
  cairo_surface_t* surface =
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, options.width, options.height);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);

  const bool panel = pic.colors.bar || !pic.colors.legend.empty();
  const double top = margin + (options.title.empty() ? 0 : title_height);
  const double plot_w = options.width - 2 * margin - (panel ? panel_width : 0);
  const double plot_h = options.height - top - margin;
  const Window w = options.window ? *options.window : bounding_window(pic);
  const View v = fit(w, margin, top, std::max(plot_w, 1.0), std::max(plot_h, 1.0));
  // The plot area seen in the plane: wider or taller than `w` when the aspects differ.
  const Window shown{(margin - v.ox) / v.scale, (v.oy - top - plot_h) / v.scale,
                     (margin + plot_w - v.ox) / v.scale, (v.oy - top) / v.scale};

  cairo_save(cr);
  cairo_rectangle(cr, margin, top, std::max(plot_w, 1.0), std::max(plot_h, 1.0));
  cairo_clip(cr);
  // Cells of a few pixels only: their edges would hide the colours.
  const bool edges = options.edges == Edges::on ||
                     (options.edges == Edges::automatic && mean_cell_pixels(v, shown, pic) >= 5);
  draw_cells(cr, v, shown, pic, edges, options.progress);
  draw_overlay(cr, v, shown, pic);
  draw_arrows(cr, v, pic);
  cairo_restore(cr);

  if (!options.title.empty()) text(cr, margin, margin + 13, options.title, 13);
  const double panel_left = options.width - panel_width;
  if (!pic.colors.legend.empty()) draw_legend(cr, panel_left, top + 4, pic.colors);
  if (pic.colors.bar) draw_bar(cr, panel_left, top + 10, std::min(plot_h, 320.0), *pic.colors.bar);

  if (options.progress) options.progress("draw", 0.9);
  cairo_surface_flush(surface);
  const cairo_status_t drawn = cairo_status(cr);
  cairo_destroy(cr);
  if (drawn != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(surface);
    throw IoError(path + ": cannot draw: " + cairo_status_to_string(drawn));
  }
  io::AtomicFile out(path);
  const cairo_status_t written = cairo_surface_write_to_png_stream(surface, write_to_stream, &out);
  cairo_surface_destroy(surface);
  if (written != CAIRO_STATUS_SUCCESS)
    throw IoError(path + ": cannot write PNG: " + cairo_status_to_string(written));
  out.commit();
  if (options.progress) options.progress("draw", 1.0);
}

}  // namespace hexadapt::render
