#include "ui/app/capture/text_fit_check.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace lmc::ui {
namespace {

// A glyph as the font atlas holds it: its character and its full texture rectangle. A glyph
// clipped on the CPU keeps one corner of that rectangle and loses the other.
struct AtlasGlyph {
  ImWchar codepoint = 0;
  ImVec2 uv0, uv1;
  float x0 = 0, x1 = 0, advance = 0;  // at the font's own size
};

using UvKey = std::pair<float, float>;

struct GlyphIndex {
  std::map<UvKey, AtlasGlyph> by_top_left, by_bottom_right;
};

GlyphIndex index_atlas(const ImFontAtlas& atlas) {
  GlyphIndex index;
  for (const ImFont* font : atlas.Fonts) {
    for (const ImFontGlyph& g : font->Glyphs) {
      if (g.Visible == 0) continue;
      const AtlasGlyph glyph{
          static_cast<ImWchar>(g.Codepoint), ImVec2(g.U0, g.V0), ImVec2(g.U1, g.V1), g.X0, g.X1, g.AdvanceX};
      index.by_top_left.emplace(UvKey{g.U0, g.V0}, glyph);
      index.by_bottom_right.emplace(UvKey{g.U1, g.V1}, glyph);
    }
  }
  return index;
}

// One drawn glyph quad, as PrimRectUV writes it.
struct DrawnGlyph {
  ImWchar codepoint = 0;
  ImRect box;  // on screen, before the scissor
  ImU32 colour = 0;
  // Where the pen stood for it and where it moves on, on screen (the font's scale applied).
  float origin = 0, next = 0;
  // The CPU clipped it (its texture rectangle is not the whole glyph), on that side.
  bool cut_left = false, cut_right = false, cut_vertically = false;
};

// Consecutive glyphs of one line of text in one draw command.
struct TextRun {
  std::string text;
  ImRect box;
  ImRect clip;
  bool cut_left = false, cut_right = false, cut_top = false, cut_bottom = false;  // by the window
  bool box_cut_left = false, box_cut_right = false;                               // by the widget's box
  float next = 0;  // where the pen moves on after the last glyph
  ImU32 colour = 0;
};

void append_utf8(std::string& out, ImWchar c) {
  char buf[5] = {};
  ImTextCharToUtf8(buf, c);
  out += buf;
}

// Reads the glyph quad at index i of a command, if that is what is there.
bool read_glyph(const ImDrawList& list, const ImDrawCmd& cmd, unsigned i, const GlyphIndex& index, DrawnGlyph& out) {
  const ImDrawIdx* idx = list.IdxBuffer.Data + cmd.IdxOffset + i;
  const unsigned base = cmd.VtxOffset;
  const unsigned v = idx[0];
  if (idx[1] != v + 1 || idx[2] != v + 2 || idx[3] != v || idx[4] != v + 2 || idx[5] != v + 3) return false;
  const ImDrawVert& a = list.VtxBuffer.Data[base + v];
  const ImDrawVert& c = list.VtxBuffer.Data[base + v + 2];
  const ImVec2 uv_min(std::min(a.uv.x, c.uv.x), std::min(a.uv.y, c.uv.y));
  const ImVec2 uv_max(std::max(a.uv.x, c.uv.x), std::max(a.uv.y, c.uv.y));
  const AtlasGlyph* glyph = nullptr;
  if (const auto it = index.by_top_left.find({uv_min.x, uv_min.y}); it != index.by_top_left.end()) {
    glyph = &it->second;
  } else if (const auto it2 = index.by_bottom_right.find({uv_max.x, uv_max.y}); it2 != index.by_bottom_right.end()) {
    glyph = &it2->second;
  }
  if (glyph == nullptr) return false;
  out.codepoint = glyph->codepoint;
  out.colour = a.col;
  out.box = ImRect(ImVec2(std::min(a.pos.x, c.pos.x), std::min(a.pos.y, c.pos.y)),
                   ImVec2(std::max(a.pos.x, c.pos.x), std::max(a.pos.y, c.pos.y)));
  out.cut_left = uv_min.x != glyph->uv0.x;
  out.cut_right = uv_max.x != glyph->uv1.x;
  out.cut_vertically = uv_min.y != glyph->uv0.y || uv_max.y != glyph->uv1.y;
  // The scale from the glyph's texture width to its drawn width (a clipped side keeps the other
  // edge exact, and ImGui draws a glyph at one scale both ways).
  const float tex_w = glyph->uv1.x - glyph->uv0.x;
  const float scale = tex_w > 0 && glyph->x1 > glyph->x0
                          ? (out.box.GetWidth() / ((uv_max.x - uv_min.x) / tex_w)) / (glyph->x1 - glyph->x0)
                          : 1.0f;
  const float left_edge = out.cut_left ? out.box.Max.x - (glyph->x1 - glyph->x0) * scale : out.box.Min.x;
  out.origin = left_edge - glyph->x0 * scale;
  out.next = out.origin + glyph->advance * scale;
  return true;
}

// Does this glyph continue the run: in its colour (a label's shadow, or the next label, is a
// run of its own), on its line, where the pen stood or up to two spaces on?
bool continues(const TextRun& run, const DrawnGlyph& g) {
  if (g.colour != run.colour) return false;
  const float h = std::max(run.box.GetHeight(), g.box.GetHeight());
  const bool same_line = g.box.Min.y < run.box.Max.y - 0.25f * h && g.box.Max.y > run.box.Min.y + 0.25f * h;
  return same_line && g.origin >= run.next - 1.0f && g.origin - run.next < 1.2f * h;
}

void add_glyph(TextRun& run, const DrawnGlyph& g, const ImRect& clip) {
  constexpr float kSlack = 0.5f;
  if (!run.text.empty() && g.origin - run.next > 2.0f) run.text += ' ';
  append_utf8(run.text, g.codepoint);
  run.next = g.next;
  run.colour = g.colour;
  if (run.text.size() == 1 || run.box.GetWidth() <= 0) {
    run.box = g.box;
  } else {
    run.box.Add(g.box);
  }
  run.clip = clip;
  run.cut_left = run.cut_left || g.box.Min.x < clip.Min.x - kSlack;
  run.cut_right = run.cut_right || g.box.Max.x > clip.Max.x + kSlack;
  run.cut_top = run.cut_top || g.box.Min.y < clip.Min.y - kSlack;
  run.cut_bottom = run.cut_bottom || g.box.Max.y > clip.Max.y + kSlack;
  if (g.cut_left || g.cut_right || g.cut_vertically) {
    // The CPU clip rectangle is the widget's box intersected with the window's: a cut exactly on
    // the window's edge is the window's, anywhere else the widget's own.
    const bool at_left = std::fabs(g.box.Min.x - clip.Min.x) < kSlack,
               at_right = std::fabs(g.box.Max.x - clip.Max.x) < kSlack;
    const bool at_top = std::fabs(g.box.Min.y - clip.Min.y) < kSlack,
               at_bottom = std::fabs(g.box.Max.y - clip.Max.y) < kSlack;
    run.cut_left = run.cut_left || (g.cut_left && at_left);
    run.cut_right = run.cut_right || (g.cut_right && at_right);
    run.cut_top = run.cut_top || (g.cut_vertically && at_top);
    run.cut_bottom = run.cut_bottom || (g.cut_vertically && at_bottom);
    run.box_cut_left = run.box_cut_left || (g.cut_left && !at_left);
    run.box_cut_right = run.box_cut_right || (g.cut_right && !at_right);
  }
}

std::vector<TextRun> text_runs(const ImDrawList& list, ImTextureID font_texture, const GlyphIndex& index) {
  std::vector<TextRun> runs;
  for (const ImDrawCmd& cmd : list.CmdBuffer) {
    if (cmd.UserCallback != nullptr || cmd.TextureId != font_texture) continue;
    const ImRect clip(cmd.ClipRect.x, cmd.ClipRect.y, cmd.ClipRect.z, cmd.ClipRect.w);
    bool open = false;
    for (unsigned i = 0; i + 6 <= cmd.ElemCount;) {
      DrawnGlyph g;
      if (!read_glyph(list, cmd, i, index, g)) {
        open = false;
        i += 3;
        continue;
      }
      i += 6;
      if (!open || !continues(runs.back(), g)) {
        runs.emplace_back();
        open = true;
      }
      add_glyph(runs.back(), g, clip);
    }
  }
  return runs;
}

ImGuiWindow* window_of(const ImDrawList* list) {
  for (ImGuiWindow* w : GImGui->Windows) {
    if (w->DrawList == list) return w;
  }
  return nullptr;
}

std::string cut_sides(const TextRun& run, const ImGuiWindow* w) {
  // A window that scrolls that way shows the rest on scrolling: a half-shown row of a long list is
  // not a cut.
  const bool scrolls_x = w != nullptr && w->ScrollbarX;
  const bool scrolls_y = w != nullptr && w->ScrollbarY;
  std::string sides;
  const auto add = [&sides](const char* s) { sides += sides.empty() ? s : std::string(" and ") + s; };
  if (run.cut_left && !scrolls_x) add("left");
  if (run.cut_right && !scrolls_x) add("right");
  if (run.cut_top && !scrolls_y) add("top");
  if (run.cut_bottom && !scrolls_y) add("bottom");
  return sides;
}

void find_glyph_cuts(const ImDrawData& data, const GlyphIndex& index, std::vector<CutText>& out) {
  const ImTextureID font_texture = ImGui::GetIO().Fonts->TexID;
  for (int l = 0; l < data.CmdListsCount; ++l) {
    const ImDrawList* list = data.CmdLists[l];
    const std::string name = list->_OwnerName != nullptr ? list->_OwnerName : "?";
    const ImGuiWindow* window = window_of(list);
    const std::vector<TextRun> runs = text_runs(*list, font_texture, index);
    for (const TextRun& run : runs) {
      const int x = static_cast<int>(run.box.Min.x), y = static_cast<int>(run.box.Min.y);
      if (const std::string sides = cut_sides(run, window); !sides.empty()) {
        out.push_back({name, run.text, "cut at the " + sides + " by its window", x, y});
      }
      // Cut on the left only is a text field scrolled to show its end (where typing goes on).
      // A path longer than its text field is the field's ordinary state: it scrolls, and where the
      // files go must not fail a picture taken in a deep build folder.
      const bool path_in_field = run.text.find('/') != std::string::npos || run.text.find('\\') != std::string::npos;
      if (run.box_cut_right && !path_in_field) out.push_back({name, run.text, "wider than its widget's box", x, y});
    }
    // Two lines of text drawn over each other (shown parts only; a few pixels of touching
    // letters are not an overlap, and the same words a pixel or two apart are a label's shadow).
    for (size_t i = 0; i < runs.size(); ++i) {
      ImRect a = runs[i].box;
      a.ClipWithFull(runs[i].clip);
      for (size_t j = i + 1; j < runs.size(); ++j) {
        ImRect b = runs[j].box;
        b.ClipWithFull(runs[j].clip);
        const float w = std::min(a.Max.x, b.Max.x) - std::max(a.Min.x, b.Min.x);
        const float h = std::min(a.Max.y, b.Max.y) - std::max(a.Min.y, b.Min.y);
        if (w <= 2.0f || h <= 3.0f) continue;
        const bool shadow = runs[i].text == runs[j].text && std::fabs(a.Min.x - b.Min.x) <= 2.5f &&
                            std::fabs(a.Min.y - b.Min.y) <= 2.5f;
        if (!shadow) {
          out.push_back({name, runs[i].text, "drawn over '" + runs[j].text + "'", static_cast<int>(a.Min.x),
                         static_cast<int>(a.Min.y)});
        }
      }
    }
  }
}

// ImGui shortens a table header or a tab label that does not fit with an ellipsis.
void find_ellipses(std::vector<CutText>& out) {
  ImGuiContext& g = *GImGui;
  for (int n = 0; n < g.Tables.GetMapSize(); ++n) {
    const ImGuiTable* table = g.Tables.TryGetMapData(n);
    if (table == nullptr || table->LastFrameActive != g.FrameCount || table->OuterWindow == nullptr) continue;
    for (int c = 0; c < table->ColumnsCount; ++c) {
      const ImGuiTableColumn& column = table->Columns[c];
      if (!column.IsEnabled || !column.IsVisibleX) continue;
      if (column.ContentMaxXHeadersIdeal > column.ContentMaxXHeadersUsed + 0.5f) {
        out.push_back({table->OuterWindow->Name, ImGui::TableGetColumnName(table, c),
                       "table header ends in an ellipsis", static_cast<int>(column.ClipRect.Min.x),
                       static_cast<int>(table->OuterRect.Min.y)});
      }
    }
  }
  for (int n = 0; n < g.TabBars.GetMapSize(); ++n) {
    const ImGuiTabBar* bar = g.TabBars.TryGetMapData(n);
    if (bar == nullptr || bar->PrevFrameVisible < g.FrameCount - 1) continue;
    for (const ImGuiTabItem& tab : bar->Tabs) {
      if (tab.LastFrameVisible < g.FrameCount - 1 || tab.NameOffset < 0) continue;
      if (tab.Width + 0.5f < tab.ContentWidth) {
        out.push_back({"tab bar", bar->GetTabName(&tab), "tab label ends in an ellipsis",
                       static_cast<int>(bar->BarRect.Min.x + tab.Offset), static_cast<int>(bar->BarRect.Min.y)});
      }
    }
  }
}

// A window whose content runs past its right edge with no horizontal scrollbar hides that part,
// labels and all (ImGui does not draw an item wholly outside the window).
void find_overflowing_windows(std::vector<CutText>& out) {
  ImGuiContext& g = *GImGui;
  for (const ImGuiWindow* w : g.Windows) {
    if (!w->WasActive || w->Hidden || w->ScrollbarX || (w->Flags & ImGuiWindowFlags_Tooltip) != 0) continue;
    // Past the window's own right edge: a table may reach into the padding and under a scrollbar,
    // which hides nothing written.
    const float start = w->Pos.x + w->WindowPadding.x - w->Scroll.x;
    const float room = w->Pos.x + w->Size.x - start;
    if (w->ContentSize.x > room + 1.0f) {
      out.push_back({w->Name, "",
                     "content " + std::to_string(static_cast<int>(std::lround(w->ContentSize.x))) + " px wide in " +
                         std::to_string(static_cast<int>(std::lround(room))) + " px, no horizontal scrollbar",
                     static_cast<int>(w->Pos.x), static_cast<int>(w->Pos.y)});
    }
  }
}

}  // namespace

std::vector<CutText> find_cut_text() {
  std::vector<CutText> out;
  const ImDrawData* data = ImGui::GetDrawData();
  if (data == nullptr || !data->Valid) return out;
  static const GlyphIndex index = index_atlas(*ImGui::GetIO().Fonts);
  find_glyph_cuts(*data, index, out);
  find_ellipses(out);
  find_overflowing_windows(out);
  return out;
}

std::string describe(const CutText& cut) {
  std::string s = "window '" + cut.window + "' at (" + std::to_string(cut.x) + ", " + std::to_string(cut.y) + ")";
  if (!cut.text.empty()) s += ": '" + cut.text + "'";
  return s + ": " + cut.how;
}

}  // namespace lmc::ui
