#include <gtest/gtest.h>

#include <cmath>

#include "ui/scene/drag_controller.h"
#include "ui/scene/orbit_camera.h"
#include "ui/scene/ray.h"

namespace lmc::ui {
namespace {

constexpr double kW = 800, kH = 600;

TEST(OrbitCamera, ProjectAndUnprojectAgree) {
  OrbitCamera cam;
  const Eigen::Vector3d p(35, 20, -50);
  const auto px = cam.project(p, kW, kH);
  ASSERT_TRUE(px);
  const Ray r = cam.ray_through_pixel(px->x(), px->y(), kW, kH);
  const double t = (p - r.origin).dot(r.direction);
  EXPECT_NEAR((r.at(t) - p).norm(), 0.0, 1e-6);
}

TEST(OrbitCamera, ZoomKeepsThePointUnderTheCursorFixed) {
  OrbitCamera cam;
  const double px = 610, py = 150;
  const Ray before = cam.ray_through_pixel(px, py, kW, kH);
  const auto t = intersect_plane(before, cam.target(), cam.forward());
  ASSERT_TRUE(t);
  const Eigen::Vector3d p = before.at(*t);
  cam.zoom_towards(px, py, kW, kH, 3.0);
  const auto after = cam.project(p, kW, kH);
  ASSERT_TRUE(after);
  EXPECT_NEAR(after->x(), px, 1e-6);
  EXPECT_NEAR(after->y(), py, 1e-6);
  EXPECT_LT(cam.distance_mm(), 900.0);
}

TEST(OrbitCamera, PanMovesTheTargetWithTheCursor) {
  OrbitCamera cam;
  const Eigen::Vector3d grabbed = cam.target();  // a point on the plane the pan is measured on
  const auto before = cam.project(grabbed, kW, kH);
  cam.pan(40, -25, kH);
  const auto after = cam.project(grabbed, kW, kH);
  EXPECT_NEAR(after->x() - before->x(), 40.0, 1e-6);
  EXPECT_NEAR(after->y() - before->y(), -25.0, 1e-6);
}

TEST(OrbitCamera, FrameBoundsPutsEveryCornerOnScreen) {
  OrbitCamera cam;
  cam.set_named_view(NamedView::kTop);
  const Eigen::Vector3d lo(-400, 0, -400), hi(400, 200, 400);
  cam.frame_bounds(lo, hi, kW / kH);
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d c((i & 1) ? hi.x() : lo.x(), (i & 2) ? hi.y() : lo.y(), (i & 4) ? hi.z() : lo.z());
    const auto px = cam.project(c, kW, kH);
    ASSERT_TRUE(px);
    EXPECT_GE(px->x(), 0.0);
    EXPECT_LE(px->x(), kW);
    EXPECT_GE(px->y(), 0.0);
    EXPECT_LE(px->y(), kH);
  }
}

TEST(Ray, OrientedBoxHitAndMiss) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(100, 0, 0);
  Ray r;
  r.origin = Eigen::Vector3d(100, 100, 0);
  r.direction = -Eigen::Vector3d::UnitY();
  const auto hit = intersect_oriented_box(r, t, Eigen::Vector3d(0, -6.5, 0), Eigen::Vector3d(40, 6.5, 15));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(*hit, 100.0, 1e-9);
  r.origin.x() = 150;
  EXPECT_FALSE(intersect_oriented_box(r, t, Eigen::Vector3d(0, -6.5, 0), Eigen::Vector3d(40, 6.5, 15)));
}

TEST(Ray, CapsuleHitsWithinRadiusOnly) {
  Ray r;
  r.origin = Eigen::Vector3d(0, 100, 0);
  r.direction = -Eigen::Vector3d::UnitY();
  EXPECT_TRUE(intersect_capsule(r, Eigen::Vector3d(-10, 0, 4), Eigen::Vector3d(10, 0, 4), 5));
  EXPECT_FALSE(intersect_capsule(r, Eigen::Vector3d(-10, 0, 6), Eigen::Vector3d(10, 0, 6), 5));
}

LayoutDevice device_at(double x, double z) {
  LayoutDevice d;
  d.slot = "LMC1";
  d.pose.x_mm = x;
  d.pose.z_mm = z;
  return d;
}

Ray down_at(double x, double z) {
  Ray r;
  r.origin = Eigen::Vector3d(x, 500, z);
  r.direction = Eigen::Vector3d(0.1, -1, 0.05).normalized();
  return r;
}

TEST(DragController, MoveFollowsTheTotalDisplacementOnTheTablePlane) {
  const LayoutDevice dev = device_at(10, 20);
  DragController drag;
  ASSERT_TRUE(drag.begin(HandleKind::kMove, dev, DeviceLocks{}, down_at(10, 20)));
  const auto pose = drag.update(down_at(60, -30));
  ASSERT_TRUE(pose);
  EXPECT_NEAR(pose->x_mm, 60.0, 1e-9);
  EXPECT_NEAR(pose->z_mm, -30.0, 1e-9);
  EXPECT_EQ(pose->y_mm, 0.0);
  // Going back to the start ray gives the start pose exactly (no drift).
  const auto back = drag.update(down_at(10, 20));
  EXPECT_NEAR(back->x_mm, 10.0, 1e-9);
  EXPECT_NEAR(back->z_mm, 20.0, 1e-9);
}

TEST(DragController, LockedParametersStayPutAndFullyLockedHandlesRefuse) {
  const LayoutDevice dev = device_at(0, 0);
  DeviceLocks locks;
  locks.locked[2] = true;  // z
  DragController drag;
  ASSERT_TRUE(drag.begin(HandleKind::kMove, dev, locks, down_at(0, 0)));
  const auto pose = drag.update(down_at(30, 40));
  EXPECT_NEAR(pose->x_mm, 30.0, 1e-9);
  EXPECT_EQ(pose->z_mm, 0.0);
  locks.locked[4] = true;  // ry
  EXPECT_FALSE(drag.begin(HandleKind::kYaw, dev, locks, down_at(70, 0)));
}

TEST(DragController, YawRingTurnsAboutTheVerticalAxis) {
  const LayoutDevice dev = device_at(0, 0);
  DragController drag;
  Ray start;
  start.origin = Eigen::Vector3d(70, 300, 0);
  start.direction = -Eigen::Vector3d::UnitY();
  ASSERT_TRUE(drag.begin(HandleKind::kYaw, dev, DeviceLocks{}, start));
  // A quarter turn from +x to −z is +90° about +y (Ry(90°)·x̂ = −ẑ).
  Ray end = start;
  end.origin = Eigen::Vector3d(0, 300, -70);
  const auto pose = drag.update(end);
  ASSERT_TRUE(pose);
  EXPECT_NEAR(pose->ry_deg, 90.0, 1e-9);
  EXPECT_NEAR(pose->rx_deg, 0.0, 1e-12);
}

TEST(DragController, TiltRingTurnsAboutTheLongAxis) {
  const LayoutDevice dev = device_at(0, 0);
  DragController drag;
  Ray start;  // looking along −x at the ring in the y–z plane
  start.origin = Eigen::Vector3d(400, 48, 0);
  start.direction = -Eigen::Vector3d::UnitX();
  ASSERT_TRUE(drag.begin(HandleKind::kTilt, dev, DeviceLocks{}, start));
  Ray end = start;
  end.origin = Eigen::Vector3d(400, 0, 48);  // ŷ → ẑ is +90° about x
  const auto pose = drag.update(end);
  ASSERT_TRUE(pose);
  EXPECT_NEAR(pose->rx_deg, 90.0, 1e-9);
  // An edge-on ray is skipped, not divided by.
  Ray edge;
  edge.origin = Eigen::Vector3d(0, 400, 0);
  edge.direction = -Eigen::Vector3d::UnitY();
  EXPECT_FALSE(drag.update(edge));
}

TEST(DragController, HoverFindsTheBoxFromAbove) {
  OrbitCamera cam;
  cam.set(Eigen::Vector3d::Zero(), 0, 60, 600);
  const LayoutDevice dev = device_at(0, 0);
  const auto centre = cam.project(Eigen::Vector3d::Zero(), kW, kH);
  const HandleHit hit = hover_handle(dev, DeviceLocks{}, cam, centre->x(), centre->y(), kW, kH);
  EXPECT_EQ(hit.kind, HandleKind::kMove);
  const auto ring = cam.project(Eigen::Vector3d(kYawRingRadiusMm, 0, 0), kW, kH);
  EXPECT_EQ(hover_handle(dev, DeviceLocks{}, cam, ring->x(), ring->y(), kW, kH).kind, HandleKind::kYaw);
  EXPECT_EQ(hover_handle(dev, DeviceLocks{}, cam, 5, 5, kW, kH).kind, HandleKind::kNone);
}

}  // namespace
}  // namespace lmc::ui
