// The capture's text check (ui/app/capture/text_fit_check.h) on headless frames: each kind of cut
// it names is found, and text that is shown whole — a label's shadow included — is not.
#include "ui/app/capture/text_fit_check.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <string>
#include <vector>

#include "tests/ui/headless_imgui.h"
#include "ui/widgets/series_plot.h"

namespace lmc::ui {
namespace {

using testing::HeadlessImGui;

std::string all(const std::vector<CutText>& cuts) {
  std::string s;
  for (const auto& c : cuts) s += describe(c) + "\n";
  return s;
}

TEST(TextFitCheck, TextShownWholeIsNotReported) {
  HeadlessImGui ui;
  ui.frames(3, [] {
    ImGui::TextUnformatted("Everything here fits");
    ImGui::Button("Start");
    // A label with its shadow a pixel away, as the 3D views draw them.
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddText(ImVec2(101, 301), IM_COL32(0, 0, 0, 200), "LMC1");
    dl->AddText(ImVec2(100, 300), IM_COL32(255, 80, 80, 255), "LMC1");
  });
  EXPECT_TRUE(find_cut_text().empty()) << all(find_cut_text());
}

TEST(TextFitCheck, FindsALabelWiderThanItsButton) {
  HeadlessImGui ui;
  // 125 px: the box's edge falls inside a letter (one wholly outside is not drawn at all).
  ui.frames(3, [] { ImGui::Button("Calibrate from a recorded trial", ImVec2(125, 0)); });
  const auto cuts = find_cut_text();
  ASSERT_EQ(cuts.size(), 1U) << all(cuts);
  EXPECT_EQ(cuts[0].how, "wider than its widget's box");
  EXPECT_EQ(cuts[0].text.rfind("Calibrate", 0), 0U) << cuts[0].text;
}

TEST(TextFitCheck, FindsTextCutByTheEdgeOfAWindowThatCannotScrollThatWay) {
  HeadlessImGui ui;
  ui.frames(3, [] {
    ImGui::BeginChild("narrow", ImVec2(150, 60), true);
    ImGui::TextUnformatted("fusion latency (frame arrival to fused hand)");
    ImGui::EndChild();
  });
  const std::string found = all(find_cut_text());
  EXPECT_NE(found.find("'fusion latency"), std::string::npos) << found;
  EXPECT_NE(found.find("cut at the right by its window"), std::string::npos) << found;
  EXPECT_NE(found.find("no horizontal scrollbar"), std::string::npos) << found;  // the window's content
}

TEST(TextFitCheck, FindsATableHeaderImGuiShortenedWithAnEllipsis) {
  HeadlessImGui ui;
  ui.frames(3, [] {
    if (ImGui::BeginTable("t", 2, ImGuiTableFlags_SizingFixedFit)) {
      ImGui::TableSetupColumn("subject", ImGuiTableColumnFlags_WidthFixed, 80);
      ImGui::TableSetupColumn("lag (ms)", ImGuiTableColumnFlags_WidthFixed, 30);
      ImGui::TableHeadersRow();
      ImGui::EndTable();
    }
  });
  const auto cuts = find_cut_text();
  ASSERT_FALSE(cuts.empty());
  EXPECT_EQ(cuts[0].text, "lag (ms)") << all(cuts);
  EXPECT_EQ(cuts[0].how, "table header ends in an ellipsis");
}

TEST(TextFitCheck, FindsTextDrawnOverOtherText) {
  HeadlessImGui ui;
  ui.frames(3, [] {
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddText(ImVec2(100, 300), IM_COL32(255, 255, 255, 255), "+300");
    dl->AddText(ImVec2(110, 302), IM_COL32(200, 200, 200, 255), "100 %");
  });
  const auto cuts = find_cut_text();
  ASSERT_EQ(cuts.size(), 1U) << all(cuts);
  EXPECT_EQ(cuts[0].how, "drawn over '100 %'");
}

// The optimiser's convergence plot ran to 80 iterations and showed "8": the last tick's number
// now ends at the plot's edge.
TEST(TextFitCheck, APlotsLastTickNumberIsShownWhole) {
  HeadlessImGui ui;
  std::vector<double> x, y;
  for (int i = 0; i <= 80; ++i) {
    x.push_back(i);
    y.push_back(1.0 / (1.0 + i));
  }
  SeriesPlot plot;
  plot.x_range()->set_extent(0, 80);
  SeriesPlotOptions options;
  options.x_label = "iteration";
  options.log_y = true;
  ui.frames(3, [&] { plot.draw("convergence", {PlotSeries{"best so far", x, y}}, options); });
  EXPECT_TRUE(find_cut_text().empty()) << all(find_cut_text());
}

}  // namespace
}  // namespace lmc::ui
