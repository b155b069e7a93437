#include "ui/scene/scene_items.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/common/angles.h"
#include "ui/scene/device_case.h"

namespace lmc::ui {
namespace {

const Rgba kDeviceColour{0.55f, 0.60f, 0.70f, 1.0f};
const Rgba kSelectedColour{1.00f, 0.62f, 0.20f, 1.0f};
const Rgba kHoveredColour{0.75f, 0.82f, 0.95f, 1.0f};
const Rgba kUsbColour{0.95f, 0.95f, 0.30f, 1.0f};
const Rgba kGhostColour{0.30f, 0.85f, 1.00f, 0.40f};
const Rgba kHandNeutral{0.80f, 0.78f, 0.74f, 1.0f};
const Rgba kGridMinor{0.30f, 0.32f, 0.36f, 1.0f};
const Rgba kGridMajor{0.42f, 0.45f, 0.50f, 1.0f};

// Each controller's pyramid gets its own hue so overlapping volumes stay distinguishable.
Rgba device_hue(int i, float alpha) {
  static constexpr float kHues[8][3] = {{0.35f, 0.60f, 1.00f}, {0.95f, 0.45f, 0.75f}, {0.40f, 0.90f, 0.70f},
                                        {0.95f, 0.75f, 0.35f}, {0.70f, 0.55f, 1.00f}, {0.50f, 0.85f, 0.95f},
                                        {0.90f, 0.60f, 0.50f}, {0.75f, 0.90f, 0.45f}};
  const auto& h = kHues[static_cast<size_t>(i % 8)];
  return {h[0], h[1], h[2], alpha};
}

void add_segment(SceneList& out, ItemRole role, const Eigen::Vector3d& a, const Eigen::Vector3d& b, Rgba c, int id = -1,
                 std::uint32_t flags = kFlagNone) {
  SceneItem it;
  it.kind = ItemKind::kSegment;
  it.role = role;
  it.a = a;
  it.b = b;
  it.colour = c;
  it.id = id;
  it.flags = flags;
  out.items.push_back(it);
}

void add_ring(SceneList& out, HandleKind kind, const LayoutDevice& dev, Rgba c, int id) {
  const auto pts = handle_ring_points(kind, dev, 64);
  for (size_t i = 0; i < pts.size(); ++i) add_segment(out, ItemRole::kHandle, pts[i], pts[(i + 1) % pts.size()], c, id);
}

void add_table(SceneList& out, const SceneInputs& in) {
  const double e = in.table_half_extent_mm;
  SceneItem fill;
  fill.kind = ItemKind::kCell;
  fill.role = ItemRole::kTable;
  fill.a = Eigen::Vector3d(-e, -0.6, -e);
  fill.b = Eigen::Vector3d(e, -0.6, e);
  fill.colour = {0.16f, 0.17f, 0.20f, 0.55f};
  fill.flags = kFlagTranslucent;
  out.items.push_back(fill);
  const double step = std::max(in.grid_step_mm, 1.0);
  const int n = static_cast<int>(std::floor(e / step));
  for (int i = -n; i <= n; ++i) {
    const double v = i * step;
    const bool major = (i % 2) == 0;
    if (i == 0) continue;  // the axes are drawn instead
    add_segment(out, ItemRole::kTable, {v, 0, -e}, {v, 0, e}, major ? kGridMajor : kGridMinor);
    add_segment(out, ItemRole::kTable, {-e, 0, v}, {e, 0, v}, major ? kGridMajor : kGridMinor);
  }
  // Axes: x red, y green, z blue (the usual convention), z towards the subject.
  add_segment(out, ItemRole::kAxis, {-e, 0, 0}, {e, 0, 0}, {0.90f, 0.35f, 0.35f, 1.0f});
  add_segment(out, ItemRole::kAxis, {0, 0, -e}, {0, 0, e}, {0.35f, 0.55f, 0.95f, 1.0f});
  add_segment(out, ItemRole::kAxis, {0, 0, 0}, {0, 100, 0}, {0.40f, 0.85f, 0.40f, 1.0f});
  const Rgba label{0.70f, 0.72f, 0.76f, 1.0f};
  // Rulers: x values along the back edge (away from the subject: the workbench's legends sit
  // along the bottom of the view), z values along the right edge. The two meet at the back-right
  // corner, whose value is written once, by the x ruler. Each ruler's title sits beside its own
  // numbers, in its axis's colour (they sat at the ends of the other ruler).
  for (int i = -n; i <= n; i += 2) {
    if (i == 0) continue;
    char buf[32];
    std::snprintf(buf, sizeof buf, "%+.0f", i * step);
    out.labels.push_back({Eigen::Vector3d(i * step, 0, -e - 18), buf, label, false});
    if (i != -n) out.labels.push_back({Eigen::Vector3d(e + 24, 0, i * step), buf, label, false});
  }
  out.labels.push_back({Eigen::Vector3d(0, 0, -e - 44), "x mm", {0.95f, 0.45f, 0.45f, 1.0f}, true});
  out.labels.push_back({Eigen::Vector3d(e + 60, 0, 0), "z mm (+ subject)", {0.45f, 0.65f, 1.0f, 1.0f}, true});
  out.labels.push_back({Eigen::Vector3d(0, 110, 0), "y", {0.45f, 0.90f, 0.45f, 1.0f}, true});
}

// The controller's case, its USB end and its LED edge.
void add_device_case(SceneList& out, const LayoutDevice& d, const Eigen::Isometry3d& t, int i, std::uint32_t flags,
                     const Rgba& body) {
  // The case of the device's own model (an LMC2 is longer and narrower than an LMC).
  const DeviceCaseBox case_box = device_case_box(d);
  SceneItem box;
  box.kind = ItemKind::kBox;
  box.role = ItemRole::kDevice;
  box.transform = t;
  box.a = case_box.centre_mm;
  box.b = case_box.half_mm;
  box.colour = body;
  box.id = i;
  box.flags = flags;
  out.items.push_back(box);
  // USB side marker: the cable leaves the controller at one short end; we mark the −x end
  // (device frame) - an assumption to be checked against the lab's own controllers.
  SceneItem usb = box;
  usb.role = ItemRole::kDeviceUsbMarker;
  usb.a = Eigen::Vector3d(-case_box.half_mm.x() - 4.0, case_box.centre_mm.y(), 0.0);
  usb.b = Eigen::Vector3d(4.0, std::min(3.5, case_box.half_mm.y()), std::min(6.0, case_box.half_mm.z()));
  usb.colour = kUsbColour;
  out.items.push_back(usb);
  // The green status LED side faces the user (+z): a thin strip on the top face's +z edge helps
  // read the orientation from above.
  SceneItem front = box;
  front.role = ItemRole::kDeviceUsbMarker;
  front.a = Eigen::Vector3d(0.0, case_box.top_y_mm() + 0.3, case_box.half_mm.z() - 3.0);
  front.b = Eigen::Vector3d(std::min(30.0, case_box.half_mm.x() - 5.0), 0.5, 2.5);
  front.colour = {0.30f, 0.90f, 0.40f, 1.0f};
  out.items.push_back(front);
}

// The field of view as a translucent pyramid out to the far range, its edges, and the near range
// as an outline (nothing closer than it is tracked: 10 cm on the LMC and LMC2).
void add_device_pyramid(SceneList& out, const LayoutDevice& d, const Eigen::Isometry3d& t, int i, bool selected,
                        std::uint32_t flags) {
  SceneItem pyr;
  pyr.kind = ItemKind::kPyramid;
  pyr.role = ItemRole::kPyramid;
  pyr.transform = t;
  // Each controller's own model (LayoutDevice::sensor).
  const SensorModel& sensor = d.sensor;
  pyr.size = sensor.range_mm;
  pyr.b = Eigen::Vector3d(sensor.fov_long_deg * 0.5, sensor.fov_short_deg * 0.5, 0);
  pyr.colour = device_hue(i, selected ? 0.12f : 0.035f);
  pyr.id = i;
  pyr.flags = flags | kFlagTranslucent;
  out.items.push_back(pyr);
  const auto c = pyramid_corners(t, pyr.size, pyr.b.x(), pyr.b.y());
  const Eigen::Vector3d apex = t.translation();
  const Rgba edge = device_hue(i, selected ? 0.85f : 0.3f);
  for (int k = 0; k < 4; ++k) {
    add_segment(out, ItemRole::kPyramid, apex, c[static_cast<size_t>(k)], edge, i, kFlagTranslucent);
    add_segment(out, ItemRole::kPyramid, c[static_cast<size_t>(k)], c[static_cast<size_t>((k + 1) % 4)], edge, i,
                kFlagTranslucent);
  }
  if (sensor.range_near_mm > 0) {
    const auto n = pyramid_corners(t, sensor.range_near_mm, pyr.b.x(), pyr.b.y());
    for (int k = 0; k < 4; ++k) {
      add_segment(out, ItemRole::kPyramid, n[static_cast<size_t>(k)], n[static_cast<size_t>((k + 1) % 4)], edge, i,
                  kFlagTranslucent);
    }
  }
}

void add_device(SceneList& out, const SceneInputs& in, int i) {
  const LayoutDevice& d = in.layout->devices[static_cast<size_t>(i)];
  const Eigen::Isometry3d t = device_transform(d);
  std::uint32_t flags = kFlagNone;
  Rgba body = kDeviceColour;
  if (i == in.selected) {
    flags |= kFlagSelected;
    body = kSelectedColour;
  } else if (i == in.hovered) {
    flags |= kFlagHovered;
    body = kHoveredColour;
  }
  add_device_case(out, d, t, i, flags, body);
  if (in.show_pyramids) add_device_pyramid(out, d, t, i, i == in.selected, flags);
  std::string text = d.slot;
  if (d.serial) text += " (" + *d.serial + ")";
  out.labels.push_back({t * Eigen::Vector3d(0, 22, 0), text,
                        i == in.selected ? kSelectedColour : Rgba{0.9f, 0.92f, 0.96f, 1.0f}, i == in.selected});

  if (i == in.selected && in.locks != nullptr && static_cast<size_t>(i) < in.locks->size()) {
    const DeviceLocks& lk = (*in.locks)[static_cast<size_t>(i)];
    const auto ring_colour = [&](HandleKind k, Rgba base) {
      if (in.active_handle == k || in.hovered_handle == k) return Rgba{1.0f, 1.0f, 1.0f, 1.0f};
      return base;
    };
    if (!lk.locked[4])
      add_ring(out, HandleKind::kYaw, d, ring_colour(HandleKind::kYaw, {0.35f, 0.90f, 0.45f, 1.0f}), i);
    if (!lk.locked[3])
      add_ring(out, HandleKind::kTilt, d, ring_colour(HandleKind::kTilt, {0.95f, 0.40f, 0.40f, 1.0f}), i);
  }
}

void add_hand(SceneList& out, const SceneInputs& in) {
  const HandFrame& h = *in.hand;
  const auto colour_of = [&](int digit) {
    if (digit < 0) return kHandNeutral;
    const int n = in.finger_seen_count[static_cast<size_t>(digit)];
    return n < 0 ? kHandNeutral : seen_count_colour(n);
  };
  for (const BoneSpec& b : hand_bones()) {
    SceneItem it;
    it.kind = ItemKind::kBone;
    it.role = b.digit < 0 ? ItemRole::kHand : ItemRole::kFinger;
    it.a = h.point(b.from);
    it.b = h.point(b.to);
    it.size = b.digit < 0 ? 3.0 : 4.0;
    it.colour = colour_of(b.digit);
    it.id = b.digit;
    out.items.push_back(it);
  }
  for (int p = 0; p < kNumHandPoints; ++p) {
    if (p == kPalmNormal || p == kPalmDirection) continue;
    SceneItem j;
    j.kind = ItemKind::kJoint;
    const int digit = p >= kFirstDigitPoint ? (p - kFirstDigitPoint) / kJointsPerDigit : -1;
    j.role = digit < 0 ? ItemRole::kHand : ItemRole::kFinger;
    j.a = h.point(p);
    j.size = digit < 0 ? 6.0 : 5.2;
    j.colour = colour_of(digit);
    j.id = digit;
    out.items.push_back(j);
  }
}

void add_heatmap(SceneList& out, const SceneInputs& in) {
  const HeatmapGrid& g = *in.heatmap;
  const double dx = (g.x_hi_mm - g.x_lo_mm) / std::max(g.nx, 1);
  const double dz = (g.z_hi_mm - g.z_lo_mm) / std::max(g.nz, 1);
  for (int iz = 0; iz < g.nz; ++iz) {
    for (int ix = 0; ix < g.nx; ++ix) {
      const float v = g.at(ix, iz);
      if (!std::isfinite(v)) continue;
      SceneItem c;
      c.kind = ItemKind::kCell;
      c.role = ItemRole::kHeatmap;
      c.a = Eigen::Vector3d(g.x_lo_mm + ix * dx, -0.3, g.z_lo_mm + iz * dz);
      c.b = Eigen::Vector3d(g.x_lo_mm + (ix + 1) * dx, -0.3, g.z_lo_mm + (iz + 1) * dz);
      c.colour = viridis(in.heatmap_range.normalise(v));
      c.colour.a = 0.88f;
      c.id = iz * g.nx + ix;
      out.items.push_back(c);
    }
  }
}

}  // namespace

std::array<Eigen::Vector3d, 4> pyramid_corners(const Eigen::Isometry3d& device_to_world, double range_mm,
                                               double half_long_deg, double half_short_deg) {
  // Corner directions (±tan α, 1, ±tan β) in the device frame, scaled so each edge is as long as
  // the range: the pyramid is drawn "up to the sensor range" along its edges.
  const double tx = std::tan(half_long_deg * kRadPerDeg), tz = std::tan(half_short_deg * kRadPerDeg);
  const double sx[4] = {-1, 1, 1, -1}, sz[4] = {-1, -1, 1, 1};
  std::array<Eigen::Vector3d, 4> c;
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector3d dir = Eigen::Vector3d(sx[k] * tx, 1.0, sz[k] * tz).normalized();
    c[static_cast<size_t>(k)] = device_to_world * (dir * range_mm);
  }
  return c;
}

const std::vector<BoneSpec>& hand_bones() {
  static const std::vector<BoneSpec> bones = [] {
    std::vector<BoneSpec> b;
    b.push_back({kElbow, kWrist, -1});
    for (int d = 0; d < kNumDigits; ++d) {
      b.push_back({kWrist, digit_point(d, 0), -1});
      for (int j = 0; j + 1 < kJointsPerDigit; ++j) b.push_back({digit_point(d, j), digit_point(d, j + 1), d});
    }
    // Across the knuckles so the palm reads as a surface.
    for (int d = 1; d + 1 < kNumDigits; ++d) b.push_back({digit_point(d, 1), digit_point(d + 1, 1), -1});
    b.push_back({digit_point(0, 1), digit_point(1, 1), -1});
    return b;
  }();
  return bones;
}

size_t SceneList::count(ItemRole role) const {
  return static_cast<size_t>(
      std::count_if(items.begin(), items.end(), [&](const SceneItem& i) { return i.role == role; }));
}

Eigen::Isometry3d device_transform(const LayoutDevice& d) {
  Eigen::Isometry3d t = d.pose.device_to_world();
  t.translation() += d.offset_mm;
  return t;
}

std::array<std::array<Eigen::Vector3d, 2>, 12> box_edges(const SceneItem& box) {
  std::array<Eigen::Vector3d, 8> c;
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d sign((k & 1) ? 1.0 : -1.0, (k & 2) ? 1.0 : -1.0, (k & 4) ? 1.0 : -1.0);
    c[static_cast<size_t>(k)] = box.transform * (box.a + sign.cwiseProduct(box.b));
  }
  // Corners differing in exactly one bit share an edge.
  std::array<std::array<Eigen::Vector3d, 2>, 12> out;
  size_t n = 0;
  for (int k = 0; k < 8; ++k) {
    for (const int bit : {1, 2, 4}) {
      if ((k & bit) == 0) out[n++] = {c[static_cast<size_t>(k)], c[static_cast<size_t>(k | bit)]};
    }
  }
  return out;
}

std::array<Eigen::Vector3d, 4> box_top_face(const SceneItem& box) {
  const Eigen::Vector3d& h = box.b;
  const auto corner = [&](double sx, double sz) {
    return box.transform * (box.a + Eigen::Vector3d(sx * h.x(), h.y(), sz * h.z()));
  };
  return {corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1)};
}

SceneList build_scene(const SceneInputs& in) {
  SceneList out;
  out.items.reserve(4096);
  if (in.heatmap != nullptr && in.heatmap->nx > 0) add_heatmap(out, in);
  add_table(out, in);
  if (in.search_box != nullptr) {
    const auto& b = *in.search_box;
    const Rgba box_colour{1.0f, 0.80f, 0.25f, 0.95f};
    const double y = 0.5;  // just above the table so the grid does not hide it
    const Eigen::Vector3d c[4] = {{b[0], y, b[2]}, {b[1], y, b[2]}, {b[1], y, b[3]}, {b[0], y, b[3]}};
    for (int k = 0; k < 4; ++k) add_segment(out, ItemRole::kSearchBox, c[k], c[(k + 1) % 4], box_colour);
    out.labels.push_back({Eigen::Vector3d(b[0] + 70, y, b[2] + 14), "search area", box_colour, false});
  }
  Eigen::AlignedBox3d bounds;
  bounds.extend(Eigen::Vector3d(-150, 0, -150));
  bounds.extend(Eigen::Vector3d(150, 50, 150));
  if (in.layout != nullptr) {
    for (int i = 0; i < in.layout->device_count(); ++i) {
      add_device(out, in, i);
      bounds.extend(device_transform(in.layout->devices[static_cast<size_t>(i)]).translation());
    }
  }
  if (in.ghost != nullptr) {
    for (int i = 0; i < in.ghost->device_count(); ++i) {
      const LayoutDevice& d = in.ghost->devices[static_cast<size_t>(i)];
      SceneItem g;
      g.kind = ItemKind::kBox;
      g.role = ItemRole::kGhost;
      g.transform = device_transform(d);
      const DeviceCaseBox ghost_case = device_case_box(d);
      g.a = ghost_case.centre_mm;
      g.b = ghost_case.half_mm;
      g.colour = kGhostColour;
      g.id = i;
      g.flags = kFlagGhost | kFlagTranslucent;
      out.items.push_back(g);
      out.labels.push_back({g.transform * Eigen::Vector3d(0, 22, 0), d.slot + "*", kGhostColour, false});
      const Eigen::Vector3d tip = g.transform * Eigen::Vector3d(0, 60, 0);
      add_segment(out, ItemRole::kGhost, g.transform.translation(), tip, {0.3f, 0.85f, 1.0f, 0.8f}, i, kFlagGhost);
    }
  }
  if (in.hand != nullptr && in.hand->hand_present) {
    add_hand(out, in);
    for (int p = 0; p < kNumHandPoints; ++p) {
      if (p != kPalmNormal && p != kPalmDirection) bounds.extend(in.hand->point(p));
    }
  }
  if (in.rays != nullptr) {
    for (size_t r = 0; r < in.rays->size(); ++r) {
      const FingerRay& ray = (*in.rays)[r];
      add_segment(out, ItemRole::kRay, ray.from, ray.to,
                  ray.clear ? Rgba{0.30f, 0.95f, 0.40f, 0.9f} : Rgba{1.0f, 0.30f, 0.25f, 0.9f}, static_cast<int>(r));
    }
  }
  out.bounds_lo = bounds.min();
  out.bounds_hi = bounds.max();
  return out;
}

}  // namespace lmc::ui
