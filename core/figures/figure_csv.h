#pragma once
// The exact numbers behind an exported figure, so a reader can re-plot or check it. Long format,
// one row per sample, because series need not share x (a Bland–Altman scatter and a time plot
// alike):
//   series,x,y            (a Figure)
//   panel,series,x,y      (a FigureGrid; panel counts from 1, top to bottom)
//   panel,row,column_group,column,value   (a Heatmap, one row per cell, row-major per panel;
//                                          column_group is empty when the heatmap has none)
// Numbers are the shortest text that reads back as exactly the plotted double (C locale); a
// missing value (NaN, ±inf, or past the end of the shorter of x and y) is an empty cell, never 0.
// Text cells are quoted as RFC 4180 says when they hold a comma, quote or line break. Lines end
// in "\n". Reference lines and notes are not data: the JSON sidecar carries them.
#include <string>

#include "core/figures/figure.h"
#include "core/figures/heatmap.h"

namespace lmc {

std::string to_csv(const Figure& figure);
std::string to_csv(const FigureGrid& grid);
std::string to_csv(const Heatmap& heatmap);

// One CSV field: quoted (quotes doubled) when it holds ',', '"', '\n' or '\r'.
std::string csv_field(const std::string& text);

}  // namespace lmc
