#pragma once
// A core figure (core/figures/figure.h) drawn on screen: the same description the SVG export and
// its CSV are written from, so what a researcher sees in the Review tab is what the exported figure
// shows. Lines break at missing values, points are dots, reference lines (a
// Bland–Altman bias and limits) are dashed with their label at the right, the legend sits above the
// plot, and hovering shows the nearest sample's values. Dark colours are lightened for the dark
// background; the export keeps its own.
#include "core/figures/figure.h"

namespace lmc::ui {

void draw_figure_view(const char* id, const Figure& figure, float height_px);

// The figure (or every panel of the grid, stacked) filling the rest of the window: what an
// off-screen PNG of it draws (ui/widgets/png_saver.h).
void draw_figure_filling(const char* id, const Figure& figure);
void draw_figure_grid_filling(const FigureGrid& grid);

}  // namespace lmc::ui
