#pragma once
// How large the subject screen's text is for the window it is drawn in. Its fonts are made for a
// picture of at least 1280 × 800 (the subject reads the cue from a metre or two away); a smaller
// window — the 1024 × 640 window of a one-monitor bench, or one the operator shrank — scales
// them down with the window, and a cue too long for the room left below the circle shrinks
// further until its last line is inside the window.
#include <functional>

namespace lmc::ui {

// The picture size the subject screen's fonts are made for.
inline constexpr float kSubjectDesignWidthPx = 1280.0F;
inline constexpr float kSubjectDesignHeightPx = 800.0F;
// Below this the text is no longer readable from the subject's chair: it is clipped instead.
inline constexpr float kSubjectMinTextScale = 0.35F;

// 1 for a window at least the design size in both directions; otherwise the smaller of the two
// ratios (never above 1: the fonts are rasterised at their design size, larger would blur).
float subject_text_scale(float width_px, float height_px);

// The largest scale ≤ `scale` (in steps of 10 %, down to kSubjectMinTextScale) at which
// `height_at(scale)` — the height the text needs, wrapped, at that scale — is at most
// `available_px`.
float fit_subject_text_scale(float scale, float available_px, const std::function<float(float)>& height_at);

}  // namespace lmc::ui
