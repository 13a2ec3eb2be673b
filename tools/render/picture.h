// Drawing a flat picture to PNG with cairo: filled cell polygons, their edges, an overlaid
// second grid, target arrows, and a legend (categories) or a colour bar (a field). Kept out
// of libhexadapt so that the library does not depend on cairo.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "coloring.h"
#include "hexadapt/core/log.h"
#include "slice.h"

namespace hexadapt::render {

struct Window {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  ///< the part of the plane shown
};

enum class Edges { automatic, on, off };  ///< automatic: when cells are >= 5 pixels wide

struct PictureOptions {
  int width = 800, height = 600;  ///< pixels of the PNG
  std::optional<Window> window;   ///< nullopt: the bounding box of the polygons
  Edges edges = Edges::automatic;  ///< draw the cells' edges
  std::string title;              ///< one line above the picture (empty: none)
  Progress progress;              ///< phase "draw", over the cells then the PNG; may be null
};

struct Picture {
  std::vector<Polygon> polygons;
  CellColors colors;               ///< indexed by Polygon::cell
  std::vector<Polygon> overlay;    ///< edges only, drawn in red over the cells
  std::vector<Arrow> arrows;       ///< drawn in black over everything
};

/// The bounding box of the polygons (and the overlay), with a little margin.
Window bounding_window(const Picture& picture);

/// Draws the picture and writes it to `path` atomically. Throws IoError when cairo cannot
/// draw or write.
void write_png(const Picture& picture, const PictureOptions& options, const std::string& path);

}  // namespace hexadapt::render
